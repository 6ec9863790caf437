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
// Sparse Cholesky factorisation M = L L^T of the symmetric positive definite
// matrices of the Laplacian texture coordinate coder (normal equations of
// mesh Laplacians), after
//   [George & Liu 1978] A. George, J. W. H. Liu: An automatic nested
//     dissection algorithm for irregular finite element problems. SIAM J.
//     Numer. Anal. 15(5).
//   [Duff & Reid 1983] I. S. Duff, J. K. Reid: The multifrontal solution of
//     indefinite sparse symmetric linear equations. ACM TOMS 9(3).
//   [Gill et al. 1974] P. E. Gill, G. H. Golub, W. Murray, M. A. Saunders:
//     Methods for modifying matrix factorizations. Math. Comp. 28(126).
//
// The fill-reducing order is a nested dissection [George & Liu 1978] of
// the matrix's square root graph (the mesh one-ring graph, where the normal
// matrix couples the unknowns at most two edges apart): coupled components
// are dissected separately, and a coupled subset is cut at the smaller of
// two balanced separators two edges wide, the smallest pair of levels near
// the median of a breadth-first level structure from a pseudo-peripheral
// vertex a, or a band of level sets of d_a - d_b across the subset (b the
// farthest vertex from a), and the separator is thinned. Searching the
// one-ring graph visits a third of the edges of the normal matrix's own
// graph, for the same separators. The dissection tree is the assembly tree
// of a multifrontal factorisation: every tree node is one dense front,
// whose columns are factorised in place in the factor's storage with
// Eigen's blocked dense kernels. Eigen's own sparse Cholesky (simplicial,
// AMD order) measured 3-4 times slower on the 300k-vertex benchmark mesh,
// mostly in the ordering and in its column-by-column numeric phase.
//
// Deterministic: the same pattern, coordinates and values give the same
// factor and solutions on one build and, with the portable dense kernels
// (the default), on every CPU of the build's architecture. Eigen would size
// its matrix kernels' blocks from the cache sizes it reads from the CPU,
// which changes the rounding (an L1 of 16 KB or 48 KB instead of 32 KB gave
// other bits), so the dense kernels use fixed sizes (dense_front.h) and
// Solve() only Eigen's vector kernels. Not bit-identical across compilers.
#ifndef DRACO_EXT_LINALG_SPARSE_CHOLESKY_H_
#define DRACO_EXT_LINALG_SPARSE_CHOLESKY_H_

#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

#include <Eigen/Core>

#include "draco_ext/linalg/dense_front.h"
#include "draco_ext/linalg/matrix_graph.h"

namespace draco {

// A symmetric sparse matrix, both triangles, compressed by column.
struct SymmetricMatrix {
  int size = 0;
  std::vector<int> column_start;  // size + 1 entries.
  std::vector<int> row;
  std::vector<double> value;
};

// Solves symmetric positive definite systems M X = B whose pattern is the
// square of a graph: Analyze() once per pattern, Factorize() per matrix of
// that pattern, then Solve() and AddToDiagonal() any number of times.
// Results are deterministic (file comment). Weak where: no pivoting, so an
// indefinite or nearly singular M fails Factorize() or solves inaccurately;
// the order is tuned for mesh-like graphs of low degree, and dense or
// expander-like graphs give large fronts (bounded only by Analyze()'s
// |max_entries|); one object must not be used from two threads at once.
class SparseCholesky {
 public:
  // Orders the unknowns and computes the structure of the factor for
  // matrices whose off-diagonal entry (u, v) may be non-zero only when u and
  // v are at most two edges apart in |graph| (symmetric): the pattern of
  // the normal matrix A^T A when |graph| is the pattern of a square A, as
  // for a mesh Laplacian and its one-ring graph. False, before allocating
  // the factor, when it would have more than |max_entries| entries. Large
  // graphs are dissected on two threads, to the same order as on one.
  bool Analyze(const MatrixGraph &graph, int64_t max_entries);
  // Analyze(), running |work| meanwhile on a second thread when allowed
  // (else first), e.g. to build the matrix during the ordering.
  bool Analyze(const MatrixGraph &graph, int64_t max_entries,
               const std::function<void()> &work);

  // Factorises |matrix| (pattern as analysed). False when the matrix is not
  // numerically positive definite or has non-finite entries. Large
  // factorisations share the subtrees and nodes of the dissection tree
  // between two threads as they become ready; every front's arithmetic is
  // the same as on one thread, so the factor is bit-identical whatever the
  // thread count and timing.
  bool Factorize(const SymmetricMatrix &matrix);

  // At most 2 (the default) or 1 thread for Analyze(), Factorize() and
  // Solve(); their results do not depend on it.
  void set_max_threads(int max_threads) { max_threads_ = max_threads; }
  // The dense kernels of Factorize(), portable by default
  // (dense_front.h).
  void set_dense_kernels(DenseKernels kernels) { dense_kernels_ = kernels; }

  // Replaces the factor of M by the factor of M + delta e_u e_u^T (rank-one
  // update, delta >= 0), touching only the columns on the elimination path
  // of unknown |unknown|.
  void AddToDiagonal(int unknown, double delta);

  // Solves M X = B in place; |rhs| has one row per unknown. Large systems
  // use two threads, with the same arithmetic as on one.
  void Solve(Eigen::Ref<Eigen::MatrixXd> rhs) const;

  int num_unknowns() const { return static_cast<int>(column_of_.size()); }
  // Entries of the factor, dense fronts included.
  int64_t factor_size() const { return num_panel_entries_; }
  // Floating point operations of Factorize().
  double factor_flops() const {
    double flops = 0;
    for (const Node &node : nodes_) {
      flops += NodeFlops(node);
    }
    return flops;
  }

 private:
  // One node of the dissection tree: a dense front whose first |num_columns|
  // rows are its own consecutive columns and whose other rows are the
  // columns |update_rows| of ancestor nodes it updates.
  struct Node {
    int first_column = 0;
    int num_columns = 0;
    std::vector<int> update_rows;  // Ascending.
    std::vector<int> children;
    int64_t panel_offset = 0;  // Into panels_: front size x num_columns.
    int front_size() const {
      return num_columns + static_cast<int>(update_rows.size());
    }
  };

  // Factorize()'s units of work for two threads: the nodes first_node ..
  // last_node (a whole subtree, or one node above the subtrees); |parent|
  // is the task that contains the parent of last_node, or -1.
  struct FactorTask {
    int first_node;
    int last_node;
    int parent;
  };

  class Dissection;

  static double NodeFlops(const Node &node) {
    const double k = node.num_columns, r = node.update_rows.size();
    return k * k * k / 3 + k * k * r + k * r * r;
  }

  // False when a child updates a column of a sibling subtree.
  bool ComputeUpdateRows(const MatrixGraph &graph);
  // Chooses solve_roots_: from the roots down, every subtree that still
  // fits into half of the factor's entries (none for small factors).
  void ChooseSolveSubtrees();
  // Chooses factor_tasks_ (none when Factorize() stays on one thread).
  void ChooseFactorTasks();
  // Runs |run_task| (bool(const FactorTask &, std::vector<int> *front_index,
  // std::vector<int> *columns, const ForkJoin *)) on every factor task,
  // children's tasks first, on two threads, which also share the halves of
  // large fronts (FactorDenseFront()); false when one fails.
  template <typename RunTask>
  bool RunFactorTasks(const RunTask &run_task) const;
  class TaskQueue;
  // True when a second thread may be used: allowed by set_max_threads()
  // and by SecondThreadAvailable() (SetMaxThreads(), cores, WebAssembly).
  bool MayUseSecondThread() const;
  // Runs |side| on a second thread and |other| on this one when
  // MayUseSecondThread(), else |side| then |other| here (SecondThread).
  template <typename Side, typename Other>
  void RunBoth(const Side &side, const Other &other) const;
  class SolveProgress;
  // Solve()'s passes over the nodes outside solve_roots_' subtrees; the
  // forward pass adds each node's rows of |outside| before solving it.
  void ForwardOtherNodes(Eigen::MatrixXd *y, const Eigen::MatrixXd &outside,
                         SolveProgress *progress) const;
  void BackwardOtherNodes(Eigen::MatrixXd *y, SolveProgress *progress) const;
  int num_nodes() const { return static_cast<int>(nodes_.size()); }
  // Forward substitution of one node; with |outside|, updates of rows from
  // |outside_begin| on go to outside->row(row) instead of y->row(row).
  void ForwardNode(const Node &node, Eigen::MatrixXd *y,
                   Eigen::MatrixXd *outside, int outside_begin,
                   Eigen::MatrixXd *gathered) const;
  void BackwardNode(const Node &node, Eigen::MatrixXd *y,
                    Eigen::MatrixXd *gathered) const;
  // Factorises node |n| with the workspace |front_index| (-1 or stale
  // entries, one per unknown) and |columns|. |updates| holds every node's
  // update matrix until its parent has assembled it. |fork_join| (or null)
  // may run the halves of a large front's dense work at once.
  bool FactorizeNode(const SymmetricMatrix &matrix, int n,
                     std::vector<int> *front_index, std::vector<int> *columns,
                     std::vector<std::vector<double>> *updates,
                     const ForkJoin *fork_join);
  // The front's global column numbers, own columns first.
  void FrontColumns(const Node &node, std::vector<int> *columns) const;
  Eigen::Map<Eigen::MatrixXd> Panel(const Node &node);
  Eigen::Map<const Eigen::MatrixXd> Panel(const Node &node) const;
  // Updates column |local| of |node| and the entries of |w| it touches.
  void UpdateColumn(Node &node, int local, std::vector<double> *w);

  std::vector<Node> nodes_;        // Children before parents.
  std::vector<int> parent_;        // Node -> parent node, -1 for roots.
  std::vector<int> subtree_size_;  // Nodes in the subtree of a node.
  std::vector<int> column_of_;     // Unknown -> column.
  std::vector<int> unknown_of_;    // Column -> unknown.
  std::vector<int> node_of_column_;
  std::unique_ptr<double[]> panels_;
  int64_t num_panel_entries_ = 0;
  int max_threads_ = 2;
  DenseKernels dense_kernels_ = DenseKernels::kPortable;
  // Solve()'s second thread: the disjoint subtrees rooted at solve_roots_
  // (ascending), about half of the factor; in_solve_side_[node] whether a
  // node belongs to one of them.
  std::vector<int> solve_roots_;
  std::vector<char> in_solve_side_;
  // In node order, so children's tasks come first.
  std::vector<FactorTask> factor_tasks_;
};

}  // namespace draco

#endif  // DRACO_EXT_LINALG_SPARSE_CHOLESKY_H_
