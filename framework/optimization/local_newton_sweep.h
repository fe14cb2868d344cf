#pragma once
// Local Newton sweeps: a nonlinear Gauss-Seidel pass over the vertices that
// carry the most of the gradient, each moved by its own projected Newton
// step with the others held.
//
// Why: far from the minimum a global step of AKVF is set by the flip-free
// bound (§5.3), and the elements that set it are a few badly shaped ones the
// smooth direction K^-1 g drives toward a collapse. A vertex alone sees
// only its own elements: its energy E_v(y) = sum over them of w_e psi(J_e),
// a barrier in y, is minimized along its projected Newton step
// -H_v^-1 g_v (H_v its D x D block of the projected Hessian), a
// local correction of exactly the kind the global operator smooths away.
// Moving a vertex v changes only the terms of E_v, so every accepted local
// step lowers E by what it lowers E_v, and det J_e of each of v's elements
// is linear along it (one column of the edge matrix, or a rank-one change of
// all of them, moves), so its flip-free bound is exact.
//
// Vertices are taken one colour class at a time (no two vertices of a class
// share an element), so the vertices of a class move independently, on any
// number of threads, with the same bits.
#include <Eigen/Core>
#include <vector>

#include "akvf/mesh_objective.h"

namespace akvf {

template <int D>
class LocalNewtonSweep {
 public:
  // The vertex-to-element incidence and the colouring of the objective's
  // mesh (the objective must outlive the sweep). `fixed`: vertices never
  // moved (empty: none), e.g. a chart's boundary, whose moves would change
  // a boundary barrier the sweep does not see.
  explicit LocalNewtonSweep(const MeshObjective<D>& objective, const std::vector<int>& fixed = {});

  // One pass over the vertices v with |g_v|^2 > gradient_share * |g|^2 / #V
  // (g the gradient at x): each is moved by its projected Newton step where
  // the step is within 0.8 of its flip-free bound (a step the bound would
  // cut has its model's minimizer past a collapse: the vertex stays),
  // halved until E_v decreases by at least 1e-4 of the step's first-order
  // decrease (at most 20 times; else it stays). Returns the number of
  // vertices moved.
  int sweep(const Eigen::VectorXd& gradient, double gradient_share, Eigen::VectorXd* x) const;

  int colours() const { return static_cast<int>(colour_start_.size()) - 1; }

 private:
  bool move_vertex(int v, Eigen::VectorXd* x) const;

  const MeshObjective<D>& objective_;
  std::vector<int> incidence_start_, incidence_;  // vertex v's (element, corner) pairs
  std::vector<int> colour_start_, by_colour_;     // movable vertices of colour c: by_colour_[colour_start_[c] ..)
};

}  // namespace akvf
