#pragma once
// Hard constraints on the preconditioner side: wraps any preconditioner and
// zeroes its direction on the fixed coordinates. With a gradient that is
// zero there (FixedVerticesObjective), the masked direction d_f =
// (P^-1)_ff g_f is still a descent direction for any SPD P, since (P^-1)_ff
// is a principal block of an SPD matrix; a large extra diagonal on the fixed
// coordinates (FactorOptions::extra_diagonal) makes it P_ff^-1 g_f, the
// preconditioner restricted to the free coordinates.
#include <memory>

#include "akvf/preconditioner.h"

namespace akvf {

class FixedVerticesPreconditioner final : public Preconditioner {
 public:
  FixedVerticesPreconditioner(std::unique_ptr<Preconditioner> inner, Eigen::VectorXd free_mask)
      : inner_(std::move(inner)), free_mask_(std::move(free_mask)) {}
  std::string name() const override { return inner_->name(); }
  void update(const OptimizationState& state) override { inner_->update(state); }
  void apply(const Eigen::VectorXd& gradient, Eigen::VectorXd* result) override {
    inner_->apply(gradient, result);
    result->array() *= free_mask_.array();
  }
  std::string report() const override { return inner_->report(); }
  bool has_element_curvature() const override { return inner_->has_element_curvature(); }
  PreconditionerStatistics statistics() const override { return inner_->statistics(); }

 private:
  std::unique_ptr<Preconditioner> inner_;
  Eigen::VectorXd free_mask_;
};

}  // namespace akvf
