#pragma once
// Maximal flip-free step of an element (§5.3, after Smith & Schaefer 2015):
// along x + t d, det J(t) = det(Ds + t Dd) is a quadratic (triangles) or a
// cubic (tets) in t, positive at t = 0, and the element inverts at its
// smallest positive root.
#include <Eigen/Core>

namespace akvf {

// Smallest t > 0 with a t^2 + b t + c = 0, or +infinity if there is none.
// Requires c > 0. The linear (a = 0) and constant (a = b = 0) cases are
// exact; otherwise the roots are q / a and c / q with
// q = -(b + sign(b) sqrt(b^2 - 4ac)) / 2, which stays accurate when a is tiny
// (the textbook form loses the small root to cancellation, and the common
// "c / q only" shortcut divides by the wrong coefficient).
double smallest_positive_root(double a, double b, double c);

// The positive roots of a t^2 + b t + c, ascending, in roots[0..n); returns
// n (0 to 2). The same stable formula, with no condition on c (boundary
// contact, boundary_contact.h, needs every root, not only the smallest).
int positive_roots(double a, double b, double c, double roots[2]);

// The step at which the triangle with edge matrices Ds = [e1 e2] (current)
// and Dd (direction), column-major 2x2 stored as {m00, m10, m01, m11},
// becomes degenerate.
double triangle_flip_step(const double Ds[4], const double Dd[4]);

// Smallest t > 0 with a3 t^3 + a2 t^2 + a1 t + a0 = 0, or +infinity.
// Requires a0 > 0. With a3 = 0 it is the quadratic case above (exact); else
// the critical points split [0, inf) into monotone pieces and the first
// piece whose ends change sign is bisected to full precision, which stays
// reliable when a3 is tiny or roots are close.
double smallest_positive_root_cubic(double a3, double a2, double a1, double a0);

// The step at which the tet with edge matrices Ds = [e1 e2 e3] (current) and
// Dd (direction) becomes degenerate: the smallest positive root of
//   det(Ds + t Dd) = det Ds + t tr(adj(Ds) Dd) + t^2 tr(adj(Dd) Ds) + t^3 det Dd.
double tet_flip_step(const Eigen::Matrix3d& Ds, const Eigen::Matrix3d& Dd);

}  // namespace akvf
