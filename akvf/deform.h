#pragma once
// The public 3D API: deform a tet mesh with positional constraints (§6.2).
//
//   akvf::DeformResult r = akvf::deform(V, T, {indices, targets});
//   r.x;  // #V by 3 deformed positions, at the input's scale
//
// Minimizes sum_t V_t D(J_t) / sum_t V_t + w sum_i |x_i - p_i|^2 on the mesh
// scaled to rest volume 1 (targets alike), from the rest shape, with a
// flip-free preconditioned descent; or with hard constraints the distortion
// alone, the constrained vertices fixed at their targets. Errors and
// callbacks as in parameterize.h.
#include <Eigen/Core>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "akvf/constrained_objective.h"
#include "akvf/parameterize.h"

namespace akvf {

// Every option of `akvf deform`, with the command line's defaults.
struct DeformOptions {
  std::string energy = "symmetric-dirichlet";  // a name of energies_3d()
  double exponent = 1;                         // k of the exponential energies; > 0
  std::string preconditioner = "akvf-newton";  // a name of preconditioners_3d()
  std::string line_search = "backtracking";
  Acceleration acceleration = Acceleration::kAuto;
  double weight = 1e5;             // w of the soft constraints (unit rest volume); > 0
  bool hard = false;               // hard constraints instead of the penalty
  double cg_tol = 0;               // > 0: Jacobi-CG to this relative residual instead of factoring
  bool akvf_as_written = false;    // AKVF as §6.2 states it (K + c I only), for comparison
  std::optional<double> grad_tol;  // none ("auto"): 1e-3, or 1e-4 for an energy 0 at an isometry
  int max_iters = 100;             // Figure 8 runs 100 iterations
  double time_limit = std::numeric_limits<double>::infinity();
  LinearSolver linear_solver = LinearSolver::kAuto;  // kAuto: kAmg only if the factor would not fit
  EigenFilter eigen_filter = EigenFilter::kAuto;     // projected Newton's element Hessians
  int threads = 0;                                   // 0 = all cores
  // As ParameterizeOptions::callbacks; x is interleaved x0 y0 z0 x1 ... at
  // the input's scale.
  std::vector<IterationCallback> callbacks;

  bool is_valid(std::string* error = nullptr) const;
};

struct DeformResult {
  Eigen::MatrixXd x;  // #V by 3 at the input's scale; vertices in no tet stay where they were
  TerminationStatus status = TerminationStatus::kMaxIterations;
  std::string message;
  std::vector<IterationSummary> trace;  // row 0 = the rest shape; energies at unit rest volume
  RunStatistics statistics;
  std::string preconditioner_report;
  Warnings warnings;

  double energy() const { return trace.empty() ? 0 : trace.back().energy; }
  double grad_norm() const { return trace.empty() ? 0 : trace.back().grad_norm; }
  int iterations() const { return trace.empty() ? 0 : trace.back().iteration; }
};

//   V  #V by 3, T  #T by 4 (0-based), constraints.vertices 0-based indices
//   into V with constraints.targets #C by 3.
DeformResult deform(const Eigen::MatrixXd& V, const Eigen::MatrixXi& T, const PositionConstraints& constraints,
                    const DeformOptions& options = {});

// Repeated deformations of one mesh (new targets, new options): validation,
// normalization to unit rest volume and the rest geometry are done once, at
// construction; the symbolic analysis of the sparse factorizations at the
// first solve. Each solve starts from the rest shape and gives the bits
// deform() gives.
class Deformer {
 public:
  //   V  #V by 3, T  #T by 4 (0-based). Throws as deform() does.
  Deformer(const Eigen::MatrixXd& V, const Eigen::MatrixXi& T);
  ~Deformer();
  Deformer(Deformer&&) noexcept;
  Deformer& operator=(Deformer&&) noexcept;

  DeformResult solve(const PositionConstraints& constraints, const DeformOptions& options = {}) const;

 private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace akvf
