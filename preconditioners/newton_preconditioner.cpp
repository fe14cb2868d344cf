#include "preconditioners/newton_preconditioner.h"

#include <cmath>

#include "framework/process/error.h"
#include "preconditioners/element_derivatives.h"

namespace akvf {

EigenvalueFilter parse_eigenvalue_filter(const std::string& name) {
  if (name == "clamp") return EigenvalueFilter::kClamp;
  if (name == "abs") return EigenvalueFilter::kAbsolute;
  if (name == "adaptive") return EigenvalueFilter::kAdaptive;
  throw OptionsError("unknown eigenvalue filter '" + name + "' (valid: clamp, abs, adaptive)");
}

template <int D>
NewtonPreconditioner<D>::NewtonPreconditioner(const MeshObjective<D>& objective, FactorOptions options,
                                              MotionProjection projection, EigenvalueFilter filter)
    : FactoredPreconditioner<D>(objective, std::move(options)),
      objective_(objective),
      projection_(projection),
      filter_(filter) {}

template <int D>
NewtonPreconditioner<D>::NewtonPreconditioner(const MeshObjective<D>& objective,
                                              const ElementMatrix<D, D + 1>& same_elements, FactorOptions options,
                                              MotionProjection projection, EigenvalueFilter filter)
    : FactoredPreconditioner<D>(objective, std::move(options), same_elements),
      objective_(objective),
      projection_(projection),
      filter_(filter) {}

template <int D>
double NewtonPreconditioner<D>::exact_curvature(const Eigen::VectorXd& x, const Eigen::VectorXd& s) const {
  double curvature = 0;
  for (int e = 0; e < objective_.weights().size(); ++e) {
    // J is linear in the positions, so jacobian(s) is the change of J along s.
    const auto dJ = objective_.jacobian(s, e);
    const Eigen::Map<const Eigen::Matrix<double, D * D, 1>> v(dJ.data());
    curvature += objective_.weights()[e] * v.dot(objective_.density().hessian(objective_.jacobian(x, e)) * v);
  }
  const Eigen::VectorXd& added = objective_.added_hessian_diagonal();
  if (added.size() == s.size()) curvature += s.dot(added.cwiseProduct(s));
  return curvature;
}

template <int D>
EigenvalueFilter NewtonPreconditioner<D>::adaptive_choice(const OptimizationState& state) {
  EigenvalueFilter choice = EigenvalueFilter::kAbsolute;
  if (previous_x_.size() == state.x.size()) {
    const Eigen::VectorXd s = state.x - previous_x_;
    const double predicted = -(previous_gradient_.dot(s) + 0.5 * exact_curvature(previous_x_, s));
    const double rho = (previous_energy_ - state.energy) / predicted;
    if (std::abs(rho - 1) < adaptive_tolerance) choice = EigenvalueFilter::kClamp;
  }
  previous_x_ = state.x;
  previous_gradient_ = state.gradient;
  previous_energy_ = state.energy;
  return choice;
}

template <int D>
void NewtonPreconditioner<D>::assemble(const OptimizationState& state, Matrix* matrix) {
  last_filter_ = filter_ == EigenvalueFilter::kAdaptive ? adaptive_choice(state) : filter_;
  const bool mirror = last_filter_ == EigenvalueFilter::kAbsolute;
  mirrored_assemblies_ += mirror;
  matrix->assemble([&](int e, typename Matrix::Local* local) {
    const auto G = jacobian_map<D>(objective_.rest().Dm_inv[e]);
    const auto J = objective_.jacobian(state.x, e);
    const auto H = mirror ? objective_.density().absolute_hessian(J) : objective_.density().projected_hessian(J);
    *local = objective_.weights()[e] * G.transpose() * H * G;
  });
}

template class NewtonPreconditioner<2>;
template class NewtonPreconditioner<3>;

}  // namespace akvf
