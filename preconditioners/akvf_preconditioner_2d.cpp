#include "preconditioners/akvf_preconditioner_2d.h"

#include <Eigen/LU>
#include <Eigen/SVD>
#include <algorithm>

#include "framework/optimization/element_derivatives.h"
#include "preconditioners/energy_scale.h"

namespace akvf {

AkvfPreconditioner2D::AkvfPreconditioner2D(const MeshObjective2D& objective, AkvfOptions2D options)
    : FactoredPreconditioner2D(objective, options.factor),
      objective_(objective),
      options_(options),
      divergence_weight_(options.divergence_weight.value_or(rest_divergence_weight(objective.density()))),
      energy_scale_(options.energy_scaling ? 1 / isometric_newton_step(objective.density(), objective.rest().total_area)
                                           : 1.0),
      energy_to_k_(energy_scale_ * isometric_newton_step(objective.density(), objective.rest().total_area)) {
  sliver_.assign(static_cast<std::size_t>(objective.elements().rows()), 0);
  stiff_.assign(static_cast<std::size_t>(objective.elements().rows()), 0);
}

void AkvfPreconditioner2D::assemble(const OptimizationState& state, ElementMatrix2D* matrix) {
  ElementMatrix2D::LocalFunction add_energy_curvature;
  if (options_.sliver_stretch || options_.compression_stiffness) {
    const double limit = options_.sliver_stretch ? *options_.sliver_stretch * *options_.sliver_stretch : 0;
    const double stiffness = options_.compression_stiffness.value_or(0);
    add_energy_curvature = [&, limit, stiffness](int f, ElementMatrix2D::Local* local) {
      const Eigen::Matrix2d J = objective_.jacobian(state.x, f);
      const Eigen::Matrix2d& Dm_inv = objective_.rest().Dm_inv[f];
      if (stiffness > 0) {
        const double weight = objective_.weights()[f] * energy_to_k_;
        // The face's compression mode, dJ = u_min v_min^T (J = U S V^T), as a motion of corners 1 and 2
        // (corner 0 held; rigid parts cost neither form): [dx_1, dx_2] = dJ Dm, so that G dx = vec(dJ).
        const Eigen::JacobiSVD<Eigen::Matrix2d> svd(J, Eigen::ComputeFullU | Eigen::ComputeFullV);
        const Eigen::Matrix2d dJ = svd.matrixU().col(1) * svd.matrixV().col(1).transpose();
        const Eigen::Matrix2d dE = dJ * Dm_inv.inverse();
        Eigen::Matrix<double, 6, 1> dx;
        dx << 0, 0, dE.col(0), dE.col(1);
        const double k_curvature = dx.dot(local->selfadjointView<Eigen::Upper>() * dx);
        const Eigen::Map<const Eigen::Vector4d> vdJ(dJ.data());
        const double energy_curvature = weight * vdJ.dot(objective_.density().hessian(J) * vdJ);
        if (k_curvature > stiffness * energy_curvature) {
          stiff_[static_cast<std::size_t>(f)] = 1;
          const auto G = jacobian_map<2>(Dm_inv);
          local->triangularView<Eigen::Upper>() =
              (weight * G.transpose() * objective_.density().absolute_hessian(J) * G).eval();
          return;
        }
      }
      // Ds^-1 = Dm^-1 J^-1 (J = Ds Dm^-1).
      if (!(limit > 0 && Dm_inv.squaredNorm() > limit * (Dm_inv * J.inverse()).squaredNorm())) return;
      sliver_[static_cast<std::size_t>(f)] = 1;
      const auto G = jacobian_map<2>(Dm_inv);
      local->triangularView<Eigen::Upper>() +=
          objective_.weights()[f] * G.transpose() * objective_.density().projected_hessian(J) * G;
    };
  }
  assemble_killing_operator_2d(objective_.elements(), state.x, objective_.rest().area, options_.area_scaling, matrix,
                               divergence_weight_, energy_scale_, add_energy_curvature);
}

std::string AkvfPreconditioner2D::report() const {
  std::string line = FactoredPreconditioner2D::report();
  const auto slivers = std::count(sliver_.begin(), sliver_.end(), 1);
  if (slivers > 0)
    line +=
        "; the energy's own curvature at " + std::to_string(slivers) + " stretched sliver" + (slivers == 1 ? "" : "s");
  const auto stiff = std::count(stiff_.begin(), stiff_.end(), 1);
  if (stiff > 0)
    line += "; the energy's own curvature instead of K at " + std::to_string(stiff) + " compressed face" +
            (stiff == 1 ? "" : "s");
  return line;
}

}  // namespace akvf
