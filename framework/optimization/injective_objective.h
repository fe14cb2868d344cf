#pragma once
// A 2D objective kept globally injective (boundary_contact.h):
//   E(x) = E_base(x) + E_B(x),
// the boundary barrier added to the wrapped distortion, and a feasible step
// that is also free of boundary contact. Everything else (the inverted
// count, the bad element, the lower bound, the rotation-following term) is
// the wrapped objective's. The preconditioners are built on the wrapped
// MeshObjective, and preconditioners/contact_preconditioner.h adds the
// barrier's curvature.
#include <Eigen/Core>
#include <memory>

#include "akvf/objective.h"
#include "framework/optimization/boundary_contact.h"

namespace akvf {

class InjectiveObjective final : public Objective {
 public:
  //   horizon  how far along a direction boundary contact is searched: the
  //            step bound is min(flip-free step, first contact, horizon).
  //            Backtracking starts at most at max_initial_step, and no
  //            search goes beyond max_step_fraction of the bound, so a
  //            horizon of 2 max_initial_step / max_step_fraction leaves
  //            backtracking as it was wherever no contact is near (the
  //            Wolfe search's growth stops at twice max_initial_step);
  //            injective_step_horizon.
  InjectiveObjective(const Objective& base, std::shared_ptr<const BoundaryContact> contact, double horizon);

  int num_variables() const override { return base_.num_variables(); }
  double value(const Eigen::VectorXd& x) const override;
  double value_and_gradient(const Eigen::VectorXd& x, Eigen::VectorXd* gradient) const override;
  double max_feasible_step(const Eigen::VectorXd& x, const Eigen::VectorXd& d) const override;
  int count_inverted(const Eigen::VectorXd& x) const override { return base_.count_inverted(x); }
  std::string first_bad_element(const Eigen::VectorXd& x) const override { return base_.first_bad_element(x); }
  double lower_bound() const override { return base_.lower_bound(); }
  double constraint_distance(const Eigen::VectorXd& x) const override { return base_.constraint_distance(x); }
  bool rotation_following_term(const Eigen::VectorXd& x, const Eigen::VectorXd& d, Eigen::VectorXd* a) const override {
    return base_.rotation_following_term(x, d, a);
  }

 private:
  const Objective& base_;
  std::shared_ptr<const BoundaryContact> contact_;
  double horizon_;
};

// The horizon of the line search settings' (max_initial_step,
// max_step_fraction): 2 max_initial_step / max_step_fraction.
double injective_step_horizon(double max_initial_step, double max_step_fraction);

}  // namespace akvf
