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
#include <numeric>
#include <utility>

#include <Eigen/Core>

#include "draco_ext/common/threads.h"
#include "draco_ext/linalg/dense_front.h"

namespace draco {

namespace {

// Dissection stops at subsets of at most this many points (dense leaves).
constexpr int kLeafPoints = 32;

// Factorisations of fewer flops, and dissections of fewer points, stay on
// one thread.
constexpr double kMinThreadFlops = 1e8;
constexpr size_t kMinThreadPoints = 20000;
// Solve() stays on one thread for factors of fewer entries (8 MB).
constexpr int64_t kMinSolveThreadEntries = int64_t{1} << 20;
// Factorize() runs subtrees of at most this share of the work as one task.
constexpr double kMaxTaskShare = 1.0 / 64;

}  // namespace

// Nested dissection of the point graph [George & Liu 1978]: every subset is
// split into its connected components, and a connected subset at a small
// balanced separator (a level of a breadth-first level structure rooted at
// a pseudo-peripheral point, or a cut across the structure's longest
// extent), thinned. Points are appended to |order| children first, so that the
// order in which nodes are created is a postorder of the dissection tree.
class SparseCholesky::Dissection {
 public:
  explicit Dissection(const MatrixGraph &graph)
      : graph_(graph),
        marks_(graph.size()),
        distance_(graph.size(), 0),
        side_(graph.size(), 0) {}

  // Returns the index of the subtree's root in |nodes|. With |may_spawn|,
  // the first split into two balanced groups of parts dissects the second
  // group on another thread (with its own Dissection); the nodes and order
  // are the same as on one thread.
  int Dissect(std::vector<int> points, bool may_spawn, std::vector<Node> *nodes,
              std::vector<int> *order) {
    if (points.size() <= static_cast<size_t>(kLeafPoints)) {
      std::sort(points.begin(), points.end());
      return AddNode(points, {}, nodes, order);
    }
    std::vector<std::vector<int>> parts;
    std::vector<int> separator;
    Split(points, &parts, &separator);
    std::vector<int> children;
    const size_t second = may_spawn ? SecondGroup(parts) : parts.size();
    if (second < parts.size()) {
      DissectOnTwoThreads(&parts, second, &children, nodes, order);
    } else {
      // Only the largest part may still spawn.
      size_t largest = 0;
      for (size_t i = 1; i < parts.size(); ++i) {
        if (parts[i].size() > parts[largest].size()) {
          largest = i;
        }
      }
      for (size_t i = 0; i < parts.size(); ++i) {
        children.push_back(Dissect(std::move(parts[i]),
                                   may_spawn && i == largest, nodes, order));
      }
    }
    std::sort(separator.begin(), separator.end());
    return AddNode(separator, std::move(children), nodes, order);
  }

 private:
  // The first part of the second group when parts[0 .. i - 1] and the
  // rest each hold at least a third of the points, else parts.size().
  static size_t SecondGroup(const std::vector<std::vector<int>> &parts) {
    size_t total = 0;
    for (const std::vector<int> &part : parts) {
      total += part.size();
    }
    size_t before = 0;
    for (size_t i = 0; i < parts.size(); ++i) {
      if (3 * before >= total && 3 * (total - before) >= total &&
          total >= kMinThreadPoints) {
        return i;
      }
      before += parts[i].size();
    }
    return parts.size();
  }

  void DissectOnTwoThreads(std::vector<std::vector<int>> *parts, size_t second,
                           std::vector<int> *children, std::vector<Node> *nodes,
                           std::vector<int> *order) {
    std::vector<Node> side_nodes;
    std::vector<int> side_order, side_roots;
    SecondThread worker([&] {
      Dissection side(graph_);
      for (size_t i = second; i < parts->size(); ++i) {
        side_roots.push_back(side.Dissect(std::move((*parts)[i]), false,
                                          &side_nodes, &side_order));
      }
    });
    for (size_t i = 0; i < second; ++i) {
      children->push_back(Dissect(std::move((*parts)[i]), false, nodes, order));
    }
    worker.Join();
    // Renumber the second group's nodes and columns after the first's.
    const int node_offset = static_cast<int>(nodes->size());
    const int column_offset = static_cast<int>(order->size());
    for (Node &node : side_nodes) {
      node.first_column += column_offset;
      for (int &child : node.children) {
        child += node_offset;
      }
      nodes->push_back(std::move(node));
    }
    for (const int root : side_roots) {
      children->push_back(root + node_offset);
    }
    order->insert(order->end(), side_order.begin(), side_order.end());
  }

  static int AddNode(const std::vector<int> &points, std::vector<int> children,
                     std::vector<Node> *nodes, std::vector<int> *order) {
    Node node;
    node.first_column = static_cast<int>(order->size());
    node.num_columns = static_cast<int>(points.size());
    node.children = std::move(children);
    order->insert(order->end(), points.begin(), points.end());
    nodes->push_back(std::move(node));
    return static_cast<int>(nodes->size()) - 1;
  }

  // A disconnected subset becomes its components (empty separator); a
  // connected one loses a small separator near its middle.
  void Split(const std::vector<int> &points,
             std::vector<std::vector<int>> *parts,
             std::vector<int> *separator) {
    const int label = next_label_++;
    for (const int p : points) {
      marks_[p].label = label;
    }
    std::vector<int> levels;
    std::vector<int> reached;
    LevelStructure(points[0], label, &reached, &levels);
    if (reached.size() < points.size()) {
      SplitComponents(points, label, parts);
      return;
    }
    // Pseudo-peripheral root a: restart from a point b of the last level
    // while the depth grows. far_* is the level structure from b.
    std::vector<int> far_reached, far_levels;
    bool have_far = false;
    for (int attempt = 0; attempt < 4 && !have_far; ++attempt) {
      LevelStructure(reached.back(), label, &far_reached, &far_levels);
      have_far = far_levels.size() <= levels.size();
      if (!have_far) {
        reached.swap(far_reached);
        levels.swap(far_levels);
      }
    }
    if (!have_far) {
      LevelStructure(reached.back(), label, &far_reached, &far_levels);
    }
    // sides[i]: where reached[i] goes. The smaller of two balanced cuts,
    // thinned.
    std::vector<int8_t> sides;
    const int level_cut = LevelCut(levels, &sides);
    DistanceCut(reached, levels, far_reached, far_levels, level_cut, &sides);
    ThinSeparator(reached, label, &sides);
    std::vector<int> before, after;
    for (size_t i = 0; i < reached.size(); ++i) {
      std::vector<int> &target = sides[i] == kBefore  ? before
                                 : sides[i] == kAfter ? after
                                                      : *separator;
      target.push_back(reached[i]);
    }
    if (!before.empty()) {
      parts->push_back(std::move(before));
    }
    if (!after.empty()) {
      // Farthest points first: a part's search starts from its first point,
      // for both parts a point far from the separator, so that the search
      // for a pseudo-peripheral point ends sooner (measured 5-8% fewer edge
      // visits, 1-2% fewer factor flops on the 300k-vertex meshes).
      std::reverse(after.begin(), after.end());
      parts->push_back(std::move(after));
    }
  }

  static constexpr int8_t kBefore = 0;
  static constexpr int8_t kSeparator = 1;
  static constexpr int8_t kAfter = 2;

  // Whether a cut leaving |before| points before and |after| after a
  // separator is balanced enough.
  static bool Balanced(int64_t before, int64_t after) {
    const int64_t parts = before + after;
    return 5 * std::min(before, after) >= 2 * parts;
  }

  // The smallest pair of consecutive levels whose sides are balanced
  // [George & Liu 1978]; levels[l] is the end of level l in the level
  // order. Two levels, because points two edges apart are coupled (see
  // LevelStructure()). Returns the separator's size.
  int LevelCut(const std::vector<int> &levels, std::vector<int8_t> *sides) {
    const int num_levels = static_cast<int>(levels.size());
    const int total = levels.back();
    int best = -1;
    int best_size = 0;
    for (int l = 1; l + 2 < num_levels; ++l) {
      const int size = levels[l + 1] - levels[l - 1];
      if (Balanced(levels[l - 1], total - levels[l + 1]) &&
          (best < 0 || size < best_size)) {
        best = l;
        best_size = size;
      }
    }
    if (best < 0) {
      // Few levels (a dense subset): the levels at the median.
      best = 1;
      while (best + 2 < num_levels && levels[best] < total / 2) {
        ++best;
      }
    }
    const int end = levels[std::min(best + 1, num_levels - 1)];
    sides->assign(total, kAfter);
    std::fill(sides->begin(), sides->begin() + levels[best - 1], kBefore);
    std::fill(sides->begin() + levels[best - 1], sides->begin() + end,
              kSeparator);
    return end - levels[best - 1];
  }

  // A cut across the subset's longest extent: with d_a and d_b the
  // distances from the root a and from the farthest point b of the level
  // structure, f = d_a - d_b changes by at most 4 between coupled points
  // (two edges apart), so the points with f in c .. c + 3 separate f < c
  // from f > c + 3. Unlike a level (a circle around a), the level sets of
  // f run straight across the middle, which measured 5-60% fewer factor
  // flops. Replaces |sides| when the smallest balanced such cut is smaller
  // than |current_size|.
  void DistanceCut(const std::vector<int> &reached,
                   const std::vector<int> &levels,
                   const std::vector<int> &far_reached,
                   const std::vector<int> &far_levels, int current_size,
                   std::vector<int8_t> *sides) {
    const int total = static_cast<int>(reached.size());
    for (size_t l = 0, i = 0; l < levels.size(); ++l) {
      for (; i < static_cast<size_t>(levels[l]); ++i) {
        distance_[reached[i]] = static_cast<int>(l);
      }
    }
    const int offset = static_cast<int>(far_levels.size());
    std::vector<int> histogram(levels.size() + far_levels.size() + 4, 0);
    for (size_t l = 0, i = 0; l < far_levels.size(); ++l) {
      for (; i < static_cast<size_t>(far_levels[l]); ++i) {
        const int p = far_reached[i];
        distance_[p] = distance_[p] - static_cast<int>(l) + offset;
        ++histogram[distance_[p]];
      }
    }
    int best = -1, best_size = 0, before = 0;
    for (size_t c = 0; c + 3 < histogram.size(); ++c) {
      const int size =
          histogram[c] + histogram[c + 1] + histogram[c + 2] + histogram[c + 3];
      if (Balanced(before, total - before - size) &&
          (best < 0 || size < best_size)) {
        best = static_cast<int>(c);
        best_size = size;
      }
      before += histogram[c];
    }
    if (best < 0 || best_size >= current_size) {
      return;
    }
    for (int i = 0; i < total; ++i) {
      const int f = distance_[reached[i]];
      (*sides)[i] = f < best ? kBefore : f > best + 3 ? kAfter : kSeparator;
    }
  }

  // Moves the separator's points coupled to no point after it to before
  // it, then those coupled to no point before it to after it. A separator
  // between two non-empty sides of a connected subset stays non-empty.
  void ThinSeparator(const std::vector<int> &reached, int label,
                     std::vector<int8_t> *sides) {
    if (std::find(sides->begin(), sides->end(), kAfter) == sides->end()) {
      return;
    }
    for (size_t i = 0; i < reached.size(); ++i) {
      side_[reached[i]] = (*sides)[i];
    }
    for (const int8_t from : {kAfter, kBefore}) {
      for (size_t i = 0; i < reached.size(); ++i) {
        const int p = reached[i];
        if (side_[p] != kSeparator) {
          continue;
        }
        if (!Coupled(p, label, from)) {
          side_[p] = static_cast<int8_t>(kAfter - from);
          (*sides)[i] = side_[p];
        }
      }
    }
  }

  // Whether point |p| is coupled to (at most two edges from) a point
  // labelled |label| on side |side|.
  bool Coupled(int p, int label, int8_t side) const {
    for (int e = graph_.start[p]; e < graph_.start[p + 1]; ++e) {
      const int m = graph_.neighbour[e];
      if (marks_[m].label == label && side_[m] == side) {
        return true;
      }
      for (int f = graph_.start[m]; f < graph_.start[m + 1]; ++f) {
        const int q = graph_.neighbour[f];
        if (marks_[q].label == label && side_[q] == side) {
          return true;
        }
      }
    }
    return false;
  }

  // |points| (labelled |label|) as coupled components.
  void SplitComponents(const std::vector<int> &points, int label,
                       std::vector<std::vector<int>> *parts) {
    std::vector<int> levels;
    for (const int p : points) {
      if (marks_[p].label != label) {
        continue;  // In an earlier component.
      }
      parts->emplace_back();
      LevelStructure(p, label, &parts->back(), &levels);
      for (const int q : parts->back()) {
        marks_[q].label = -1;
      }
    }
  }

  // Breadth-first search from |root| over points labelled |label|: |reached|
  // in level order, |levels| the end offset of every level. Points two
  // edges apart are coupled (the matrix has the pattern of the graph's
  // square) also through a point outside the subset (of an ancestor
  // separator): the search steps onto such a point, as a level of its own
  // that |reached| leaves out, but not on from it to another one.
  void LevelStructure(int root, int label, std::vector<int> *reached,
                      std::vector<int> *levels) {
    const int stamp = next_stamp_++;
    reached->clear();
    levels->clear();
    reached->push_back(root);
    marks_[root].stamp = stamp;
    frontier_.assign(1, root);
    while (!frontier_.empty()) {
      levels->push_back(static_cast<int>(reached->size()));
      next_frontier_.clear();
      for (const int p : frontier_) {
        const bool outside = marks_[p].label != label;
        for (int e = graph_.start[p]; e < graph_.start[p + 1]; ++e) {
          const int q = graph_.neighbour[e];
          if (marks_[q].stamp == stamp) {
            continue;
          }
          if (marks_[q].label == label) {
            reached->push_back(q);
          } else if (outside) {
            continue;
          }
          marks_[q].stamp = stamp;
          next_frontier_.push_back(q);
        }
      }
      frontier_.swap(next_frontier_);
    }
    // No trailing levels of outside points only.
    while (levels->size() > 1 &&
           (*levels)[levels->size() - 2] == (*levels)[levels->size() - 1]) {
      levels->pop_back();
    }
  }

  const MatrixGraph &graph_;
  // Per point its subset's label and the stamp of the last search that
  // reached it, side by side: a search reads both.
  struct Mark {
    int label = -1;
    int stamp = -1;
  };
  std::vector<Mark> marks_;
  std::vector<int> distance_;
  std::vector<int8_t> side_;
  std::vector<int> frontier_;
  std::vector<int> next_frontier_;
  int next_label_ = 0;
  int next_stamp_ = 0;
};

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
  unknown_of_.reserve(n);
  std::vector<int> all(n);
  std::iota(all.begin(), all.end(), 0);
  if (n > 0) {
    const bool may_spawn = MayUseSecondThread();
    Dissection(graph).Dissect(std::move(all), may_spawn, &nodes_, &unknown_of_);
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
  // dissection never couples; checked, because the extend-add relies on it.
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
