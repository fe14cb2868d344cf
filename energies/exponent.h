#pragma once
// What the exponential energies (exp(k u): exp-symmetric-dirichlet, amips)
// share in 2D and 3D: the check of the exponent k and the derivatives of
// exp(k u) from those of u.
#include <cmath>

#include "akvf/error.h"
#include "energies/invariant_density_2d.h"
#include "energies/invariant_density_3d.h"

namespace akvf {

inline double checked_exponent(double k) {
  if (!(k > 0)) throw OptionsError("energy exponent must be > 0");
  return k;
}

// Derivatives of exp(k u) in (s, g) from those of u.
inline InvariantDerivatives2D exponentiate(const InvariantDerivatives2D& u, double k) {
  InvariantDerivatives2D d;
  d.f = std::exp(k * u.f);
  d.f_s = k * d.f * u.f_s;
  d.f_g = k * d.f * u.f_g;
  d.f_ss = k * d.f * (u.f_ss + k * u.f_s * u.f_s);
  d.f_sg = k * d.f * (u.f_sg + k * u.f_s * u.f_g);
  d.f_gg = k * d.f * (u.f_gg + k * u.f_g * u.f_g);
  return d;
}

// Derivatives of exp(k u) in (s, c, g) from those of u.
inline InvariantDerivatives3D exponentiate(const InvariantDerivatives3D& u, double k) {
  InvariantDerivatives3D d;
  d.f = std::exp(k * u.f);
  const double kf = k * d.f;
  d.f_s = kf * u.f_s;
  d.f_c = kf * u.f_c;
  d.f_g = kf * u.f_g;
  d.f_ss = kf * (u.f_ss + k * u.f_s * u.f_s);
  d.f_sc = kf * (u.f_sc + k * u.f_s * u.f_c);
  d.f_sg = kf * (u.f_sg + k * u.f_s * u.f_g);
  d.f_cc = kf * (u.f_cc + k * u.f_c * u.f_c);
  d.f_cg = kf * (u.f_cg + k * u.f_c * u.f_g);
  d.f_gg = kf * (u.f_gg + k * u.f_g * u.f_g);
  return d;
}

}  // namespace akvf
