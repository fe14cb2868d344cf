#pragma once
// The As-Killing-As-Possible preconditioner of §4-§5 in the plane:
// d = -K(x)^+ grad E (Eq. 11-12), with K(x) of Eq. (5), area-scaled (§4.2.1).
//
// Null space. K(x) is PSD with exactly the rigid motions of x in its null
// space (two translations, one rotation). We factor K + eps I with
// eps = tikhonov * mean(diag K) and then project the rigid motions out of
// the solution (§5.1). For a gradient orthogonal to the rigid motions (the
// gradient of every rigid-invariant energy is) this is K^+ g up to a factor
// lambda / (lambda + eps) on each eigenvector, i.e. a relative change of
// about eps / lambda_min(K), 1e-5 or less on the meshes we tested. The shift
// makes the singular system factorizable by a plain Cholesky (no pivoting,
// symbolic analysis reusable); the projection removes the rigid component the
// shifted solve lets through. See docs/design.md.
#include <memory>

#include "framework/param_objective.h"
#include "framework/preconditioner.h"
#include "preconditioners/killing_operator_2d.h"
#include "solvers/sparse_cholesky.h"

namespace akvf {

struct AkvfOptions {
  // Tikhonov shift relative to the mean diagonal of K.
  double tikhonov = 1e-8;
  // Scale each face by A_hat_f / A_f (§4.2.1); off integrates over the UV domain.
  bool area_scaling = true;
  // Factorization reuse. 0: factor K(x) at every iteration (Algorithm 1 as
  // written). tau > 0: first try to solve K(x) d = g by conjugate gradients
  // preconditioned with the last factorization, to ||K d - g|| <= tau ||g||
  // (the paper's own 3D solver uses CG to 1%); refactor when that takes more
  // than reuse_max_cg iterations (and then try again only after a back-off).
  // The default 0.03 is measured in docs/performance.md.
  double reuse_tolerance = 0.03;
  int reuse_max_cg = 8;
};

// What the preconditioner did, for reports.
struct AkvfStatistics {
  int factorizations = 0;
  int reused_solves = 0;  // directions from CG with an older factorization
  int cg_iterations = 0;
};

class AkvfPreconditioner2D final : public Preconditioner {
 public:
  AkvfPreconditioner2D(const ParamObjective& objective, AkvfOptions options = {});
  std::string name() const override { return "akvf"; }
  void update(const OptimizationState& state) override;
  void apply(const Eigen::VectorXd& gradient, Eigen::VectorXd* result) override;

  const KillingOperator2D& killing_operator() const { return operator_; }
  const AkvfStatistics& statistics() const { return statistics_; }
  std::string report() const override;

 private:
  void factorize_current();
  // Preconditioned CG on (K + eps I) d = g with the last factor; false if it
  // does not reach the tolerance in reuse_max_cg iterations.
  bool solve_with_previous_factor(const Eigen::VectorXd& g, Eigen::VectorXd* d);

  const ParamObjective& objective_;
  AkvfOptions options_;
  KillingOperator2D operator_;
  SparseCholesky cholesky_;
  Eigen::MatrixXd rigid_basis_;           // 2|V| by 3, orthonormal rigid motions of the current x
  Eigen::MatrixXd factored_rigid_basis_;  // the same at the last factorization
  bool factor_is_current_ = false;
  // Back-off after failed reuse: skip this many further attempts, doubling
  // after each failure and reset by a success, so a fast-changing K is
  // simply factored every iteration.
  int skip_reuse_ = 0;
  int failure_backoff_ = 1;
  AkvfStatistics statistics_;
};

// Orthonormal basis (2|V| by 3) of the rigid motions of the planar points x:
// the two translations and the rotation about their centroid.
Eigen::MatrixXd rigid_motion_basis_2d(const Eigen::VectorXd& x);

}  // namespace akvf
