#pragma once
// The AQP proxy of Kovalsky, Galun and Lipman 2016: the cotangent Laplacian
// of the rest mesh for each coordinate, L = sum_e w_e grad phi_i . grad phi_j
// (x) I_D, constant, so assembled and factored once. Its null space is the
// translations (projected in 2D; in 3D deformation the constraint term's
// Hessian, FactorOptions::extra_diagonal, fixes them). The momentum of AQP
// lives in the optimizer (OptimizerOptions::acceleration_eta).
#include "akvf/mesh_objective.h"
#include "preconditioners/factored_preconditioner.h"

namespace akvf {

template <int D>
class LaplacianPreconditioner final : public FactoredPreconditioner<D> {
 public:
  // scale multiplies L (3D deformation: the energy's rest curvature over
  // L's, energy_scale.h, so that L sits beside the constraints' Hessian).
  explicit LaplacianPreconditioner(const MeshObjective<D>& objective, FactorOptions options = {},
                                   MotionProjection projection = D == 2 ? MotionProjection::kTranslations
                                                                        : MotionProjection::kNone,
                                   double scale = 1.0);
  std::string name() const override { return "laplacian"; }

 private:
  using Matrix = typename FactoredPreconditioner<D>::Matrix;
  void assemble(const OptimizationState& state, Matrix* matrix) override;
  Eigen::MatrixXd null_space(const Eigen::VectorXd& x) const override { return motion_basis(D, projection_, x); }
  bool is_constant() const override { return true; }

  const MeshObjective<D>& objective_;
  MotionProjection projection_;
  double scale_;
};

using LaplacianPreconditioner2D = LaplacianPreconditioner<2>;
using LaplacianPreconditioner3D = LaplacianPreconditioner<3>;

}  // namespace akvf
