#pragma once
// The 2D parameterization pipeline, from a mesh to a UV map:
// validate -> normalize (area 1) -> Tutte (+ flaps) -> optimize -> rescale.
#include <memory>
#include <string>

#include "akvf/catalog.h"
#include "akvf/internal/preconditioner_settings.h"
#include "akvf/mesh.h"
#include "akvf/optimizer.h"
#include "akvf/rest_geometry.h"
#include "framework/mesh/initialization.h"
#include "framework/mesh/mesh_validation.h"
#include "framework/mesh/seam_opening.h"
#include "framework/mesh/uv_overlap.h"
#include "framework/optimization/boundary_contact.h"
#include "framework/optimization/distortion_objective.h"

namespace akvf {

// Whether the start is a conformal map (framework/optimization/conformal_map.h,
// boundary_first_map.h): never, where it is flip-free and lower in energy
// than the other starts tried, or wherever it is flip-free.
enum class ConformalStart { kNever, kAuto, kAlways };

struct ParamConfig {
  std::string energy = "symmetric-dirichlet";
  EnergySettings energy_settings;
  Solver solver = Solver::kDescent;
  std::string preconditioner = "akvf-newton";  // the default method (docs/design.md)
  std::string line_search = "backtracking";
  LineSearchSettings line_search_settings;
  PreconditionerSettings2D preconditioner_settings;
  TutteWeights init = TutteWeights::kUniform;
  // The conformal map instead of Tutte's (akvf/parameterization.cpp,
  // take_conformal_start), on one chart.
  ConformalStart conformal = ConformalStart::kAuto;
  // The boundary-first map likewise (take_conformal_start, after the
  // least-squares one).
  ConformalStart boundary_first = ConformalStart::kAuto;
  // Cut a closed, multi-boundary, higher-genus or multi-component mesh into
  // disks (one chart per component, framework/mesh/cut_to_disk.h) instead of
  // refusing it.
  bool cut = false;
  // Then add seams until every chart's symmetric Dirichlet energy is at
  // most `max_distortion` (akvf/internal/seam_cutting.h).
  bool seams = false;
  double max_distortion = 4.2;
  // With a cut, charts are split until their packing covers this share of
  // the UV square (akvf/internal/packing_splits.h); 0: never.
  double min_coverage = 0.6;
  // Several charts are packed at least this share of the square's side
  // apart (the gutter over the texture's size).
  double gutter = 2.0 / 1024;
  // Open edges of three or more faces and split non-manifold vertices
  // (framework/mesh/manifold_repair.h) instead of refusing them.
  bool repair = true;
  // init "file": start from `start_uv` (#V of the input by 2, any scale and
  // placement; a file's texture coordinates) instead of Tutte and flaps.
  bool init_from_file = false;
  Eigen::MatrixXd start_uv;
  // §5.4 flap optimization after the Tutte map (scripts/performance.sh
  // measures the default).
  bool optimize_flaps = true;
  // Keep the map globally injective (framework/optimization/
  // injective_objective.h: no boundary vertex ever reaches a boundary edge
  // of its chart) instead of only flip-free, the paper's Algorithm 1.
  bool global_injectivity = true;
  // AQP's momentum (OptimizerOptions::acceleration_eta): "auto" turns it on
  // for the laplacian preconditioner only, as AQP pairs them.
  Acceleration acceleration = Acceleration::kAuto;
  // > 0: after each step the flip-free bound set (of a preconditioner
  // without the elements' own curvature), one local Newton sweep
  // (framework/optimization/local_newton_sweep.h) over the vertices whose
  // squared gradient passes this many times the mean; with global
  // injectivity the interior ones only.
  double local_sweep = 0;
  OptimizerOptions optimizer;
  // Iteration limit of the warm start of energies that are infinite at the
  // initial map (symmetric Dirichlet with AKVF to gradient 1e-3 first).
  int warm_start_max_iterations = 1000;
  // Worker threads (TBB and OpenBLAS) during the run; 0 = all cores.
  LinearSolver linear_solver = LinearSolver::kAuto;  // kAuto: chosen from the factor's size
  int threads = 0;
};

// A validated, normalized problem with its initial map.
struct ParamSetup {
  double unit_scale = 1;                             // exact power of two: input * unit_scale has extent ~1
  DiskMesh disk;                                     // the compacted input mesh times unit_scale
  Normalization normalization;                       // of disk.mesh to total area 1
  std::shared_ptr<DistortionObjective2D> objective;  // on the normalized mesh
  // The charts' boundary loops: the run keeps them from crossing with
  // global injectivity, and every run counts their crossings at its end.
  std::shared_ptr<const BoundaryContact> boundary_contact;
  Eigen::VectorXd x0;  // initial map, interleaved, area-1 units
  InitialMap initial_map = InitialMap::kTutte;  // what x0 is (before a warm start)
  int flaps_moved = 0;
  int flaps_shortened = 0;  // of those, moved only part of the way: the full move crossed the boundary
  int folds_unfolded = 0;   // vertices of the conformal start moved out of its folds (fold_repair.h)
  // The fill-reducing ordering of the mesh's vertex graph, found with the
  // Tutte start (akvf/parameterization.cpp, mesh_vertex_ordering): the
  // optimizer's matrices are analyzed with it. Null where the start is not
  // Tutte's, and below 100 K vertices with global injectivity.
  std::shared_ptr<const BlockOrdering> vertex_ordering;
  // The symbolic analyses of the run's matrices: the API's cache where it
  // keeps one (Parameterizer), else one made where the setup prepares the
  // analysis of the mesh's 2 x 2-block pattern beside the Tutte solve (with
  // vertex_ordering). Null otherwise; run_from_start shares it.
  std::shared_ptr<SymbolicAnalysisCache> analyses;
  // The warm start's run when the energy is infinite at the initial map
  // (empty trace otherwise); x0 is its end point when it succeeded.
  OptimizerResult warm_start;
  Warnings warnings;
  // ParamConfig::gutter and min_coverage (set with them), for the packed outputs.
  double gutter = 0, min_coverage = 0;
};

// Throws ValidationError / OptionsError with a message naming `name`.
ParamSetup prepare_parameterization(const TriMesh& input, const std::string& name, const ParamConfig& config);

struct ParamRun {
  OptimizerResult result;
  std::string preconditioner_name;
  std::string preconditioner_report;
  PreconditionerStatistics preconditioner_statistics;
  // The final map's self-overlap: boundary edges that cross, and the
  // rasterized overlapping area (framework/mesh/uv_overlap.h). Zero for a
  // run with global injectivity from an injective start.
  int boundary_crossings = 0;
  UvOverlap overlap;
  // The distortion alone at the final map, the energy of the written map
  // (the trace's energy adds the boundary barrier of global injectivity,
  // which is not zero where the map is held off an overlap).
  double distortion_energy = 0;
  // With seams: the problem the final map is of (the mesh opened along the
  // seams), and what the seams did. Null / empty otherwise.
  std::shared_ptr<const ParamSetup> seamed;
  SeamReport seams;
  int packing_splits = 0;  // cuts split_for_packing made (the final problem is then run.seamed)
};

// A callback's stop or a signal: the run ends there, whatever would follow.
inline bool stop_asked(TerminationStatus status) {
  return status == TerminationStatus::kUserStopped || status == TerminationStatus::kInterrupted;
}

// Whether the run stops here: a stop asked already, or a signal arrived
// (framework/process/interrupt.h) while the work between or after the
// optimizer's loops ran, which then sets result's status to interrupted.
bool stop_on_signal(OptimizerResult* result);

// The problem run.result.x is a map of: run.seamed if seams were added or
// charts split for the packing, else `setup` itself.
inline const ParamSetup& final_setup(const ParamSetup& setup, const ParamRun& run) {
  return run.seamed ? *run.seamed : setup;
}

// The run from setup.x0. A warm start's rows open the trace (warm_start set)
// and its time is added to the seconds column. With config.seams, the rounds
// of seam_cutting.h, whose final problem is run.seamed.
ParamRun run_parameterization(const ParamSetup& setup, const ParamConfig& config,
                              const std::vector<IterationCallback>& callbacks = {});

// One optimization from setup.x0 with the warm start's rows ahead, without
// the final map's overlap measures (the rounds of seam_cutting.h). A run
// from a map near a minimum (`near_minimum`: the last seam round's map, or
// a warm start that left the energy within a factor e of its infimum) is
// where akvf-newton would switch to its Newton phase: the curvature, not
// the flip-free bound, sets the step (switching_preconditioner.h). It then
// starts there, with that phase's settings.
ParamRun optimize_from_start(const ParamSetup& setup, const ParamConfig& config,
                             const std::vector<IterationCallback>& callbacks, bool near_minimum = false);

// The overlap measures and the distortion energy of run->result.x.
void measure_final_map(const ParamSetup& setup, ParamRun* run);

// After setup->disk gained vertices (seams opened, same faces): its
// objective (same rest shapes) and boundary contact anew; with
// `tutte_start`, x0 the Tutte map (+ flaps) of the opened charts too.
void rebuild_problem(const ParamConfig& config, ParamSetup* setup, bool tutte_start = false);

// The UV map of the optimized mesh's vertices (#setup.disk.mesh.V by 2) at
// the input's scale: x with the normalization undone, so that the input
// mesh with this map has the energy the optimizer reported; several charts
// packed side by side (framework/mesh/chart_layout.h).
Eigen::MatrixXd chart_uv(const ParamSetup& setup, const Eigen::VectorXd& x);

// The UV map as the output gives it: without a cut or repair, in the input's
// numbering (#input V by 2; unreferenced vertices get (0, 0)); otherwise
// chart_uv (one row per vertex of the cut or repaired mesh: a seam vertex has
// one per side), then a row per interpolated corner of a face set aside.
Eigen::MatrixXd output_uv(const ParamSetup& setup, const Eigen::VectorXd& x);

// The rows of output_uv each input face's corners use (#F by 3, in the
// input's order): the input's F without a cut or repair (libigl's FTC).
Eigen::MatrixXi output_uv_faces(const ParamSetup& setup);

// A start map of the input's vertices (#V by 2, any scale and placement) as
// the optimizer's x (compacted, in area-1 units, at the best uniform scale
// of the energy a run with `config` minimizes: uniform_scale.h). OptionsError
// for another shape; ValidationError for a coordinate that is not finite or
// an inverted triangle, named with `what` ("the start map inverts a
// triangle: triangle 12 ..."). With `allow_mirror`, a map that inverts every triangle (a
// mirror image, as tools with the other orientation convention write) is
// mirrored back, with a warning.
Eigen::VectorXd start_from_map(const ParamSetup& setup, const ParamConfig& config, const Eigen::MatrixXd& uv,
                               const std::string& what, bool allow_mirror, Warnings* warnings);

}  // namespace akvf
