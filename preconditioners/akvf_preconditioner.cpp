#include "preconditioners/akvf_preconditioner.h"

#include "framework/error.h"

namespace akvf {

Eigen::MatrixXd rigid_motion_basis_2d(const Eigen::VectorXd& x) {
  const Eigen::Index n = x.size() / 2;
  Eigen::MatrixXd B = Eigen::MatrixXd::Zero(x.size(), 3);
  double cx = 0, cy = 0;
  for (Eigen::Index i = 0; i < n; ++i) {
    cx += x[2 * i];
    cy += x[2 * i + 1];
  }
  cx /= static_cast<double>(n);
  cy /= static_cast<double>(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    B(2 * i, 0) = 1;
    B(2 * i + 1, 1) = 1;
    // Velocity of a rotation about the centroid: (-(y - cy), x - cx).
    B(2 * i, 2) = -(x[2 * i + 1] - cy);
    B(2 * i + 1, 2) = x[2 * i] - cx;
  }
  // The three columns are mutually orthogonal by construction (centred rotation).
  for (int c = 0; c < 3; ++c) B.col(c).normalize();
  return B;
}

AkvfPreconditioner2D::AkvfPreconditioner2D(const ParamObjective& objective, AkvfOptions options)
    : objective_(objective), options_(options), operator_(objective.faces(), objective.num_vertices()) {
  if (!(options_.tikhonov > 0)) throw OptionsError("AKVF Tikhonov shift must be > 0");
}

void AkvfPreconditioner2D::update(const OptimizationState& state) {
  operator_.assemble(state.x, objective_.rest().area, options_.area_scaling);
  operator_.add_to_diagonal(options_.tikhonov * operator_.mean_diagonal());
  if (!cholesky_.analyzed()) cholesky_.analyze(operator_.upper());
  cholesky_.factorize(operator_.upper());
  rigid_basis_ = rigid_motion_basis_2d(state.x);
}

void AkvfPreconditioner2D::apply(const Eigen::VectorXd& gradient, Eigen::VectorXd* result) {
  cholesky_.solve(gradient, result);
  *result -= rigid_basis_ * (rigid_basis_.transpose() * *result);
}

}  // namespace akvf
