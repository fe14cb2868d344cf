#include "preconditioners/contact_preconditioner.h"

#include <algorithm>
#include <cmath>

namespace akvf {

ContactPreconditioner::ContactPreconditioner(std::unique_ptr<Preconditioner> inner,
                                             std::shared_ptr<const BoundaryContact> contact, int max_terms)
    : inner_(std::move(inner)), contact_(std::move(contact)), max_terms_(max_terms) {}

Eigen::VectorXd ContactPreconditioner::spread(const Eigen::VectorXd& z, Eigen::Index size) const {
  Eigen::VectorXd v = Eigen::VectorXd::Zero(size);
  for (size_t k = 0; k < terms_.size(); ++k) {
    const BoundaryContact::ActiveTerm& term = terms_[k];
    const double weight = std::sqrt(term.curvature) * z[static_cast<Eigen::Index>(k)];
    for (int i = 0; i < 3; ++i) v.segment<2>(2 * term.vertex[i]) += weight * term.gradient[i];
  }
  return v;
}

Eigen::VectorXd ContactPreconditioner::gather(const Eigen::VectorXd& y) const {
  Eigen::VectorXd z(static_cast<Eigen::Index>(terms_.size()));
  for (size_t k = 0; k < terms_.size(); ++k) {
    const BoundaryContact::ActiveTerm& term = terms_[k];
    double dot = 0;
    for (int i = 0; i < 3; ++i) dot += term.gradient[i].dot(y.segment<2>(2 * term.vertex[i]));
    z[static_cast<Eigen::Index>(k)] = std::sqrt(term.curvature) * dot;
  }
  return z;
}

void ContactPreconditioner::update(const OptimizationState& state) {
  inner_->update(state);
  terms_ = contact_->active_terms(state.x);
  // The stiffest terms first; ties in the barrier's own order.
  std::stable_sort(terms_.begin(), terms_.end(),
                   [](const auto& a, const auto& b) { return a.curvature > b.curvature; });
  if (static_cast<int>(terms_.size()) > max_terms_) terms_.resize(static_cast<size_t>(max_terms_));
  if (terms_.empty()) return;
  const auto k = static_cast<Eigen::Index>(terms_.size());
  Eigen::MatrixXd S = Eigen::MatrixXd::Identity(k, k);
  Eigen::VectorXd unit = Eigen::VectorXd::Zero(k), w;
  for (Eigen::Index j = 0; j < k; ++j) {
    unit[j] = 1;
    inner_->apply(spread(unit, state.x.size()), &w);
    unit[j] = 0;
    S.col(j) += gather(w);
  }
  capacitance_.compute(0.5 * (S + S.transpose()));
}

void ContactPreconditioner::apply(const Eigen::VectorXd& gradient, Eigen::VectorXd* result) {
  inner_->apply(gradient, result);
  if (terms_.empty()) return;
  Eigen::VectorXd correction;
  inner_->apply(spread(capacitance_.solve(gather(*result)), gradient.size()), &correction);
  const Eigen::VectorXd corrected = *result - correction;
  if (corrected.allFinite() && gradient.dot(corrected) > 0) *result = corrected;
}

}  // namespace akvf
