#pragma once
// The 2D distortion densities beyond symmetric Dirichlet, each a function
// f(s, g) of s = |J|_F^2 and g = det J (see invariant_density.h). Formulas,
// lower bounds and sources are in docs/energies.md.
#include "energies/invariant_density.h"

namespace akvf {

// ARAP [Liu et al. 2008]: |J - R(J)|_F^2 with R the closest rotation. In 2D
// sigma_1 + sigma_2 = sqrt(s + 2g) for g > 0, so f = s - 2 sqrt(s + 2g) + 2.
class Arap2 final : public InvariantDensity2 {
 public:
  std::string name() const override { return "arap"; }
  double lower_bound() const override { return 0.0; }

 protected:
  InvariantDerivatives derivatives(double s, double g) const override;
};

// Conformal / MIPS [Hormann and Greiner 2000]: |J|_F^2 / det J = s / g.
class Mips2 final : public InvariantDensity2 {
 public:
  std::string name() const override { return "mips"; }
  double lower_bound() const override { return 2.0; }

 protected:
  InvariantDerivatives derivatives(double s, double g) const override;
};

// Exponential symmetric Dirichlet (SLIM's convention, Rabinovich et al.
// 2017): exp(k (|J|^2 + |J^-1|^2)) with exponent k > 0.
class ExpSymmetricDirichlet2 final : public InvariantDensity2 {
 public:
  explicit ExpSymmetricDirichlet2(double exponent);
  std::string name() const override { return "exp-symmetric-dirichlet"; }
  double lower_bound() const override;

 protected:
  InvariantDerivatives derivatives(double s, double g) const override;

 private:
  double exponent_;
};

// AMIPS [Fu, Liu and Guo 2015] in 2D with equal weights on the conformal
// and area terms: exp(k (s / (4g) + (g + 1/g) / 4)), minimum exp(k) at
// rotations.
class Amips2 final : public InvariantDensity2 {
 public:
  explicit Amips2(double exponent);
  std::string name() const override { return "amips"; }
  double lower_bound() const override;

 protected:
  InvariantDerivatives derivatives(double s, double g) const override;

 private:
  double exponent_;
};

}  // namespace akvf
