#pragma once
// The per-element distortion density D(J) of Eq. (1), as a function of the
// element's Jacobian J (Dim x Dim). A density knows nothing of meshes; the
// assembler (distortion_objective.h) sums A_hat_f D(J_f) over elements.
#include <array>
#include <cmath>
#include <limits>

#include <Eigen/Core>
#include <Eigen/Eigenvalues>
#include <string>

namespace akvf {

// D(J) of an inverted or collapsed element (det J <= 0): the barrier's value.
inline constexpr double kInvertedEnergy = std::numeric_limits<double>::infinity();

template <int Dim>
class DistortionDensity {
 public:
  using Matrix = Eigen::Matrix<double, Dim, Dim>;
  // Second derivative with respect to vec(J) (column-major).
  using Hessian = Eigen::Matrix<double, Dim * Dim, Dim * Dim>;

  virtual ~DistortionDensity() = default;

  virtual std::string name() const = 0;
  // inf_J D(J) over rotations-and-all: the value at J = I for isometric
  // energies. After area normalization it is also the energy's lower bound.
  virtual double lower_bound() const = 0;

  // D(J); +infinity when det J <= 0 so a line search backs off.
  virtual double value(const Matrix& J) const = 0;
  // D(J) and dD/dJ; the gradient is unspecified when the value is +infinity.
  virtual double value_and_gradient(const Matrix& J, Matrix* dD_dJ) const = 0;
  // d^2 D / dvec(J)^2 (may be indefinite).
  virtual Hessian hessian(const Matrix& J) const = 0;

  // The Hessian with negative eigenvalues clamped to zero (projected Newton).
  virtual Hessian projected_hessian(const Matrix& J) const {
    return with_eigenvalues(hessian(J), [](double lambda) { return lambda > 0 ? lambda : 0.0; });
  }
  // The Hessian with negative eigenvalues replaced by their absolute values
  // (mirrored), the filter Chen et al. 2024 use where the quadratic model
  // fits poorly.
  virtual Hessian absolute_hessian(const Matrix& J) const {
    return with_eigenvalues(hessian(J), [](double lambda) { return std::abs(lambda); });
  }
  // A density with a barrier term in det J that acts only near collapse
  // (2D ARAP's) returns true where it acts and sets H to that term's Hessian
  // with negative eigenvalues clamped. Preconditioners whose proxy models
  // the distortion but not the barrier (SLIM) add it, as IPC adds its
  // barrier's Hessian to any elasticity proxy: without it they see none of
  // the barrier's curvature and their steps shrink towards the collapse.
  virtual bool collapse_barrier_hessian(const Matrix& /*J*/, Hessian* /*H*/) const { return false; }
  // g_hat of that barrier: it acts only below det J = g_hat, and above it no
  // Hessian sees it (projected Newton adds a log-area damping of this weight:
  // preconditioners/newton_preconditioner.h); 0 for a density without one.
  virtual double collapse_barrier_onset() const { return 0; }

 protected:
  // H's eigen-decomposition with every eigenvalue lambda replaced by f(lambda).
  template <class F>
  static Hessian with_eigenvalues(const Hessian& H, F f) {
    const Eigen::SelfAdjointEigenSolver<Hessian> eig(H);
    return eig.eigenvectors() * eig.eigenvalues().unaryExpr(f).asDiagonal() * eig.eigenvectors().transpose();
  }
};

using DistortionDensity2D = DistortionDensity<2>;
using DistortionDensity3D = DistortionDensity<3>;

// Densities that expose dD/dsigma_i, the derivative in the signed singular
// values of J (J = U diag(sigma) V^T with U V^T a rotation): what the SLIM
// proxy reweights with. A density implements it alongside DistortionDensity.
template <int Dim>
class SingularValueDerivative {
 public:
  using Vector = Eigen::Matrix<double, Dim, 1>;
  virtual ~SingularValueDerivative() = default;
  // At sigma with a positive product (an element that is not inverted).
  virtual Vector singular_value_gradient(const Vector& sigma) const = 0;
  // Whether the density is minimal at every similarity (scale invariant,
  // as MIPS) rather than at rotations only: the SLIM proxy then pulls J
  // towards the nearest similarity instead of the nearest rotation.
  virtual bool minimal_at_similarities() const { return false; }
};

// Densities whose Hessian's eigen-decomposition is known in closed form
// expose it: d^2 D / dvec(J)^2 = sum_i lambda_i vec(M_i) vec(M_i)^T, the
// Dim^2 modes M_i orthonormal in the Frobenius product. Projected Newton then
// filters each lambda_i and assembles an element's block from the modes
// without forming the Hessian. A density implements it alongside
// DistortionDensity.
template <int Dim>
class HessianEigensystem {
 public:
  using Mode = Eigen::Matrix<double, Dim, Dim>;
  struct Eigenpairs {
    Eigen::Matrix<double, Dim * Dim, 1> values;
    std::array<Mode, Dim * Dim> modes;
  };
  virtual ~HessianEigensystem() = default;
  // At J with det J > 0.
  virtual Eigenpairs hessian_eigensystem(const Mode& J) const = 0;
};

}  // namespace akvf
