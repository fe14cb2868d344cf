#pragma once
// Maximal flip-free step of a triangle (§5.3, after Smith & Schaefer 2015):
// along x + t d, det J(t) = det(Ds + t Dd) = a t^2 + b t + c with
// c = det Ds > 0, and the element inverts at the smallest positive root.
namespace akvf {

// Smallest t > 0 with a t^2 + b t + c = 0, or +infinity if there is none.
// Requires c > 0. The linear (a = 0) and constant (a = b = 0) cases are
// exact; otherwise the roots are q / a and c / q with
// q = -(b + sign(b) sqrt(b^2 - 4ac)) / 2, which stays accurate when a is tiny
// (the textbook form loses the small root to cancellation, and the common
// "c / q only" shortcut divides by the wrong coefficient).
double smallest_positive_root(double a, double b, double c);

// The step at which the triangle with edge matrices Ds = [e1 e2] (current)
// and Dd (direction), column-major 2x2 stored as {m00, m10, m01, m11},
// becomes degenerate.
double triangle_flip_step(const double Ds[4], const double Dd[4]);

}  // namespace akvf
