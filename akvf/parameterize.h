#pragma once
// The public 2D API: parameterize a triangle mesh with disk topology.
//
//   Eigen::MatrixXd V;  // #V by 3 vertex positions
//   Eigen::MatrixXi F;  // #F by 3 vertex indices, 0-based
//   akvf::ParameterizeResult r = akvf::parameterize(V, F);
//   r.uv;               // #V by 2, at the input's scale (the optimized map, r.energy() of this V, F)
//
// Errors are the typed exceptions of <akvf/error.h>: InputError and
// ValidationError for the mesh (messages name the element as the arrays
// number it, from 0), OptionsError for options, NumericalError. Nothing is
// printed; progress goes through options.callbacks. A run that ends early
// (line search or numerical failure) is not an exception: see result.status.
#include <Eigen/Core>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "akvf/choices.h"
#include "akvf/mesh.h"
#include "akvf/optimizer.h"
#include "akvf/preconditioner.h"

namespace akvf {

// Every option of `akvf param`, with the command line's defaults
// (docs/api.md lists the flag of each field).
struct ParameterizeOptions {
  std::string energy = "symmetric-dirichlet";       // a name of energies_2d(), built in or registered
  double exponent = 1;                              // k of exp-symmetric-dirichlet and amips; > 0
  Solver solver = Solver::kDescent;                 // Algorithm 1 with `preconditioner`, or L-BFGS
  std::string preconditioner = "akvf-newton";       // a name of preconditioners_2d(); "lbfgs" = solver lbfgs
  std::string line_search = "backtracking";         // or "wolfe-bisection"
  Acceleration acceleration = Acceleration::kAuto;  // AQP momentum (kAuto: the laplacian only)
  double akvf_reuse = 0.03;                        // AKVF: reuse the last factor through CG to this residual; 0 = never
  std::optional<double> newton_reuse;              // projected Newton's reuse tolerance; none ("auto"): 0 for
                                                   // newton, akvf_reuse for the Newton phase of akvf-newton
  double ls_rho = 0.5;                             // backtracking shrink factor in (0, 1)
  std::optional<double> local_sweep;               // > 0: local Newton sweeps after bound-set steps (the
                                                   // vertices whose |g_v|^2 passes it times the mean); 0 = off;
                                                   // none ("auto"): 4 for akvf-newton on an energy
                                                   // tagged kCollapseBarrier (not arap), off for the others
  std::optional<double> akvf_compression;          // plain AKVF: faces whose K curves more than this many times
                                                   // the energy along their compression take the energy's
                                                   // mirrored Hessian; 0 = off (K as in §4); none ("auto"): 1
                                                   // on an energy not tagged kCollapseBarrier (arap), else off
  InitialMap init = InitialMap::kAuto;             // kFile is the command line's (the API takes
                                                   // Parameterizer::solve(uv0))
  Cut cut = Cut::kNone;                            // kAuto: cut closed / multi-boundary / higher-genus /
                                                   // multi-component meshes into disk charts (uv_faces);
                                                   // kSeams: then add seams (max_distortion)
  double max_distortion = 4.2;                     // kSeams: bound on each chart's symmetric Dirichlet energy
  double min_coverage = 0.6;                       // a cut: charts split until the packing covers this share
  int texture_size = 1024;                         // several charts: the texture's side in texels, and
  double gutter = 2;                               // the least gap between packed charts, in its texels
  Repair repair = Repair::kAuto;                   // kAuto: weld duplicate vertices, repair non-manifold input
                                                   // (per-corner uv_faces); kNone: refuse such meshes
  bool flaps = true;                               // flap optimization of §5.4 after the Tutte map
  Injectivity injectivity = Injectivity::kGlobal;  // kGlobal: no UV overlap (boundary contact-free);
                                                   // kLocal: flip-free only, the paper's Algorithm 1
  std::optional<double> grad_tol;                  // converged when ||grad E|| < grad_tol (area-1 units); none
                                                   // ("auto"): 1e-3, or 1e-4 for an energy 0 at an isometry (arap)
  int max_iters = 1000;                            // >= 0
  double time_limit = std::numeric_limits<double>::infinity();  // optimizer seconds, > 0
  int warm_start_iters = 1000;  // limit of the symmetric Dirichlet warm start of overflowing energies
  LinearSolver linear_solver = LinearSolver::kAuto;  // kAuto: kAmg only if the factor would not fit
  EigenFilter eigen_filter = EigenFilter::kAuto;     // projected Newton's element Hessians
  int threads = 0;                                   // worker threads for this call; 0 = all cores
  // Called after every iteration (row 0 = the initial map) with the summary
  // and the current map (interleaved u0 v0 u1 v1 ..., area-1 units; use
  // Parameterizer::uv_of to get #V by 2 at the input's scale). Returning
  // CallbackAction::kStop ends the run with status kUserStopped.
  std::vector<IterationCallback> callbacks;

  // True if every value is in range and every name is known; otherwise
  // *error (if given) says which is not, as the command line would.
  bool is_valid(std::string* error = nullptr) const;
};

// What a run did, as numbers.
struct RunStatistics {
  int iterations = 0;
  double seconds = 0;                 // optimizer time, warm start included
  double preconditioner_seconds = 0;  // update + apply, summed over iterations
  double line_search_seconds = 0;
  PreconditionerStatistics preconditioner;  // factorizations, reused solves, CG iterations
};

struct ParameterizeResult {
  // At the input's scale: #V by 2 (vertices in no face get (0, 0)); with
  // cut "auto", one row per vertex of the cut mesh (a seam vertex has one
  // per side). uv_faces (#F by 3) says which row each face corner uses: F
  // itself without the cut (libigl's TC and FTC).
  Eigen::MatrixXd uv;
  Eigen::MatrixXi uv_faces;
  TerminationStatus status = TerminationStatus::kMaxIterations;
  std::string message;                  // why it ended, e.g. "gradient norm below 0.001"
  std::vector<IterationSummary> trace;  // row 0 = the initial map (warm-start rows first, if any)
  RunStatistics statistics;
  std::string preconditioner_report;  // the command line's one-line report
  Warnings warnings;                  // e.g. dropped unreferenced vertices
  // The start: kTutte, kCotan, kConformal (init kAuto resolved), or kFile
  // for a given start map (Parameterizer::solve(uv0)).
  InitialMap initial_map = InitialMap::kTutte;
  // Self-overlap of the final map, per chart: boundary edges that cross
  // and the fraction of the area rasterized twice (about 10^6 samples).
  // Zero with injectivity "global" from an injective start.
  int boundary_crossings = 0;
  double overlap_fraction = 0;
  // The energy of the map in uv: energy() less the boundary barrier that
  // global injectivity adds where it holds the map off an overlap.
  double distortion_energy = 0;
  // With cut kSeams: the seams added after the first cut, the length of
  // every seam (that cut's too) over the square root of the mesh's area,
  // each chart's symmetric Dirichlet energy at the end, and whether all are
  // at most max_distortion (if not, seam_stop_reason says why seams stopped);
  // the charts added where the flip-free map that met the bound lay over
  // itself (overlap_pieces) and the charts parted in two because seams
  // alone did not meet it (parted_charts).
  int seams_added = 0;
  int overlap_pieces = 0;
  int parted_charts = 0;
  double seam_length = 0;
  // With a cut: the straight cuts that split charts for the packing
  // (min_coverage).
  int packing_splits = 0;
  std::vector<double> chart_distortion;
  bool distortion_bounded = false;
  std::string seam_stop_reason;

  double energy() const { return trace.empty() ? 0 : trace.back().energy; }
  double grad_norm() const { return trace.empty() ? 0 : trace.back().grad_norm; }
  int iterations() const { return trace.empty() ? 0 : trace.back().iteration; }
};

// Validates, normalizes, computes the initial map and optimizes.
//   V  #V by 3, F  #F by 3 (0-based)
ParameterizeResult parameterize(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F,
                                const ParameterizeOptions& options = {});

// Repeated solves on one mesh: validation, normalization and the initial map
// are done once, at construction; then solve, change the options or the
// start map, and solve again. Each solve builds its preconditioner anew, so
// it gives the bits parameterize() gives for the same options and start; the
// symbolic analysis of the sparse factorizations is computed by the first
// solve (with local injectivity at construction, beside the Tutte solve, and
// counted by the first solve) and copied by the later ones
// (statistics.preconditioner.symbolic_analyses).
class Parameterizer {
 public:
  //   V  #V by 3, F  #F by 3 (0-based). Throws as parameterize() does.
  Parameterizer(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, const ParameterizeOptions& options = {});
  ~Parameterizer();
  Parameterizer(Parameterizer&&) noexcept;
  Parameterizer& operator=(Parameterizer&&) noexcept;

  // From the initial map (Tutte + flaps, or the warm start of energies that
  // overflow there). `callbacks` are called for this solve only, after
  // options().callbacks.
  ParameterizeResult solve(const std::vector<IterationCallback>& callbacks = {});
  // From `uv0` (#V by 2, any scale and placement; started at the energy's
  // best uniform scale): OptionsError if it is not of that shape,
  // ValidationError naming the first inverted triangle.
  ParameterizeResult solve(const Eigen::MatrixXd& uv0, const std::vector<IterationCallback>& callbacks = {});

  // New options for the next solves; the initial map is recomputed only if
  // an option whose schema field says so changed (marked (*) in
  // docs/options.md).
  // One Parameterizer does one thing at a time: solve() or set_options()
  // while it is solving (from another thread, or from a callback) throws
  // OptionsError and changes nothing.
  void set_options(const ParameterizeOptions& options);
  const ParameterizeOptions& options() const;

  // The initial map (#V by 2, at the input's scale) and a callback's x as
  // #V by 2 at the input's scale (OptionsError for an x of another size: with
  // cut kSeams, the rounds after the first).
  Eigen::MatrixXd initial_uv() const;
  Eigen::MatrixXd uv_of(const Eigen::VectorXd& x) const;

 private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace akvf
