#pragma once
// The shared finite-difference checker for distortion densities: at random
// non-inverted J (well conditioned and near-degenerate), the gradient matches
// central differences of the value and the Hessian matches central
// differences of the gradient; the projected Hessian is PSD.
#include <doctest/doctest.h>

#include <Eigen/Eigenvalues>
#include <Eigen/SVD>
#include <random>
#include <string>

#include "akvf/distortion_density.h"
#include "preconditioners/newton_preconditioner.h"

namespace akvf::test {

// A random J with det > 0 whose singular values lie in [smallest, largest].
template <int Dim>
Eigen::Matrix<double, Dim, Dim> random_jacobian(std::mt19937& rng, double smallest, double largest) {
  using M = Eigen::Matrix<double, Dim, Dim>;
  std::uniform_real_distribution<double> u(-1, 1), s(std::log(smallest), std::log(largest));
  const Eigen::HouseholderQR<M> qr1(M::NullaryExpr([&](Eigen::Index, Eigen::Index) { return u(rng); }));
  const Eigen::HouseholderQR<M> qr2(M::NullaryExpr([&](Eigen::Index, Eigen::Index) { return u(rng); }));
  M U = qr1.householderQ(), V = qr2.householderQ();
  if (U.determinant() < 0) U.col(0) *= -1;
  if (V.determinant() < 0) V.col(0) *= -1;
  Eigen::Matrix<double, Dim, 1> sigma;
  for (int i = 0; i < Dim; ++i) sigma[i] = std::exp(s(rng));
  return U * sigma.asDiagonal() * V.transpose();
}

template <int Dim>
void check_density_derivatives(const DistortionDensity<Dim>& density, double smallest, double largest, int samples = 50,
                               unsigned seed = 7) {
  using M = Eigen::Matrix<double, Dim, Dim>;
  using H = typename DistortionDensity<Dim>::Hessian;
  constexpr int N = Dim * Dim;
  std::mt19937 rng(seed);
  for (int sample = 0; sample < samples; ++sample) {
    const M J = random_jacobian<Dim>(rng, smallest, largest);
    M grad;
    const double value = density.value_and_gradient(J, &grad);
    REQUIRE(value == doctest::Approx(density.value(J)).epsilon(1e-14));
    const double h = 1e-6 * std::max(1.0, J.norm()) * std::min(1.0, smallest);
    H fd_hessian;
    for (int k = 0; k < N; ++k) {
      M plus = J, minus = J;
      plus.data()[k] += h;
      minus.data()[k] -= h;
      const double fd = (density.value(plus) - density.value(minus)) / (2 * h);
      CHECK(grad.data()[k] == doctest::Approx(fd).epsilon(1e-5).scale(std::abs(value)));
      M grad_plus, grad_minus;
      density.value_and_gradient(plus, &grad_plus);
      density.value_and_gradient(minus, &grad_minus);
      for (int l = 0; l < N; ++l) fd_hessian(l, k) = (grad_plus.data()[l] - grad_minus.data()[l]) / (2 * h);
    }
    const H hessian = density.hessian(J);
    const double scale = std::max(1.0, hessian.norm());
    CHECK((hessian - fd_hessian).norm() <= 1e-5 * scale);
    CHECK((hessian - hessian.transpose()).norm() <= 1e-12 * scale);
    const Eigen::SelfAdjointEigenSolver<H> projected(density.projected_hessian(J));
    CHECK(projected.eigenvalues().minCoeff() >= -1e-10 * scale);
  }
}

// The density's projected and absolute Hessians at J (closed form where the
// density has one) against the eigen-decomposition of its Hessian with the
// eigenvalues clamped at 0 and mirrored, to 1e-10 relative. Returns whether
// the Hessian was indefinite (so the filters had something to do).
template <int Dim>
bool check_filtered_hessians(const DistortionDensity<Dim>& density, const Eigen::Matrix<double, Dim, Dim>& J) {
  using H = typename DistortionDensity<Dim>::Hessian;
  const Eigen::SelfAdjointEigenSolver<H> eig(density.hessian(J));
  const H clamped = eig.eigenvectors() * eig.eigenvalues().cwiseMax(0.0).asDiagonal() * eig.eigenvectors().transpose();
  CHECK((density.projected_hessian(J) - clamped).norm() <= 1e-10 * (1 + clamped.norm()));
  const H mirrored = eig.eigenvectors() * eig.eigenvalues().cwiseAbs().asDiagonal() * eig.eigenvectors().transpose();
  CHECK((density.absolute_hessian(J) - mirrored).norm() <= 1e-10 * (1 + mirrored.norm()));
  return eig.eigenvalues().minCoeff() < 0;
}

// The density's closed-form eigensystem at J (HessianEigensystem): its
// modes orthonormal and sum_i lambda_i vec(M_i) vec(M_i)^T its Hessian, to
// 1e-10 relative.
template <int Dim>
void check_eigensystem(const HessianEigensystem<Dim>& eigensystem, const DistortionDensity<Dim>& density,
                       const Eigen::Matrix<double, Dim, Dim>& J) {
  using H = typename DistortionDensity<Dim>::Hessian;
  const auto pairs = eigensystem.hessian_eigensystem(J);
  H modes;  // vec(M_i) as columns
  for (int i = 0; i < Dim * Dim; ++i)
    modes.col(i) = Eigen::Map<const Eigen::Matrix<double, Dim * Dim, 1>>(pairs.modes[i].data());
  CHECK((modes.transpose() * modes - H::Identity()).norm() <= 1e-12);
  const H hessian = density.hessian(J);
  CHECK((modes * pairs.values.asDiagonal() * modes.transpose() - hessian).norm() <= 1e-10 * (1 + hessian.norm()));
}

// `Density` through DistortionDensity alone, without its closed-form
// eigensystem (HessianEigensystem): projected Newton then assembles
// G^T H G from the filtered element Hessians, the path to compare with.
template <int Dim, class Density>
class HessiansOnly : public DistortionDensity<Dim> {
 public:
  using typename DistortionDensity<Dim>::Matrix;
  using typename DistortionDensity<Dim>::Hessian;
  std::string name() const override { return density_.name(); }
  double lower_bound() const override { return density_.lower_bound(); }
  double value(const Matrix& J) const override { return density_.value(J); }
  double value_and_gradient(const Matrix& J, Matrix* dD_dJ) const override {
    return density_.value_and_gradient(J, dD_dJ);
  }
  Hessian hessian(const Matrix& J) const override { return density_.hessian(J); }
  Hessian projected_hessian(const Matrix& J) const override { return density_.projected_hessian(J); }
  Hessian absolute_hessian(const Matrix& J) const override { return density_.absolute_hessian(J); }
  double collapse_barrier_onset() const override { return density_.collapse_barrier_onset(); }

 private:
  Density density_;
};

// The same, claiming no collapse barrier onset: projected Newton then adds
// no log-area damping (newton_preconditioner.h).
template <int Dim, class Density>
class HessiansOnlyWithoutOnset final : public HessiansOnly<Dim, Density> {
 public:
  double collapse_barrier_onset() const override { return 0; }
};

// v^T (P_a - P_b) v for projected Newton's matrices on the objectives a and
// b at x (the clamp, one update each), each without its Tikhonov shift, v a
// seeded Gaussian vector.
template <int Dim>
double newton_matrix_difference(const MeshObjective<Dim>& a, const MeshObjective<Dim>& b, const Eigen::VectorXd& x,
                                unsigned seed, Eigen::VectorXd* v) {
  const double shift = FactorOptions{}.tikhonov;
  std::mt19937 random(seed);
  std::normal_distribution<double> normal;
  *v = Eigen::VectorXd::NullaryExpr(x.size(), [&] { return normal(random); });
  double form[2];
  int i = 0;
  for (const MeshObjective<Dim>* objective : {&a, &b}) {
    Eigen::VectorXd g;
    const double energy = objective->value_and_gradient(x, &g);
    NewtonPreconditioner<Dim> newton(*objective);
    newton.update({x, g, energy, 1});
    Eigen::MatrixXd P(newton.matrix().full());
    P.diagonal().array() -= shift * P.diagonal().mean() / (1 + shift);
    form[i++] = v->dot(P * *v);
  }
  return form[0] - form[1];
}

// The density's collapse barrier Hessian at J against the barrier alone
// (its value less sum (sigma_i - 1)^2, ARAP's own density) by central
// differences in vec(J) with step h, its eigenvalues clamped at 0.
template <int Dim>
void check_collapse_barrier_hessian(const DistortionDensity<Dim>& density, const Eigen::Matrix<double, Dim, Dim>& J,
                                    double h) {
  using M = Eigen::Matrix<double, Dim, Dim>;
  using H = typename DistortionDensity<Dim>::Hessian;
  H barrier_hessian;
  REQUIRE(density.collapse_barrier_hessian(J, &barrier_hessian));
  const auto barrier = [&](const M& K) {
    return density.value(K) - (Eigen::JacobiSVD<M>(K).singularValues().array() - 1).square().sum();
  };
  H raw;
  for (int a = 0; a < Dim * Dim; ++a)
    for (int b = 0; b < Dim * Dim; ++b) {
      const auto at = [&](double da, double db) {
        M K = J;
        K.data()[a] += da;
        K.data()[b] += db;
        return barrier(K);
      };
      raw(a, b) = (at(h, h) - at(h, -h) - at(-h, h) + at(-h, -h)) / (4 * h * h);
    }
  const Eigen::SelfAdjointEigenSolver<H> eig(0.5 * (raw + raw.transpose()));
  const H clamped = eig.eigenvectors() * eig.eigenvalues().cwiseMax(0.0).asDiagonal() * eig.eigenvectors().transpose();
  CHECK((barrier_hessian - clamped).norm() <= 1e-4 * clamped.norm());
  CHECK(barrier_hessian.template selfadjointView<Eigen::Lower>().eigenvalues().minCoeff() >=
        -1e-9 * barrier_hessian.norm());
}

// dD/dsigma_i of a density with a singular-value derivative against central
// differences of D at diag(sigma).
template <int Dim>
void check_singular_value_gradient(const DistortionDensity<Dim>& density, const Eigen::Matrix<double, Dim, 1>& sigma) {
  using Vector = Eigen::Matrix<double, Dim, 1>;
  const auto& derivative = dynamic_cast<const SingularValueDerivative<Dim>&>(density);
  const Vector grad = derivative.singular_value_gradient(sigma);
  const double h = 1e-6;
  for (int i = 0; i < Dim; ++i) {
    Vector plus = sigma, minus = sigma;
    plus[i] += h;
    minus[i] -= h;
    const double fd =
        (density.value(plus.asDiagonal().toDenseMatrix()) - density.value(minus.asDiagonal().toDenseMatrix())) /
        (2 * h);
    CHECK(grad[i] == doctest::Approx(fd).epsilon(1e-6));
  }
}

}  // namespace akvf::test
