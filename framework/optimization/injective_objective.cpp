#include "framework/optimization/injective_objective.h"

#include <algorithm>
#include <cmath>

namespace akvf {

InjectiveObjective::InjectiveObjective(const Objective& base, std::shared_ptr<const BoundaryContact> contact,
                                       double horizon)
    : base_(base), contact_(std::move(contact)), horizon_(horizon) {}

double InjectiveObjective::value(const Eigen::VectorXd& x) const {
  const double energy = base_.value(x);
  return std::isfinite(energy) ? energy + contact_->barrier(x, nullptr) : energy;
}

double InjectiveObjective::value_and_gradient(const Eigen::VectorXd& x, Eigen::VectorXd* gradient) const {
  const double energy = base_.value_and_gradient(x, gradient);
  return std::isfinite(energy) ? energy + contact_->barrier(x, gradient) : energy;
}

double InjectiveObjective::max_feasible_step(const Eigen::VectorXd& x, const Eigen::VectorXd& d) const {
  const double bound = std::min(base_.max_feasible_step(x, d), horizon_);
  return std::min(bound, contact_->first_contact_step(x, d, bound));
}

double injective_step_horizon(double max_initial_step, double max_step_fraction) {
  return 2 * max_initial_step / max_step_fraction;
}

}  // namespace akvf
