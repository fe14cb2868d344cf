#include "akvf/constrained_objective.h"

#include <algorithm>

#include "akvf/error.h"

namespace akvf {

SoftConstrainedObjective::SoftConstrainedObjective(const Objective& base, int dimension,
                                                   PositionConstraints constraints, double weight)
    : base_(base), dimension_(dimension), constraints_(std::move(constraints)), weight_(weight) {
  if (!(weight_ > 0)) throw OptionsError("constraint weight must be > 0");
  const int num_vertices = base_.num_variables() / dimension_;
  if (constraints_.targets.rows() != static_cast<Eigen::Index>(constraints_.vertices.size()) ||
      constraints_.targets.cols() != dimension_)
    throw OptionsError("constraint targets must be " + std::to_string(constraints_.vertices.size()) + " by " +
                       std::to_string(dimension_));
  for (int v : constraints_.vertices)
    if (v < 0 || v >= num_vertices)
      throw OptionsError("constrained vertex " + std::to_string(v) + " out of range (" + std::to_string(num_vertices) +
                         " vertices)");
}

double SoftConstrainedObjective::penalty(const Eigen::VectorXd& x) const {
  double sum = 0;
  for (std::size_t c = 0; c < constraints_.vertices.size(); ++c)
    sum += (x.segment(dimension_ * constraints_.vertices[c], dimension_) - constraints_.targets.row(c).transpose())
               .squaredNorm();
  return weight_ * sum;
}

double SoftConstrainedObjective::constraint_distance(const Eigen::VectorXd& x) const {
  double largest = 0;
  for (std::size_t c = 0; c < constraints_.vertices.size(); ++c)
    largest = std::max(largest, (x.segment(dimension_ * constraints_.vertices[c], dimension_) -
                                 constraints_.targets.row(c).transpose())
                                    .norm());
  return largest;
}

double SoftConstrainedObjective::value(const Eigen::VectorXd& x) const { return base_.value(x) + penalty(x); }

double SoftConstrainedObjective::value_and_gradient(const Eigen::VectorXd& x, Eigen::VectorXd* gradient) const {
  const double energy = base_.value_and_gradient(x, gradient);
  for (std::size_t c = 0; c < constraints_.vertices.size(); ++c) {
    const int offset = dimension_ * constraints_.vertices[c];
    gradient->segment(offset, dimension_) +=
        2 * weight_ * (x.segment(offset, dimension_) - constraints_.targets.row(c).transpose());
  }
  return energy + penalty(x);
}

Eigen::VectorXd SoftConstrainedObjective::hessian_diagonal() const {
  Eigen::VectorXd diagonal = Eigen::VectorXd::Zero(base_.num_variables());
  for (int v : constraints_.vertices) diagonal.segment(dimension_ * v, dimension_).setConstant(2 * weight_);
  return diagonal;
}

FixedVerticesObjective::FixedVerticesObjective(const Objective& base, int dimension, std::vector<int> fixed_vertices)
    : base_(base), free_mask_(Eigen::VectorXd::Ones(base.num_variables())) {
  const int num_vertices = base_.num_variables() / dimension;
  for (int v : fixed_vertices) {
    if (v < 0 || v >= num_vertices)
      throw OptionsError("constrained vertex " + std::to_string(v) + " out of range (" + std::to_string(num_vertices) +
                         " vertices)");
    free_mask_.segment(dimension * v, dimension).setZero();
  }
}

double FixedVerticesObjective::value_and_gradient(const Eigen::VectorXd& x, Eigen::VectorXd* gradient) const {
  const double energy = base_.value_and_gradient(x, gradient);
  gradient->array() *= free_mask_.array();
  return energy;
}

Eigen::VectorXd place_at_targets(const Eigen::VectorXd& x, int dimension, const PositionConstraints& constraints) {
  Eigen::VectorXd placed = x;
  for (std::size_t c = 0; c < constraints.vertices.size(); ++c)
    placed.segment(dimension * constraints.vertices[c], dimension) = constraints.targets.row(c).transpose();
  return placed;
}

}  // namespace akvf
