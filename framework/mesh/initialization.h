#pragma once
// Initial maps for parameterization (Algorithm 1, first two lines): the Tutte
// embedding and the flap optimization of §5.4.
#include <Eigen/Core>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "akvf/mesh.h"

namespace akvf {

enum class TutteWeights { kUniform, kCotangent };

// Solves A X = B for a sparse symmetric A (both triangles stored), whose
// row i is the mesh's vertex vertices[i] (so that a solver may order A by an
// ordering of the mesh's vertex graph); returns false when it cannot (A not
// positive definite), and the Tutte solve then falls back to Eigen's
// simplicial L D L^T, the framework's own solver. The library passes
// CHOLMOD's supernodal Cholesky on large meshes (akvf/parameterization.cpp
// says from where).
using SpdSolver = std::function<bool(const Eigen::SparseMatrix<double>& A, const Eigen::MatrixXd& B,
                                     const std::vector<int>& vertices, Eigen::MatrixXd* X)>;

// The Laplacian's off-diagonal weights w_ij > 0 (uniform) or
// (cot a + cot b) / 2 (the 3D corners opposite edge ij), one triplet per
// face and direction (summed by setFromTriplets): L = D - W.
std::vector<Eigen::Triplet<double>> laplacian_edge_weights(const TriMesh& mesh, TutteWeights weights);

// Each vertex's sum of corner angles at rest: 2 pi less its angle defect
// inside, pi less the boundary's turning on the boundary.
Eigen::VectorXd vertex_angle_sums(const TriMesh& mesh);

// The system L_II X_I = S_I - L_IB X_B for the vertices off a boundary
// loop (L of laplacian_edge_weights), assembled once for solves with
// several right-hand sides. By `solver` (which factors at each solve), else
// (or where it declines) Eigen's L D L^T, factored at the first solve and
// kept.
class InteriorLaplacian {
 public:
  InteriorLaplacian(const TriMesh& mesh, const std::vector<int>& loop, TutteWeights weights, SpdSolver solver);

  // Writes the rows of *X off the loop, its loop rows given (S = `source`,
  // #V rows, or empty for 0); false when the system is singular or the
  // result is not finite.
  bool solve(const Eigen::MatrixXd& source, Eigen::MatrixXd* X);

  // (L X)_i = sum_j w_ij (X_i - X_j) at every vertex.
  Eigen::MatrixXd apply(const Eigen::MatrixXd& X) const;

 private:
  std::vector<Eigen::Triplet<double>> weights_;
  std::vector<int> interior_index_;  // -1 on the loop
  std::vector<int> interior_vertex_;
  Eigen::SparseMatrix<double> interior_;  // L_II
  SpdSolver solver_;
  std::unique_ptr<Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>>> ldlt_;
};

// Tutte embedding: the boundary loop on a circle of the mesh's area, spaced by
// 3D arc length, and each interior vertex at the weighted average of its
// neighbours. With cotangent weights (which may be negative) the map can fold;
// then the uniform map is returned instead and a warning is added.
//   boundary_loop  ordered with the mesh to its left (counter-clockwise result)
//   solver         for the interior vertices' system; empty: Eigen's L D L^T
//   returns UV     #V by 2
Eigen::MatrixXd tutte_embedding(const TriMesh& mesh, const std::vector<int>& boundary_loop, TutteWeights weights,
                                Warnings* warnings, const SpdSolver& solver = {});

// §5.4: moves every flap vertex (a boundary vertex in a single triangle) to
// the optimal position for an isometric energy given its two neighbours:
// x0 = (1 - beta) x1 + beta x2 + gamma / |x2 - x1| (x2 - x1)^perp.
// Returns the number of vertices moved.
int optimize_flaps(const TriMesh& mesh, Eigen::MatrixXd* UV);

// Triangles with det(J) <= 0 under the map UV (#V by 2).
int count_inverted_triangles(const Eigen::MatrixXi& F, const Eigen::MatrixXd& UV);

}  // namespace akvf
