#pragma once
// Positional constraints on interleaved D-dimensional vertex positions.
// Soft (§6.2): a term of the problem,
//   E_c(x) = E(x) + w sum_{i in C} |x_i - p_i|^2.
// Hard: the constrained vertices sit at p_i from the start and never move
// (their gradient entries are zero; FixedVerticesPreconditioner keeps the
// directions zero there). Both wrap any objective; the flip-free bound and
// the inverted count are the wrapped objective's.
#include <Eigen/Core>
#include <vector>

#include "akvf/objective.h"
#include "akvf/position_constraints.h"

namespace akvf {

class SoftConstrainedObjective final : public Objective {
 public:
  // Throws OptionsError if a vertex index is out of range, the target matrix
  // does not match, or the weight is not positive.
  SoftConstrainedObjective(const Objective& base, int dimension, PositionConstraints constraints, double weight);

  int num_variables() const override { return base_.num_variables(); }
  double value(const Eigen::VectorXd& x) const override;
  double value_and_gradient(const Eigen::VectorXd& x, Eigen::VectorXd* gradient) const override;
  double max_feasible_step(const Eigen::VectorXd& x, const Eigen::VectorXd& d) const override {
    return base_.max_feasible_step(x, d);
  }
  int count_inverted(const Eigen::VectorXd& x) const override { return base_.count_inverted(x); }
  std::string first_bad_element(const Eigen::VectorXd& x) const override { return base_.first_bad_element(x); }
  double lower_bound() const override { return base_.lower_bound(); }
  bool rotation_following_term(const Eigen::VectorXd& x, const Eigen::VectorXd& d, Eigen::VectorXd* a) const override {
    return base_.rotation_following_term(x, d, a);
  }

  double constraint_distance(const Eigen::VectorXd& x) const override;

  // w sum |x_i - p_i|^2 alone.
  double penalty(const Eigen::VectorXd& x) const;
  // The Hessian of the penalty, diagonal: 2 w on the constrained coordinates.
  Eigen::VectorXd hessian_diagonal() const;

 private:
  const Objective& base_;
  int dimension_;
  PositionConstraints constraints_;
  double weight_;
};

class FixedVerticesObjective final : public Objective {
 public:
  // Throws OptionsError if a vertex index is out of range.
  FixedVerticesObjective(const Objective& base, int dimension, std::vector<int> fixed_vertices);

  int num_variables() const override { return base_.num_variables(); }
  double value(const Eigen::VectorXd& x) const override { return base_.value(x); }
  double value_and_gradient(const Eigen::VectorXd& x, Eigen::VectorXd* gradient) const override;
  double max_feasible_step(const Eigen::VectorXd& x, const Eigen::VectorXd& d) const override {
    return base_.max_feasible_step(x, d);
  }
  int count_inverted(const Eigen::VectorXd& x) const override { return base_.count_inverted(x); }
  std::string first_bad_element(const Eigen::VectorXd& x) const override { return base_.first_bad_element(x); }
  double lower_bound() const override { return base_.lower_bound(); }
  // The base's term, 0 on the fixed coordinates (which never move).
  bool rotation_following_term(const Eigen::VectorXd& x, const Eigen::VectorXd& d, Eigen::VectorXd* a) const override {
    if (!base_.rotation_following_term(x, d, a)) return false;
    *a = a->cwiseProduct(free_mask_);
    return true;
  }
  // 0: the fixed vertices sit at their targets from the start and never move.
  double constraint_distance(const Eigen::VectorXd&) const override { return 0; }

  // 1 on free coordinates, 0 on fixed ones.
  const Eigen::VectorXd& free_mask() const { return free_mask_; }

 private:
  const Objective& base_;
  Eigen::VectorXd free_mask_;
};

// The start of a hard-constrained run: x with each constrained vertex moved
// to its target.
Eigen::VectorXd place_at_targets(const Eigen::VectorXd& x, int dimension, const PositionConstraints& constraints);

}  // namespace akvf
