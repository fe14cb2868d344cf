#pragma once
// Symmetric sparse matrices on the interleaved vertex dofs (D per vertex:
// x_0, y_0[, z_0], x_1, ...) of a mesh whose elements have N vertices,
// assembled from one symmetric (D N) x (D N) local matrix per element (dof
// order: corner 0's D coordinates, then corner 1's, ...). The Killing
// operator (triangles, Eq. 5; tets, Eq. 9-10), the projected Newton Hessian,
// the SLIM proxy and the Laplacian all have this form.
//
// The sparsity pattern (the upper triangle of D x D blocks for each vertex
// and edge) is built once from the elements, through the vertex graph (framework/mesh/vertex_graph.h: each
// vertex's sorted neighbors, found by counting: no triplet per local slot,
// which took 3.4 GB at 10 M triangles), and may be shared by another
// matrix on the same elements (with_pattern_of; taking_storage_of, with the
// values' storage too: akvf-newton's Newton phase takes AKVF's at the switch
// instead of building or copying it). Each local matrix's upper triangle,
// D N (D N + 1) / 2 numbers, goes to the global upper triangle, each number
// added to its nonzero in increasing element order, so the result is
// bitwise identical for any thread count.
//
// Threads. The nonzeros are split into as many contiguous ranges as the
// arena has threads, each with about the same number of additions; a
// thread visits, in increasing order, the elements with a slot in its
// range, computes their local matrices and adds the slots that land there.
// An element whose vertices' columns fall in two ranges is computed twice,
// by two threads (a few along the ranges' borders when the vertex order
// follows the surface; up to N times in a random order). No buffer of
// local matrices is kept: each is used where it is computed.
#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <functional>
#include <memory>
#include <vector>

namespace akvf {

struct UpperVertexGraph;

// The upper triangle of D x D blocks on `graph` (framework/mesh/vertex_graph.h),
// values zero: the pattern of every ElementMatrix<D, N> on the elements the
// graph was built from (their symbolic analysis needs no values).
template <int D>
Eigen::SparseMatrix<double> block_upper_pattern(const UpperVertexGraph& graph);

template <int D, int N>
class ElementMatrix {
 public:
  static constexpr int kLocalSize = D * N;
  using Local = Eigen::Matrix<double, kLocalSize, kLocalSize>;
  // Fills the local matrix of element e (only its upper triangle is read).
  using LocalFunction = std::function<void(int e, Local* local)>;
  // Fills the local matrices of `count` (1 to kBatch) elements, elements[i]'s
  // in locals[i]: for local matrices whose computation is one long chain of
  // dependent operations (a closed-form eigensystem's square roots and
  // divisions), computing a batch's chains one after another lets the
  // processor overlap them.
  static constexpr int kBatch = 8;
  using LocalBatchFunction = std::function<void(const int* elements, int count, Local* locals)>;

  //   elements  #E by N vertex indices
  ElementMatrix(const Eigen::MatrixXi& elements, int num_vertices);
  // A matrix on the same elements as `other`, sharing its pattern (values
  // zero; nothing is rebuilt).
  static ElementMatrix with_pattern_of(const ElementMatrix& other);
  // The same without a new allocation: takes `donor`'s storage (values
  // zeroed), leaving it without values. For a matrix whose owner is about to
  // be released (akvf-newton's switch, where a copy cost 0.9 GB at 10 M
  // triangles).
  static ElementMatrix taking_storage_of(ElementMatrix* donor);
  // Eigen 3.4's SparseMatrix has no move constructor (its "move" copies), so
  // these swap the storage.
  ElementMatrix(ElementMatrix&& other) noexcept;
  ElementMatrix& operator=(ElementMatrix&& other) noexcept;
  ElementMatrix(const ElementMatrix&) = default;
  ElementMatrix& operator=(const ElementMatrix&) = default;
  // Whether `other` is on the same sparsity pattern (shared, or of the same
  // size and number of nonzeros); true for a donor of taking_storage_of.
  bool same_pattern(const ElementMatrix& other) const;

  // On the calling arena's threads.
  void assemble(const LocalFunction& local);
  // The same, the local matrices computed in batches (each thread's elements
  // in increasing order, as above; the sums are the same bits).
  void assemble_batches(const LocalBatchFunction& locals);
  // upper() += shift I (Tikhonov regularization).
  void add_to_diagonal(double shift);
  // upper() *= factor (mean_diagonal() follows).
  void scale(double factor);
  // upper() += diag(values), one value per dof.
  void add_to_diagonal(const Eigen::VectorXd& values);

  // Upper triangle, column-major compressed, D|V| by D|V|.
  const Eigen::SparseMatrix<double>& upper() const { return upper_; }
  // Mean of the diagonal of the last assembled matrix (before any shift).
  double mean_diagonal() const { return mean_diagonal_; }
  // The full symmetric matrix (for tests and small problems).
  Eigen::SparseMatrix<double> full() const;

 private:
  static constexpr int kSlots = kLocalSize * (kLocalSize + 1) / 2;
  // What depends on the elements only: the nonzero each local slot adds to
  // (element e's slots, in the loop order of assemble(), are
  // entries[kSlots e .. kSlots (e + 1))).
  struct Pattern {
    int num_elements = 0;
    int nonzeros = 0;
    std::vector<int> entries;            // #E x kSlots nonzero indices
    std::vector<long> additions_before;  // per vertex + 1: the slots adding to earlier vertices' columns
    std::vector<int> diagonal_entries;   // nonzero index of each (i, i)
  };
  // The nonzeros split into contiguous ranges, one per thread of the arena:
  // part p owns [bounds[p], bounds[p + 1]) and visits, in increasing order,
  // the elements with a slot there, items[offsets[p] .. offsets[p + 1]):
  // e where all of e's slots are in the range, ~e where only some are.
  struct Parts {
    std::vector<int> bounds;
    std::vector<int> offsets;
    std::vector<int> items;
  };
  // assemble()'s loop, the local matrices computed `Batch` at a time by
  // compute(elements, count, locals).
  template <int Batch, class ComputeLocals>
  void assemble_parts(const ComputeLocals& compute);
  // On a shared pattern, without values (the factories above fill upper_).
  ElementMatrix(std::shared_ptr<const Pattern> pattern, std::shared_ptr<const Parts> parts);
  // `count` parts of about the same number of additions; outer: upper_'s column starts.
  static std::shared_ptr<const Parts> split_nonzeros(const Pattern& pattern, const int* outer, int count);

  std::shared_ptr<const Pattern> pattern_;
  std::shared_ptr<const Parts> parts_;  // for the arena's number of threads at the last assemble()
  Eigen::SparseMatrix<double> upper_;
  double mean_diagonal_ = 0;
};

using ElementMatrix2D = ElementMatrix<2, 3>;  // triangles in the plane
using ElementMatrix3D = ElementMatrix<3, 4>;  // tetrahedra in space

}  // namespace akvf
