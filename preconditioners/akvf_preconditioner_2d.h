#pragma once
// The As-Killing-As-Possible preconditioner of §4-§5 in the plane:
// d = -K(x)^+ grad E (Eq. 11-12), with K(x) of Eq. (5), area-scaled
// (§4.2.1). Its null space is exactly the rigid motions of x. Shift,
// projection and factorization reuse: factored_preconditioner.h.
// It uses K_beta (killing_operator_2d.h) with the energy's beta
// (energy_scale.h): K itself except for MIPS, whose K_0 has the
// similarities of x as null space; they are projected out instead.
// The paper's Algorithm 1 factors K_beta unscaled. The default method's
// AKVF phase (akvf/catalog.cpp) factors c K_beta instead, c the energy's
// curvature at the rest isometry over K's (energy_scale.h), so that the
// direction's unit step, the line search's first trial, is Newton's step
// at an isometry (for symmetric Dirichlet the unscaled one is 4 times it).
//
// Slivers (AkvfOptions2D::sliver_stretch, the default's AKVF phase): K
// measures the velocity gradient on the current face, the energy the
// Jacobian's change on the rest face, and the two differ by the face's hat
// gradients, rest over current. A sliver of the input (a rest face of
// near-zero height) opened up by the start map (Tutte's ignores the rest
// shape) has its thinnest height stretched by a factor s, and there K holds
// about 1 / s^2 of the energy's curvature (symmetric Dirichlet's |J|^2 term
// alone curves as 2 |dJ|^2), with area scaling another 1 / det J. K^-1 g
// then closes the face within a tiny step and the flip-free bound holds the
// whole map there: K alone, tricera_b's sliver (5.6e-6 of the median area),
// opened to det J 1e4, holds AKVF's steps at 1e-5 to 1e-4 until the
// default's stall rule switches to Newton. A face whose ratio
// |Dm^-1|^2 / |Ds^-1|^2 (the hat gradients' squared norms, rest over
// current: s^2) exceeds sliver_stretch^2 adds projected Newton's block
// w_f G_f^T [H_f]_+ G_f to its part of K, so that the direction sees the
// curvature that holds it.
//
// Compression (AkvfOptions2D::compression_stiffness, plain AKVF on an
// energy without a barrier at collapse: ARAP): the other way round, a face
// the map compresses to singular value sigma_min has K curving as
// 1 / sigma_min^2 along that compression, while ARAP's density curves as 2
// there whatever sigma_min. K^-1 g then hardly moves the vertices of the
// faces the map squeezes (camelhead's flattened rest slivers: 98 % of the
// gradient on ten vertices after 300 iterations,
// docs/notes/2026-12-03-akvf-arap-compressed-slivers.md), and AKVF ends at
// the iteration limit. A face along whose compression mode dJ = u_min
// v_min^T K's quadratic form exceeds compression_stiffness times the
// energy's (both in K's units) takes the energy's own block
// w_f G_f^T |H_f| G_f instead of K's, its negative eigenvalues mirrored:
// clamped, ARAP's twist mode of a compressed face (eigenvalue
// 2 - 4 / (sigma_1 + sigma_2)) would leave a motion no term stiffens. The
// energies with a barrier at collapse curve at least as 1 / sigma^4 under
// compression, above K, so their option stays unset (akvf/options.cpp);
// it would still take faces stretched both ways there (symmetric
// Dirichlet's 2 + 6 / sigma^4 falls below K's 8 / sigma^2 for sigma > 1).
#include <optional>
#include <vector>

#include "akvf/mesh_objective.h"
#include "preconditioners/factored_preconditioner.h"
#include "preconditioners/killing_operator_2d.h"

namespace akvf {

struct AkvfOptions2D {
  // Reuse tau 0.03: measured by scripts/performance.sh.
  FactorOptions factor = [] {
    FactorOptions o;
    o.reuse_tolerance = 0.03;
    return o;
  }();
  // Scale each face by A_hat_f / A_f (§4.2.1); off integrates over the UV domain.
  bool area_scaling = true;
  // beta of K_beta; unset: the energy's (rest_divergence_weight).
  std::optional<double> divergence_weight;
  // c K_beta instead of K_beta (above).
  bool energy_scaling = false;
  // Faces whose thinnest height the map stretched more than this many times
  // carry the energy's own curvature too (above); unset: K alone.
  std::optional<double> sliver_stretch;
  // Faces along whose compression K curves more than this many times the
  // energy carry the energy's Hessian, negative eigenvalues mirrored,
  // instead of K (above); unset: K everywhere, as in §4.
  std::optional<double> compression_stiffness;
};

class AkvfPreconditioner2D final : public FactoredPreconditioner2D {
 public:
  explicit AkvfPreconditioner2D(const MeshObjective2D& objective, AkvfOptions2D options = {});
  std::string name() const override { return "akvf"; }
  std::string report() const override;

 private:
  void assemble(const OptimizationState& state, ElementMatrix2D* matrix) override;
  Eigen::MatrixXd null_space(const Eigen::VectorXd& x) const override {
    return divergence_weight_ > 0 ? rigid_motion_basis_2d(x) : similarity_motion_basis_2d(x);
  }

  const MeshObjective2D& objective_;
  AkvfOptions2D options_;
  double divergence_weight_;  // beta
  double energy_scale_;       // c, or 1 without energy_scaling
  double energy_to_k_;        // the energy's curvature in the factored matrix's units: energy_scale_ / c
  std::vector<char> sliver_;  // per face: it carried the energy's curvature in some assembly (sliver_stretch)
  std::vector<char> stiff_;   // per face: the energy's curvature replaced K in some assembly (compression_stiffness)
};

}  // namespace akvf
