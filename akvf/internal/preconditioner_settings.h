#pragma once
// The options of the built-in preconditioners, as the registries of
// catalog.h pass them to every preconditioner factory.
#include <memory>
#include <string>

#include "akvf/catalog.h"
#include "preconditioners/akvf_preconditioner_2d.h"
#include "preconditioners/akvf_preconditioner_3d.h"
#include "preconditioners/newton_preconditioner.h"
#include "preconditioners/switching_preconditioner.h"

namespace akvf {

// The tag of the 2D preconditioners that take the boundary barrier's
// curvature through share_contact_curvature(); the others get it through
// ContactPreconditioner.
inline constexpr const char* kTakesContactCurvature = "takes-contact-curvature";

// Options of the preconditioners that have them, set from the command line.
struct PreconditionerSettings2D {
  AkvfOptions2D akvf;
  FactorOptions newton;  // factored every iteration unless reuse is set
  // The Newton phase of akvf-newton: reuses factorizations as AKVF does
  // (measured by akvf_speed).
  FactorOptions newton_phase = AkvfOptions2D{}.factor;
  FactorOptions laplacian;  // constant: factored once
  FactorOptions slim;       // factored every iteration unless reuse is set
  // When akvf-newton switches; its isometric step is the energy's (set by
  // the catalog), its backtracking factor the line search's.
  SwitchRule akvf_newton_switch;
  EigenvalueFilter newton_filter = EigenvalueFilter::kClamp;  // newton
  // akvf-newton's Newton phase: the exact Hessian while it is positive
  // definite (newton_preconditioner.h; docs/design.md says why).
  EigenvalueFilter newton_phase_filter = EigenvalueFilter::kExact;

  // Every factored preconditioner takes its symbolic analyses from `cache`.
  void share_analyses(const std::shared_ptr<SymbolicAnalysisCache>& cache) {
    for (FactorOptions* options : {&akvf.factor, &newton, &newton_phase, &laplacian, &slim})
      options->analysis_cache = cache;
  }
  // Every factored preconditioner solves with `solver`.
  void set_linear_solver(LinearSolver solver) {
    for (FactorOptions* options : {&akvf.factor, &newton, &newton_phase, &laplacian, &slim})
      options->linear_solver = solver;
  }
  // Every factored preconditioner includes the boundary barrier's curvature
  // (global injectivity), one pattern shared by them all.
  void share_contact_curvature(const std::shared_ptr<ContactCurvature>& curvature) {
    for (FactorOptions* options : {&akvf.factor, &newton, &newton_phase, &laplacian, &slim})
      options->contact_curvature = curvature;
  }
  // Every factored preconditioner's analysis eliminates the vertices in
  // `ordering` (the mesh's, computed once; null: each orders its own).
  void share_vertex_ordering(const std::shared_ptr<const BlockOrdering>& ordering) {
    for (FactorOptions* options : {&akvf.factor, &newton, &newton_phase, &laplacian, &slim})
      options->vertex_ordering = ordering;
  }
};

// Options of the 3D preconditioners. In deformation, newton, laplacian and
// slim carry the constraint term's Hessian in their extra_diagonal.
struct PreconditionerSettings3D {
  AkvfOptions3D akvf;
  FactorOptions newton = shifted_factor_options(1e-4);
  FactorOptions laplacian = shifted_factor_options(1e-4);
  FactorOptions slim = shifted_factor_options(1e-4);
  SwitchRule akvf_newton_switch;  // as in 2D
  EigenvalueFilter newton_filter = EigenvalueFilter::kClamp;
  EigenvalueFilter newton_phase_filter = EigenvalueFilter::kExact;  // as in 2D

  // Jacobi-CG to this relative residual instead of factoring, for every
  // matrix that changes per iteration (akvf, newton, slim; the Laplacian is
  // factored once). 0 = factor.
  void set_cg_tolerance(double tolerance) {
    for (FactorOptions* options : {&akvf.factor, &newton, &slim}) options->cg_tolerance = tolerance;
  }
  // Every factored preconditioner takes its symbolic analyses from `cache`.
  void share_analyses(const std::shared_ptr<SymbolicAnalysisCache>& cache) {
    for (FactorOptions* options : {&akvf.factor, &newton, &laplacian, &slim}) options->analysis_cache = cache;
  }
  // Every factored preconditioner solves with `solver`.
  void set_linear_solver(LinearSolver solver) {
    for (FactorOptions* options : {&akvf.factor, &newton, &laplacian, &slim}) options->linear_solver = solver;
  }
};
// The solver a run uses for `solver`: kAuto becomes kCholmod in a build
// without multigrid.
LinearSolver available_linear_solver(LinearSolver solver);

}  // namespace akvf
