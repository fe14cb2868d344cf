#pragma once
// A distortion density written once, as a template over the scalar type,
// and differentiated automatically: the gradient with Ceres' dual numbers
// (Jet), the Hessian with Eigen's AutoDiffScalar nested in itself (forward
// over forward mode),
// the PSD projection from DistortionDensity, and dD/dsigma for SLIM from the
// same function at J = diag(sigma). A new energy is then one small functor:
//
//   struct Conformal {  // |J|_F^2 / (2 det J): 1 for every conformal map
//     template <class T> T operator()(const Eigen::Matrix<T, 2, 2>& J) const {
//       return J.squaredNorm() / (2 * J.determinant());
//     }
//   };
//   akvf::register_autodiff_energy<2>("conformal", "...", 1.0, Conformal{});
//
// Use exp, log, sqrt, pow(x, number) and the arithmetic operators: the
// functor is instantiated with double, ceres::Jet and Eigen::AutoDiffScalar.
// The functor is called only for det J > 0 (value() returns +infinity
// otherwise, so line searches back off as for the built-in energies). It must
// be rotation-invariant, D(R J) = D(J) = D(J R) for rotations R, as every
// distortion energy is; SLIM relies on that when it asks for dD/dsigma.
// The hand-written densities stay: they are faster.
#include <ceres/jet.h>

#include <Eigen/Core>
#include <Eigen/LU>
#include <limits>
#include <string>
#include <unsupported/Eigen/AutoDiff>
#include <utility>

#include "akvf/distortion_density.h"

// Eigen's pow(AutoDiffScalar, exponent) takes the exponent as the scalar of
// the derivatives, which for nested AutoDiffScalars is itself an
// AutoDiffScalar, so pow(x, 2.0 / 3) does not compile there. This overload
// takes a plain exponent at the nested level (found by argument-dependent
// lookup, preferred for a double or int exponent): d x^y = y x^(y-1) dx.
namespace Eigen {
template <typename InnerDerivatives, int N>
inline AutoDiffScalar<Matrix<AutoDiffScalar<InnerDerivatives>, N, 1>> pow(
    const AutoDiffScalar<Matrix<AutoDiffScalar<InnerDerivatives>, N, 1>>& x, double y) {
  using Inner = AutoDiffScalar<InnerDerivatives>;
  const Inner value = pow(x.value(), y);
  const Inner slope = y * pow(x.value(), y - 1);
  Matrix<Inner, N, 1> derivatives = x.derivatives();
  for (int i = 0; i < N; ++i) derivatives[i] = derivatives[i] * slope;
  return AutoDiffScalar<Matrix<Inner, N, 1>>(value, derivatives);
}
}  // namespace Eigen

namespace akvf {

template <int Dim, class Functor>
class AutodiffDensity final : public DistortionDensity<Dim>, public SingularValueDerivative<Dim> {
 public:
  static constexpr int kEntries = Dim * Dim;
  using Base = DistortionDensity<Dim>;
  using typename Base::Hessian;
  using typename Base::Matrix;
  using Vector = typename SingularValueDerivative<Dim>::Vector;

  AutodiffDensity(std::string name, double lower_bound, Functor functor)
      : name_(std::move(name)), lower_bound_(lower_bound), functor_(std::move(functor)) {}

  std::string name() const override { return name_; }
  double lower_bound() const override { return lower_bound_; }

  double value(const Matrix& J) const override {
    if (!(J.determinant() > 0)) return std::numeric_limits<double>::infinity();
    return functor_(J);
  }

  double value_and_gradient(const Matrix& J, Matrix* dD_dJ) const override {
    if (!(J.determinant() > 0)) return std::numeric_limits<double>::infinity();
    using Dual = ceres::Jet<double, kEntries>;
    Eigen::Matrix<Dual, Dim, Dim> X;
    for (int k = 0; k < kEntries; ++k) X(k % Dim, k / Dim) = Dual(J(k % Dim, k / Dim), k);  // vec(J), column-major
    const Dual d = functor_(X);
    for (int k = 0; k < kEntries; ++k) (*dD_dJ)(k % Dim, k / Dim) = d.v[k];
    // The value from the double evaluation, as value() gives it: a dual
    // number's value may differ in the last bit, and the line search and the
    // trace must see the same energy.
    return functor_(J);
  }

  Hessian hessian(const Matrix& J) const override {
    // Forward over forward mode with Eigen's AutoDiffScalar, which nests
    // (Ceres' Jet does not build from a plain double once nested, and Eigen's
    // reductions need that): d.derivatives()[a].derivatives()[b] is
    // d2D / dJ_a dJ_b.
    using Inner = Eigen::AutoDiffScalar<Eigen::Matrix<double, kEntries, 1>>;
    using Outer = Eigen::AutoDiffScalar<Eigen::Matrix<Inner, kEntries, 1>>;
    Eigen::Matrix<Outer, Dim, Dim> X;
    for (int k = 0; k < kEntries; ++k) {
      const Inner entry(J(k % Dim, k / Dim), kEntries, k);
      Eigen::Matrix<Inner, kEntries, 1> seed;
      for (int i = 0; i < kEntries; ++i)
        seed[i] = Inner(i == k ? 1.0 : 0.0, Eigen::Matrix<double, kEntries, 1>::Zero());
      X(k % Dim, k / Dim) = Outer(entry, seed);
    }
    const Outer d = functor_(X);
    Hessian H;
    for (int a = 0; a < kEntries; ++a)
      for (int b = 0; b < kEntries; ++b) H(a, b) = d.derivatives()[a].derivatives()[b];
    return 0.5 * (H + H.transpose());  // exact already; removes rounding asymmetry
  }

  Vector singular_value_gradient(const Vector& sigma) const override {
    using Dual = ceres::Jet<double, Dim>;
    Eigen::Matrix<Dual, Dim, Dim> X = Eigen::Matrix<Dual, Dim, Dim>::Constant(Dual(0.0));
    for (int i = 0; i < Dim; ++i) X(i, i) = Dual(sigma[i], i);
    const Dual d = functor_(X);
    return d.v;
  }

 private:
  std::string name_;
  double lower_bound_;
  Functor functor_;
};

}  // namespace akvf
