// Copyright 2026 The draco-uv Authors.
//
// Licensed under the Apache License, Version 2.0 (the "License");
// you may not use this file except in compliance with the License.
// You may obtain a copy of the License at
//
//      http://www.apache.org/licenses/LICENSE-2.0
//
// Unless required by applicable law or agreed to in writing, software
// distributed under the License is distributed on an "AS IS" BASIS,
// WITHOUT WARRANTIES OR CONDITIONS OF ANY KIND, either express or implied.
// See the License for the specific language governing permissions and
// limitations under the License.
//
#include "draco_ext/linalg/sparse_cholesky.h"

#include <algorithm>
#include <cmath>
#include <condition_variable>
#include <cstdint>
#include <deque>
#include <functional>
#include <mutex>
#include <utility>

#include <Eigen/Core>

#include "draco_ext/common/threads.h"
#include "draco_ext/linalg/dense_front.h"
#include "draco_ext/linalg/elimination_tree.h"

namespace draco {

namespace {

// Factorisations of fewer flops stay on one thread.
constexpr double kMinThreadFlops = 1e8;
// Solve() stays on one thread for factors of fewer entries (8 MB).
constexpr int64_t kMinSolveThreadEntries = int64_t{1} << 20;
// Factorize() runs subtrees of at most this share of the work as one task.
constexpr double kMaxTaskShare = 1.0 / 64;

}  // namespace

bool SparseCholesky::Analyze(const MatrixGraph &graph, int64_t max_entries,
                             const std::function<void()> &work) {
  bool ok = false;
  RunBoth(work, [&] { ok = Analyze(graph, max_entries); });
  return ok;
}

bool SparseCholesky::Analyze(const MatrixGraph &graph, int64_t max_entries) {
  const int n = graph.size();
  nodes_.clear();
  unknown_of_.clear();
  if (n > 0) {
    const std::vector<int> order = ColumnMinimumDegreeOrder(graph);
    Supernodes supernodes;
    if (static_cast<int>(order.size()) != n ||
        !ComputeSupernodes(graph, order, max_entries, &supernodes)) {
      return false;
    }
    unknown_of_ = std::move(supernodes.order);
    nodes_.resize(supernodes.parent.size());
    for (size_t i = 0; i < nodes_.size(); ++i) {
      nodes_[i].first_column = supernodes.first_column[i];
      nodes_[i].num_columns =
          supernodes.first_column[i + 1] - supernodes.first_column[i];
      if (supernodes.parent[i] >= 0) {
        nodes_[supernodes.parent[i]].children.push_back(static_cast<int>(i));
      }
    }
  }
  column_of_.assign(n, 0);
  for (int column = 0; column < n; ++column) {
    column_of_[unknown_of_[column]] = column;
  }
  if (!ComputeUpdateRows(graph)) {
    return false;
  }
  parent_.assign(nodes_.size(), -1);
  subtree_size_.assign(nodes_.size(), 1);
  for (size_t i = 0; i < nodes_.size(); ++i) {
    for (const int child : nodes_[i].children) {
      parent_[child] = static_cast<int>(i);
      subtree_size_[i] += subtree_size_[child];
    }
  }
  node_of_column_.assign(n, 0);
  int64_t offset = 0;
  for (size_t i = 0; i < nodes_.size(); ++i) {
    Node &node = nodes_[i];
    node.panel_offset = offset;
    offset += static_cast<int64_t>(node.front_size()) * node.num_columns;
    std::fill(node_of_column_.begin() + node.first_column,
              node_of_column_.begin() + node.first_column + node.num_columns,
              static_cast<int>(i));
  }
  ChooseSolveSubtrees();
  ChooseFactorTasks();
  if (offset > max_entries) {
    return false;
  }
  // Not zeroed: Factorize() writes every entry.
  panels_.reset(new double[offset]);
  num_panel_entries_ = offset;
  return true;
}

bool SparseCholesky::ComputeUpdateRows(const MatrixGraph &graph) {
  // A node updates the later columns coupled to its own (at most two edges
  // away) and those its children update. A child's update row before the
  // node's own columns would belong to a sibling subtree, which the
  // elimination tree never couples; checked, because the extend-add relies
  // on it.
  // Each neighbour of the node's unknowns is searched once (|near|), not
  // once per unknown next to it.
  std::vector<int> seen(graph.size(), -1), searched(graph.size(), -1);
  std::vector<int> near;
  for (size_t i = 0; i < nodes_.size(); ++i) {
    Node &node = nodes_[i];
    const int end = node.first_column + node.num_columns;
    std::vector<int> &rows = node.update_rows;
    rows.clear();
    auto add = [&](int column) {
      if (column >= end && seen[column] != static_cast<int>(i)) {
        seen[column] = static_cast<int>(i);
        rows.push_back(column);
      }
    };
    near.clear();
    for (int column = node.first_column; column < end; ++column) {
      const int u = unknown_of_[column];
      for (int e = graph.start[u]; e < graph.start[u + 1]; ++e) {
        const int m = graph.neighbour[e];
        if (searched[m] != static_cast<int>(i)) {
          searched[m] = static_cast<int>(i);
          near.push_back(m);
        }
      }
    }
    for (const int m : near) {
      add(column_of_[m]);
      for (int f = graph.start[m]; f < graph.start[m + 1]; ++f) {
        add(column_of_[graph.neighbour[f]]);
      }
    }
    for (const int child : node.children) {
      for (const int column : nodes_[child].update_rows) {
        if (column < node.first_column) {
          return false;
        }
        add(column);
      }
    }
    std::sort(rows.begin(), rows.end());
  }
  return true;
}

void SparseCholesky::FrontColumns(const Node &node,
                                  std::vector<int> *columns) const {
  columns->resize(node.front_size());
  for (int i = 0; i < node.num_columns; ++i) {
    (*columns)[i] = node.first_column + i;
  }
  std::copy(node.update_rows.begin(), node.update_rows.end(),
            columns->begin() + node.num_columns);
}

Eigen::Map<Eigen::MatrixXd> SparseCholesky::Panel(const Node &node) {
  return Eigen::Map<Eigen::MatrixXd>(panels_.get() + node.panel_offset,
                                     node.front_size(), node.num_columns);
}

Eigen::Map<const Eigen::MatrixXd> SparseCholesky::Panel(
    const Node &node) const {
  return Eigen::Map<const Eigen::MatrixXd>(panels_.get() + node.panel_offset,
                                           node.front_size(), node.num_columns);
}

bool SparseCholesky::Factorize(const SymmetricMatrix &matrix) {
  if (matrix.size != num_unknowns()) {
    return false;
  }
  for (const double v : matrix.value) {
    if (!std::isfinite(v)) {
      return false;
    }
  }
  std::vector<std::vector<double>> updates(nodes_.size());
  // Every front's arithmetic and its children's order are fixed, so the
  // factor does not depend on which thread runs which task, or when.
  auto run_task = [&](const FactorTask &task, std::vector<int> *front_index,
                      std::vector<int> *columns, const ForkJoin *fork_join) {
    for (int n = task.first_node; n <= task.last_node; ++n) {
      if (!FactorizeNode(matrix, n, front_index, columns, &updates,
                         fork_join)) {
        return false;
      }
    }
    return true;
  };
  if (factor_tasks_.size() < 2 || !MayUseSecondThread()) {
    std::vector<int> front_index(num_unknowns(), -1), columns;
    const FactorTask all{0, static_cast<int>(nodes_.size()) - 1, -1};
    return run_task(all, &front_index, &columns, nullptr);
  }
  return RunFactorTasks(run_task);
}

// The factor tasks for two workers: a task is ready when its child tasks
// are done, and parents go first (they are on the longest path). A worker
// that splits a large front offers one half of each step to the other
// (ForkJoin()), which takes it while waiting for a task.
class SparseCholesky::TaskQueue {
 public:
  explicit TaskQueue(const std::vector<FactorTask> &tasks)
      : tasks_(tasks), pending_(tasks.size(), 0), num_left_(tasks.size()) {
    for (const FactorTask &task : tasks) {
      if (task.parent >= 0) {
        ++pending_[task.parent];
      }
    }
    for (size_t t = 0; t < tasks.size(); ++t) {
      if (pending_[t] == 0) {
        ready_.push_back(static_cast<int>(t));
      }
    }
  }

  // The next ready task, running offered halves meanwhile; false when all
  // tasks are done or one failed.
  bool Next(int *task) {
    std::unique_lock<std::mutex> lock(mutex_);
    while (true) {
      changed_.wait(lock, [&] {
        return HasOpenOffer() || !ready_.empty() || num_left_ == 0 || !ok_;
      });
      if (num_left_ == 0 || !ok_) {
        return false;
      }
      if (!HasOpenOffer()) {
        *task = ready_.front();
        ready_.pop_front();
        return true;
      }
      offer_taken_ = true;
      lock.unlock();
      (*offer_)();
      lock.lock();
      offer_done_ = true;
      changed_.notify_all();
    }
  }

  void Done(int task, bool ok) {
    std::lock_guard<std::mutex> lock(mutex_);
    ok_ = ok_ && ok;
    --num_left_;
    const int parent = tasks_[task].parent;
    if (parent >= 0 && --pending_[parent] == 0) {
      ready_.push_front(parent);
    }
    changed_.notify_all();
  }

  // Runs |a| here and offers |b| to the other worker; runs |b| here too if
  // the other has not taken it by then (or has an offer open itself).
  void ForkJoin(const std::function<void()> &a,
                const std::function<void()> &b) {
    std::unique_lock<std::mutex> lock(mutex_);
    const bool offered = offer_ == nullptr;
    if (offered) {
      offer_ = &b;
      offer_taken_ = offer_done_ = false;
      changed_.notify_all();
    }
    lock.unlock();
    a();
    lock.lock();
    if (offered && offer_taken_) {
      changed_.wait(lock, [&] { return offer_done_; });
      offer_ = nullptr;
      return;
    }
    if (offered) {
      offer_ = nullptr;
    }
    lock.unlock();
    b();
  }

  bool ok() const { return ok_; }

 private:
  bool HasOpenOffer() const { return offer_ != nullptr && !offer_taken_; }

  const std::vector<FactorTask> &tasks_;
  std::mutex mutex_;
  std::condition_variable changed_;
  std::deque<int> ready_;
  std::vector<int> pending_;  // Child tasks not done, per task.
  size_t num_left_;
  bool ok_ = true;
  const std::function<void()> *offer_ = nullptr;
  bool offer_taken_ = false;
  bool offer_done_ = false;
};

template <typename RunTask>
bool SparseCholesky::RunFactorTasks(const RunTask &run_task) const {
  TaskQueue queue(factor_tasks_);
  const ForkJoin fork_join = [&](const std::function<void()> &a,
                                 const std::function<void()> &b) {
    queue.ForkJoin(a, b);
  };
  auto worker = [&] {
    std::vector<int> front_index(num_unknowns(), -1), columns;
    int task;
    while (queue.Next(&task)) {
      queue.Done(task, run_task(factor_tasks_[task], &front_index, &columns,
                                &fork_join));
    }
  };
  RunBoth(worker, worker);
  return queue.ok();
}

bool SparseCholesky::MayUseSecondThread() const {
  return max_threads_ > 1 && SecondThreadAvailable();
}

template <typename Side, typename Other>
void SparseCholesky::RunBoth(const Side &side, const Other &other) const {
  SecondThread worker(side, max_threads_ > 1);
  other();
  worker.Join();
}

void SparseCholesky::ChooseFactorTasks() {
  const int num_nodes = static_cast<int>(nodes_.size());
  std::vector<double> subtree(num_nodes);
  double total = 0;
  for (int i = 0; i < num_nodes; ++i) {
    subtree[i] = NodeFlops(nodes_[i]);
    total += subtree[i];
    for (const int child : nodes_[i].children) {
      subtree[i] += subtree[child];
    }
  }
  factor_tasks_.clear();
  if (total < kMinThreadFlops) {
    return;
  }
  // From the roots down (parents after children in node order): subtrees
  // of at most kMaxTaskShare of the work are one task, larger subtrees'
  // root nodes one task each.
  std::vector<int> task_of(num_nodes, -1);
  for (int i = num_nodes - 1; i >= 0; --i) {
    const int parent_task = parent_[i] < 0 ? -1 : task_of[parent_[i]];
    if (parent_task >= 0 && factor_tasks_[parent_task].first_node <= i) {
      task_of[i] = parent_task;  // Inside the parent's subtree task.
      continue;
    }
    const bool whole_subtree = subtree[i] <= total * kMaxTaskShare;
    task_of[i] = static_cast<int>(factor_tasks_.size());
    factor_tasks_.push_back(
        {whole_subtree ? i - subtree_size_[i] + 1 : i, i, parent_task});
  }
  // In node order, children's tasks first.
  std::reverse(factor_tasks_.begin(), factor_tasks_.end());
  const int last = static_cast<int>(factor_tasks_.size()) - 1;
  for (FactorTask &task : factor_tasks_) {
    if (task.parent >= 0) {
      task.parent = last - task.parent;
    }
  }
}

void SparseCholesky::ChooseSolveSubtrees() {
  // Solve() reads every entry of the factor once per pass.
  const int num_nodes = static_cast<int>(nodes_.size());
  std::vector<int64_t> subtree(num_nodes);
  int64_t total = 0;
  for (int i = 0; i < num_nodes; ++i) {
    subtree[i] =
        static_cast<int64_t>(nodes_[i].front_size()) * nodes_[i].num_columns;
    total += subtree[i];
    for (const int child : nodes_[i].children) {
      subtree[i] += subtree[child];
    }
  }
  solve_roots_.clear();
  in_solve_side_.assign(num_nodes, 0);
  if (total < kMinSolveThreadEntries) {
    return;
  }
  // From the roots down (parents after children in node order), every
  // subtree that still fits into half the work.
  int64_t remaining = total / 2;
  for (int i = num_nodes - 1; i >= 0; --i) {
    if (parent_[i] >= 0 && in_solve_side_[parent_[i]]) {
      in_solve_side_[i] = 1;
    } else if (subtree[i] <= remaining) {
      in_solve_side_[i] = 1;
      solve_roots_.push_back(i);
      remaining -= subtree[i];
    }
  }
  // In node order, which is the order of their parents too.
  std::reverse(solve_roots_.begin(), solve_roots_.end());
}

bool SparseCholesky::FactorizeNode(
    const SymmetricMatrix &matrix, int n, std::vector<int> *front_index_ptr,
    std::vector<int> *columns_ptr,
    std::vector<std::vector<double>> *updates_ptr, const ForkJoin *fork_join) {
  std::vector<int> &front_index = *front_index_ptr;
  std::vector<int> &columns = *columns_ptr;
  std::vector<std::vector<double>> &updates = *updates_ptr;
  const Node &node = nodes_[n];
  const int k = node.num_columns;
  const int m = node.front_size();
  FrontColumns(node, &columns);
  for (int i = 0; i < m; ++i) {
    front_index[columns[i]] = i;
  }
  // The front [panel | 0; update] in place: its first k columns are the
  // node's panel of the factor, its lower right block the update matrix
  // handed to the parent, so neither is copied.
  Eigen::Map<Eigen::MatrixXd> panel = Panel(node);
  panel.setZero();
  updates[n].assign(static_cast<size_t>(m - k) * (m - k), 0.0);
  Eigen::Map<Eigen::MatrixXd> update(updates[n].data(), m - k, m - k);
  // The node's columns of the matrix (lower triangle in factor order).
  for (int j = 0; j < k; ++j) {
    const int column = node.first_column + j;
    const int unknown = unknown_of_[column];
    for (int e = matrix.column_start[unknown];
         e < matrix.column_start[unknown + 1]; ++e) {
      const int row_column = column_of_[matrix.row[e]];
      if (row_column < column) {
        continue;
      }
      const int local = front_index[row_column];
      if (local < 0 || local >= m || columns[local] != row_column) {
        return false;  // Not in the analysed pattern.
      }
      panel(local, j) += matrix.value[e];
    }
  }
  // Extend-add of the children's update matrices (lower triangles).
  for (const int child : node.children) {
    const std::vector<int> &rows = nodes_[child].update_rows;
    const int size = static_cast<int>(rows.size());
    Eigen::Map<const Eigen::MatrixXd> child_update(updates[child].data(), size,
                                                   size);
    for (int a = 0; a < size; ++a) {
      // Rows at or below the column's diagonal, in the panel or the update.
      const int column = front_index[rows[a]];
      double *target = column < k ? &panel(0, column) : &update(0, column - k);
      const int row_offset = column < k ? 0 : k;
      for (int b = a; b < size; ++b) {
        target[front_index[rows[b]] - row_offset] += child_update(b, a);
      }
    }
    std::vector<double>().swap(updates[child]);
  }
  // Dense partial factorisation: L11 L11^T = F11, L21 = F21 L11^-T,
  // update = F22 - L21 L21^T.
  return FactorDenseFront(dense_kernels_, panel.data(), m, k, update.data(),
                          fork_join);
}

void SparseCholesky::UpdateColumn(Node &node, int local,
                                  std::vector<double> *w) {
  const int column = node.first_column + local;
  const double x = (*w)[column];
  if (x == 0.0) {
    return;
  }
  Eigen::Map<Eigen::MatrixXd> panel = Panel(node);
  const double d = panel(local, local);
  // Not std::hypot(): C libraries differ in its last bit, while the square
  // root is correctly rounded everywhere (d and x are far from overflow).
  const double r = std::sqrt(d * d + x * x);
  const double c = r / d;
  const double s = x / d;
  panel(local, local) = r;
  (*w)[column] = 0.0;
  const int k = node.num_columns;
  for (int i = local + 1; i < node.front_size(); ++i) {
    const int row = i < k ? node.first_column + i : node.update_rows[i - k];
    const double l = (panel(i, local) + s * (*w)[row]) / c;
    (*w)[row] = c * (*w)[row] - s * l;
    panel(i, local) = l;
  }
}

void SparseCholesky::AddToDiagonal(int unknown, double delta) {
  // [Gill et al. 1974] method C1 along the elimination path: within a front
  // every later column depends on the current one, and a front's last
  // column hands over to its first update row.
  std::vector<double> w(num_unknowns(), 0.0);
  int column = column_of_[unknown];
  w[column] = std::sqrt(delta);
  while (true) {
    Node &node = nodes_[node_of_column_[column]];
    for (int local = column - node.first_column; local < node.num_columns;
         ++local) {
      UpdateColumn(node, local, &w);
    }
    if (node.update_rows.empty()) {
      break;
    }
    column = node.update_rows[0];
  }
}

void SparseCholesky::ForwardNode(const Node &node, Eigen::MatrixXd *y,
                                 Eigen::MatrixXd *outside, int outside_begin,
                                 Eigen::MatrixXd *gathered) const {
  const int k = node.num_columns;
  if (k == 0) {
    return;
  }
  const auto panel = Panel(node);
  auto own = y->middleRows(node.first_column, k);
  // Triangular solves and matrix-vector products per right-hand side: a
  // matrix product would copy (pack) the whole panel for the few right-hand
  // sides, and Eigen blocks the matrix kernels (and so orders their sums) by
  // the cache sizes it reads from the CPU, its vector kernels by fixed sizes.
  for (int c = 0; c < own.cols(); ++c) {
    panel.topRows(k).triangularView<Eigen::Lower>().solveInPlace(own.col(c));
  }
  if (node.update_rows.empty()) {
    return;
  }
  const auto below = panel.bottomRows(node.update_rows.size());
  gathered->resize(node.update_rows.size(), own.cols());
  for (int c = 0; c < own.cols(); ++c) {
    gathered->col(c).noalias() = below * own.col(c);
  }
  for (size_t i = 0; i < node.update_rows.size(); ++i) {
    const int row = node.update_rows[i];
    if (outside != nullptr && row >= outside_begin) {
      outside->row(row) -= gathered->row(i);
    } else {
      y->row(row) -= gathered->row(i);
    }
  }
}

void SparseCholesky::BackwardNode(const Node &node, Eigen::MatrixXd *y,
                                  Eigen::MatrixXd *gathered) const {
  const int k = node.num_columns;
  if (k == 0) {
    return;
  }
  const auto panel = Panel(node);
  auto own = y->middleRows(node.first_column, k);
  if (!node.update_rows.empty()) {
    gathered->resize(node.update_rows.size(), y->cols());
    for (size_t i = 0; i < node.update_rows.size(); ++i) {
      gathered->row(i) = y->row(node.update_rows[i]);
    }
    const auto below = panel.bottomRows(node.update_rows.size());
    for (int c = 0; c < own.cols(); ++c) {
      own.col(c).noalias() -= below.transpose() * gathered->col(c);
    }
  }
  for (int c = 0; c < own.cols(); ++c) {
    panel.topRows(k).transpose().triangularView<Eigen::Upper>().solveInPlace(
        own.col(c));
  }
}

// How far one thread of Solve() has got, for the other to wait on.
class SparseCholesky::SolveProgress {
 public:
  void Advance(int value) {
    std::lock_guard<std::mutex> lock(mutex_);
    value_ = value;
    changed_.notify_one();
  }
  void WaitFor(int value) {
    std::unique_lock<std::mutex> lock(mutex_);
    changed_.wait(lock, [&] { return value_ >= value; });
  }
  void Reset() { value_ = 0; }

 private:
  std::mutex mutex_;
  std::condition_variable changed_;
  int value_ = 0;
};

void SparseCholesky::Solve(Eigen::Ref<Eigen::MatrixXd> rhs) const {
  const int num_rhs = static_cast<int>(rhs.cols());
  Eigen::MatrixXd y(num_unknowns(), num_rhs);
  for (int u = 0; u < num_unknowns(); ++u) {
    y.row(column_of_[u]) = rhs.row(u);
  }
  // The side subtrees' updates of other nodes' rows go to |outside|, and
  // are added to a node's rows just before it is solved, whatever the
  // threads.
  Eigen::MatrixXd outside = Eigen::MatrixXd::Zero(num_unknowns(), num_rhs);
  SolveProgress progress;
  RunBoth(
      [&] {
        Eigen::MatrixXd gathered;
        for (const int root : solve_roots_) {
          const int first = root - subtree_size_[root] + 1;
          for (int n = first; n <= root; ++n) {
            ForwardNode(nodes_[n], &y, &outside,
                        nodes_[root].first_column + nodes_[root].num_columns,
                        &gathered);
          }
          progress.Advance(root + 1);
        }
      },
      [&] { ForwardOtherNodes(&y, outside, &progress); });
  progress.Reset();
  // Back substitution: a node reads only its ancestors' columns.
  RunBoth([&] { BackwardOtherNodes(&y, &progress); },
          [&] {
            Eigen::MatrixXd gathered;
            for (auto root = solve_roots_.rbegin(); root != solve_roots_.rend();
                 ++root) {
              const int parent = parent_[*root];
              progress.WaitFor(parent < 0 ? 0 : num_nodes() - parent);
              for (int n = *root; n > *root - subtree_size_[*root]; --n) {
                BackwardNode(nodes_[n], &y, &gathered);
              }
            }
          });
  for (int u = 0; u < num_unknowns(); ++u) {
    rhs.row(u) = y.row(column_of_[u]);
  }
}

void SparseCholesky::ForwardOtherNodes(Eigen::MatrixXd *y,
                                       const Eigen::MatrixXd &outside,
                                       SolveProgress *progress) const {
  Eigen::MatrixXd gathered;
  for (int n = 0; n < num_nodes(); ++n) {
    if (in_solve_side_[n]) {
      continue;
    }
    for (const int child : nodes_[n].children) {
      if (in_solve_side_[child]) {
        progress->WaitFor(child + 1);
      }
    }
    const Node &node = nodes_[n];
    y->middleRows(node.first_column, node.num_columns) +=
        outside.middleRows(node.first_column, node.num_columns);
    ForwardNode(node, y, nullptr, 0, &gathered);
  }
}

void SparseCholesky::BackwardOtherNodes(Eigen::MatrixXd *y,
                                        SolveProgress *progress) const {
  Eigen::MatrixXd gathered;
  for (int n = num_nodes() - 1; n >= 0; --n) {
    if (!in_solve_side_[n]) {
      BackwardNode(nodes_[n], y, &gathered);
    }
    progress->Advance(num_nodes() - n);
  }
}

}  // namespace draco
