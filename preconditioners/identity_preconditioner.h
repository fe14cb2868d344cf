#pragma once
// P = I: plain gradient descent, the baseline the paper improves on.
#include "akvf/preconditioner.h"

namespace akvf {

class IdentityPreconditioner final : public Preconditioner {
 public:
  std::string name() const override { return "identity"; }
  void update(const OptimizationState&) override {}
  void apply(const Eigen::VectorXd& gradient, Eigen::VectorXd* result) override { *result = gradient; }
};

}  // namespace akvf
