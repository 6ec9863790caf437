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
#include "draco_ext/linalg/elimination_tree.h"

#include <algorithm>

#include <Eigen/OrderingMethods>

namespace draco {

namespace {

// The columns of A's row (and column) |u|: u and its neighbours.
template <typename Visit>
void ForRowOfA(const MatrixGraph &graph, int u, const Visit &visit) {
  visit(u);
  for (int e = graph.start[u]; e < graph.start[u + 1]; ++e) {
    visit(graph.neighbour[e]);
  }
}

// The elimination tree of A^T A in column order (parent column, -1 for
// roots), from A's rows: the columns sharing a row of A form a clique of
// A^T A, whose first column suffices [Liu 1990] (CSparse's cs_etree).
std::vector<int> ColumnEliminationTree(const MatrixGraph &graph,
                                       const std::vector<int> &order,
                                       const std::vector<int> &column_of) {
  const int n = graph.size();
  std::vector<int> parent(n, -1), ancestor(n, -1), previous(n, -1);
  for (int k = 0; k < n; ++k) {
    ForRowOfA(graph, order[k], [&](int row) {
      int i = previous[row];
      while (i != -1 && i < k) {
        const int next = ancestor[i];
        ancestor[i] = k;  // Path compression.
        if (next == -1) {
          parent[i] = k;
          break;
        }
        i = next;
      }
      previous[row] = k;
    });
  }
  return parent;
}

// A postorder of the forest |parent|: post[new] = old, children in
// ascending order.
std::vector<int> Postorder(const std::vector<int> &parent) {
  const int n = static_cast<int>(parent.size());
  std::vector<int> head(n, -1), next(n, -1), post, stack;
  post.reserve(n);
  for (int j = n - 1; j >= 0; --j) {
    if (parent[j] >= 0) {
      next[j] = head[parent[j]];
      head[parent[j]] = j;
    }
  }
  for (int root = 0; root < n; ++root) {
    if (parent[root] >= 0) {
      continue;
    }
    stack.assign(1, root);
    while (!stack.empty()) {
      const int p = stack.back();
      const int child = head[p];
      if (child == -1) {
        stack.pop_back();
        post.push_back(p);
      } else {
        head[p] = next[child];
        stack.push_back(child);
      }
    }
  }
  return post;
}

// The column counts (diagonal included) of A^T A's factor for a
// postordered tree [Gilbert et al. 1994] (CSparse's cs_counts for A^T A):
// every row of A enters at its first column, and each column's count is the
// sum of its skeleton entries' row subtrees' leaves, without overlaps.
std::vector<int64_t> ColumnCounts(const MatrixGraph &graph,
                                  const std::vector<int> &order,
                                  const std::vector<int> &column_of,
                                  const std::vector<int> &parent) {
  const int n = graph.size();
  std::vector<int64_t> delta(n, 0);
  std::vector<int> first(n, -1), max_first(n, -1), previous_leaf(n, -1);
  std::vector<int> ancestor(n), head(n, -1), next(n, -1);
  for (int k = 0; k < n; ++k) {
    delta[k] = first[k] == -1 ? 1 : 0;  // 1 for a leaf.
    for (int j = k; j != -1 && first[j] == -1; j = parent[j]) {
      first[j] = k;
    }
  }
  for (int u = 0; u < n; ++u) {  // Row u of A by its first column.
    int k = n;
    ForRowOfA(graph, u, [&](int v) { k = std::min(k, column_of[v]); });
    next[u] = head[k];
    head[k] = u;
  }
  for (int i = 0; i < n; ++i) {
    ancestor[i] = i;
  }
  for (int j = 0; j < n; ++j) {
    if (parent[j] != -1) {
      --delta[parent[j]];
    }
    for (int row = head[j]; row != -1; row = next[row]) {
      ForRowOfA(graph, row, [&](int v) {
        const int i = column_of[v];
        // Whether j is a leaf of row i's subtree (cs_leaf()).
        if (i <= j || first[j] <= max_first[i]) {
          return;
        }
        max_first[i] = first[j];
        const int previous = previous_leaf[i];
        previous_leaf[i] = j;
        ++delta[j];
        if (previous == -1) {
          return;
        }
        int q = previous;
        while (q != ancestor[q]) {
          q = ancestor[q];
        }
        for (int s = previous; s != q;) {
          const int s_parent = ancestor[s];
          ancestor[s] = q;
          s = s_parent;
        }
        --delta[q];  // The overlap of the two leaves' paths.
      });
    }
    if (parent[j] != -1) {
      ancestor[j] = parent[j];
    }
  }
  for (int j = 0; j < n; ++j) {
    if (parent[j] != -1) {
      delta[parent[j]] += delta[j];
    }
  }
  return delta;
}

// Relaxation of [Ashcraft & Grimes 1989] with CHOLMOD's thresholds: a
// child is merged into its parent when the merged front has at most
// kRelax[i].columns columns and explicit zeros below kRelax[i].zeros of its
// entries.
struct Relaxation {
  int columns;
  double zeros;
};
constexpr Relaxation kRelax[] = {
    {4, 1.0}, {16, 0.8}, {48, 0.1}, {1 << 30, 0.05}};

bool MayMerge(int columns, double zeros, double entries) {
  for (const Relaxation &r : kRelax) {
    if (columns <= r.columns && zeros < r.zeros * entries) {
      return true;
    }
  }
  return false;
}

// The elimination tree of A^T A with the columns of |order| renumbered in
// a postorder of it: returns the parent column per column, and the new
// order (column -> unknown) and its inverse.
std::vector<int> PostorderedTree(const MatrixGraph &graph,
                                 const std::vector<int> &order,
                                 std::vector<int> *new_order,
                                 std::vector<int> *column_of) {
  const int n = graph.size();
  column_of->resize(n);
  for (int k = 0; k < n; ++k) {
    (*column_of)[order[k]] = k;
  }
  const std::vector<int> parent =
      ColumnEliminationTree(graph, order, *column_of);
  const std::vector<int> post = Postorder(parent);
  std::vector<int> new_column(n);
  for (int k = 0; k < n; ++k) {
    new_column[post[k]] = k;
  }
  new_order->resize(n);
  std::vector<int> new_parent(n);
  for (int k = 0; k < n; ++k) {
    (*new_order)[k] = order[post[k]];
    (*column_of)[(*new_order)[k]] = k;
    new_parent[k] = parent[post[k]] < 0 ? -1 : new_column[parent[post[k]]];
  }
  return new_parent;
}

// The first column of every fundamental supernode (chains of only
// children with nested patterns), plus the end.
std::vector<int> FundamentalSupernodes(const std::vector<int> &parent,
                                       const std::vector<int64_t> &count) {
  const int n = static_cast<int>(parent.size());
  std::vector<int> num_children(n, 0);
  for (int j = 0; j < n; ++j) {
    if (parent[j] >= 0) {
      ++num_children[parent[j]];
    }
  }
  std::vector<int> first{0};
  for (int j = 1; j < n; ++j) {
    if (parent[j - 1] != j || num_children[j] != 1 ||
        count[j - 1] != count[j] + 1) {
      first.push_back(j);
    }
  }
  first.push_back(n);
  return first;
}

// Merges the fundamental supernodes starting at |first| into their parents
// while MayMerge() [Ashcraft & Grimes 1989]; writes |supernodes|'
// first_column and parent.
void Amalgamate(const std::vector<int> &parent,
                const std::vector<int64_t> &count,
                const std::vector<int> &first, Supernodes *supernodes) {
  const int n = static_cast<int>(parent.size());
  const int num_fundamental = static_cast<int>(first.size()) - 1;
  // Per group of merged supernodes (stored at its first): columns, rows
  // of the front (own columns included), explicit zeros, parent.
  std::vector<int> columns(num_fundamental), rows(num_fundamental);
  std::vector<double> zeros(num_fundamental, 0.0);
  std::vector<int> super_parent(num_fundamental, -1), super_of(n);
  for (int s = 0; s < num_fundamental; ++s) {
    columns[s] = first[s + 1] - first[s];
    rows[s] = static_cast<int>(count[first[s]]);
    std::fill(super_of.begin() + first[s], super_of.begin() + first[s + 1], s);
  }
  for (int s = 0; s < num_fundamental; ++s) {
    const int last_parent = parent[first[s + 1] - 1];
    super_parent[s] = last_parent < 0 ? -1 : super_of[last_parent];
  }
  // From the top: a last child merges into its parent (group).
  std::vector<char> merged_into_previous(num_fundamental, 0);
  for (int s = num_fundamental - 2; s >= 0; --s) {
    const int p = s + 1;
    if (super_parent[s] != p) {
      continue;
    }
    const int merged_columns = columns[s] + columns[p];
    const double new_zeros =
        static_cast<double>(columns[s]) * (columns[s] + rows[p] - rows[s]);
    const double total_zeros = zeros[s] + zeros[p] + new_zeros;
    const double size =
        0.5 * merged_columns * (merged_columns + 1.0) +
        static_cast<double>(merged_columns) * (rows[p] - columns[p]);
    if (new_zeros > 0 && !MayMerge(merged_columns, total_zeros, size)) {
      continue;
    }
    merged_into_previous[p] = 1;
    zeros[s] = total_zeros;
    rows[s] = columns[s] + rows[p];
    columns[s] = merged_columns;
    super_parent[s] = super_parent[p];
  }
  std::vector<int> group(num_fundamental);
  supernodes->first_column.clear();
  supernodes->parent.clear();
  for (int s = 0; s < num_fundamental; ++s) {
    if (!merged_into_previous[s]) {
      supernodes->first_column.push_back(first[s]);
    }
    group[s] = static_cast<int>(supernodes->first_column.size()) - 1;
  }
  supernodes->first_column.push_back(n);
  for (int s = 0; s < num_fundamental; ++s) {
    if (!merged_into_previous[s]) {
      supernodes->parent.push_back(
          super_parent[s] < 0 ? -1 : group[super_parent[s]]);
    }
  }
}

}  // namespace

std::vector<int> ColumnMinimumDegreeOrder(const MatrixGraph &graph) {
  namespace colamd = Eigen::internal::Colamd;
  const int n = graph.size();
  const int entries = n + static_cast<int>(graph.neighbour.size());
  // A by column (A's pattern is symmetric), with COLAMD's working space.
  std::vector<int> start(n + 1), row(colamd::recommended(entries, n, n));
  int entry = 0;
  for (int u = 0; u < n; ++u) {
    start[u] = entry;
    ForRowOfA(graph, u, [&](int v) { row[entry++] = v; });
  }
  start[n] = entry;
  double knobs[colamd::NKnobs];
  int stats[colamd::NStats];
  colamd::set_defaults(knobs);
  if (!colamd::compute_ordering(n, n, static_cast<int>(row.size()), row.data(),
                                start.data(), knobs, stats)) {
    return {};
  }
  start.resize(n);  // start[column] = unknown.
  return start;
}

bool ComputeSupernodes(const MatrixGraph &graph, const std::vector<int> &order,
                       int64_t max_entries, Supernodes *supernodes) {
  std::vector<int> column_of;
  const std::vector<int> parent =
      PostorderedTree(graph, order, &supernodes->order, &column_of);
  const std::vector<int64_t> count =
      ColumnCounts(graph, supernodes->order, column_of, parent);
  supernodes->exact_entries = 0;
  for (const int64_t c : count) {
    supernodes->exact_entries += c;
  }
  if (supernodes->exact_entries > max_entries) {
    return false;
  }
  Amalgamate(parent, count, FundamentalSupernodes(parent, count), supernodes);
  return true;
}

}  // namespace draco
