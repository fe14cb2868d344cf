#pragma once
// Projected Newton: P(x) = sum_e w_e G_e^T [d^2 D / dvec(J)^2]_+ G_e, the
// energy's Hessian with every element block projected to PSD (the density's
// projected_hessian), where G_e maps the element's corner positions to
// vec(J_e) (element_derivatives.h). The baseline of TinyAD-style
// second-order solvers; shift, projection and factorization reuse as in
// factored_preconditioner.h. In 3D deformation the constraint term's Hessian
// comes in through FactorOptions::extra_diagonal.
#include "framework/optimization/mesh_objective.h"
#include "preconditioners/factored_preconditioner.h"

namespace akvf {

template <int D>
class NewtonPreconditioner final : public FactoredPreconditioner<D> {
 public:
  // projection: rigid motions by default in 2D (the energy's null space),
  // none in 3D (the constraints fix the motion).
  explicit NewtonPreconditioner(const MeshObjective<D>& objective, FactorOptions options = {},
                                MotionProjection projection = D == 2 ? MotionProjection::kRigidMotions
                                                                     : MotionProjection::kNone);
  std::string name() const override { return "newton"; }

 private:
  using Matrix = typename FactoredPreconditioner<D>::Matrix;
  void assemble(const OptimizationState& state, Matrix* matrix) override;
  Eigen::MatrixXd null_space(const Eigen::VectorXd& x) const override { return motion_basis(D, projection_, x); }

  const MeshObjective<D>& objective_;
  MotionProjection projection_;
};

using NewtonPreconditioner2D = NewtonPreconditioner<2>;
using NewtonPreconditioner3D = NewtonPreconditioner<3>;

}  // namespace akvf
