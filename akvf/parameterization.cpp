#include "akvf/internal/parameterization.h"

#include <tbb/task_group.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <optional>

#include "akvf/catalog.h"
#include "akvf/error.h"
#include "akvf/internal/packing_splits.h"
#include "akvf/internal/preconditioner_settings.h"
#include "akvf/internal/seam_cutting.h"
#include "akvf/threads.h"
#include "framework/mesh/chart_layout.h"
#include "framework/mesh/fold_repair.h"
#include "framework/mesh/initialization.h"
#include "framework/mesh/plane_geometry.h"
#include "framework/mesh/vertex_graph.h"
#include "framework/optimization/boundary_first_map.h"
#include "framework/optimization/conformal_map.h"
#include "framework/optimization/element_matrix.h"
#include "framework/optimization/injective_objective.h"
#include "framework/optimization/local_newton_sweep.h"
#include "framework/optimization/uniform_scale.h"
#include "framework/process/interrupt.h"
#include "preconditioners/contact_preconditioner.h"
#include "solvers/lbfgs_solver.h"
#include "solvers/sparse_cholesky.h"

namespace akvf {

namespace {
// The energy whose minimizer starts energies that are infinite at the Tutte map.
constexpr const char* kWarmStartEnergy = "symmetric-dirichlet";

void warm_start(const ParamConfig& config, ParamSetup* setup);

// A start the optimizer can use: finite energy and gradient norm (the
// exponential energies overflow one or the other at the Tutte map).
bool usable_start(const Objective& objective, const Eigen::VectorXd& x) {
  Eigen::VectorXd gradient;
  const double energy = objective.value_and_gradient(x, &gradient);
  return std::isfinite(energy) && std::isfinite(gradient.norm());
}
ParamRun run_from_start(const ParamSetup& setup, const ParamConfig& config,
                        const std::vector<IterationCallback>& callbacks);

// The Tutte system's solver: CHOLMOD's supernodal Cholesky (with nested
// dissection on large meshes) from kCholmodTutteVertices on, Eigen's
// simplicial L D L^T below, where both take milliseconds and the maps of the
// committed results (docs/results.md, docs/pairs.md) were computed with it:
// the two factorizations round differently, and a start differing in its last
// bits can change an iteration count. The paper's largest mesh has 20 K
// vertices; at 1.27 M (horse_b subdivided three times) the setup of a run
// takes 10.3 s instead of 19.3 s.
constexpr int kCholmodTutteVertices = 100000;

// The vertex graph is ordered once for the optimizer's matrices (2 x 2
// blocks per vertex: the symbolic analysis of their first factorization
// takes it as given). From kCholmodTutteVertices on, the Tutte system (the
// interior vertices) is ordered by its restriction: one ordering of the mesh
// instead of two (horse_b x64: METIS takes about 7 s of each). Below, Eigen
// orders the Tutte system itself, and the mesh's ordering is found beside
// the Tutte solve, on a second thread where the arena has one (horse_b: 14
// ms of ordering beside 30 ms of Tutte solve, which runs on one thread),
// and with it the symbolic analysis of the 2 x 2-block pattern every
// factored preconditioner's matrix has, for the run's first factorization
// to take (SymbolicAnalysisCache::prepare); but not for global injectivity,
// whose factored matrix P + C has the barrier's entries beside the mesh's:
// there each analysis orders the graph it factors (milliseconds below
// kCholmodTutteVertices, seconds above).
bool tutte_by_cholmod(const TriMesh& mesh) { return mesh.num_vertices() >= kCholmodTutteVertices; }

std::shared_ptr<const BlockOrdering> mesh_vertex_ordering(const UpperVertexGraph& graph) {
  return std::make_shared<const BlockOrdering>(fill_reducing_ordering(graph, 2));
}

SpdSolver tutte_solver(const std::shared_ptr<const BlockOrdering>& ordering) {
  return [ordering](const Eigen::SparseMatrix<double>& A, const Eigen::MatrixXd& B, const std::vector<int>& vertices,
                    Eigen::MatrixXd* X) {
    const BlockOrdering restricted{restricted_order(*ordering, vertices), ordering->method};
    return solve_positive_definite(A, B, X, &restricted);
  };
}

// The boundary loops with the normalized mesh as their rest shape: its
// positions and each vertex's angle sum.
std::shared_ptr<const BoundaryContact> boundary_contact_of(const TriMesh& normalized,
                                                           const std::vector<std::vector<int>>& loops) {
  return std::make_shared<const BoundaryContact>(loops, normalized.V, vertex_angle_sums(normalized), normalized.F);
}

// Shortens the flap moves (§5.4) that make a chart's boundary cross itself,
// so that a globally injective run starts injective: a move in a crossing
// is halved, pass by pass, and undone after 30 halvings (the Tutte map's
// boundary is convex, so that ends with no crossing). Returns the number of
// moves shortened or undone.
int shorten_crossing_flaps(const BoundaryContact& contact, const Eigen::MatrixXd& tutte, Eigen::MatrixXd* UV) {
  std::vector<int> halvings(UV->rows(), 0);
  for (;;) {
    bool changed = false;
    for (const std::array<int, 4>& crossing : contact.crossings(stack_uv(*UV)))
      for (int v : crossing) {
        if (UV->row(v) == tutte.row(v)) continue;
        const Eigen::RowVector2d halfway = 0.5 * (UV->row(v) + tutte.row(v));
        UV->row(v) = ++halvings[v] > 30 ? Eigen::RowVector2d(tutte.row(v)) : halfway;
        changed = true;
      }
    if (!changed) break;
  }
  return static_cast<int>(std::count_if(halvings.begin(), halvings.end(), [](int n) { return n > 0; }));
}

// The solver of the conformal map's system: our supernodal Cholesky with
// the analysis of the 2 x 2-block pattern where the setup holds it, else
// analyzed with the mesh's ordering where there is one, or its own.
BlockSpdSolver conformal_solver(const ParamSetup& setup) {
  return [&setup](const Eigen::SparseMatrix<double>& upper, const Eigen::VectorXd& b, Eigen::VectorXd* x) {
    SparseCholesky cholesky;
    if (!setup.analyses || !setup.analyses->copy(upper, 2, &cholesky))
      cholesky.analyze(upper, 2, setup.vertex_ordering.get());
    try {
      cholesky.factorize(upper);
    } catch (const NotPositiveDefinite&) {
      return false;
    }
    cholesky.solve(b, x);
    return true;
  };
}

// A local Newton sweep over the objective's mesh. The sweeps see the
// distortion only: with the boundary barrier (global injectivity) they move
// the interior vertices, which the barrier does not involve (and a map
// without inverted triangles whose boundary does not cross itself is
// injective, so they keep it so).
LocalNewtonSweep<2> distortion_sweep(const ParamSetup& setup, bool global_injectivity) {
  std::vector<int> boundary;
  if (global_injectivity)
    for (const std::vector<int>& loop : setup.disk.boundary_loops)
      boundary.insert(boundary.end(), loop.begin(), loop.end());
  return LocalNewtonSweep<2>(*setup.objective, boundary);
}

// E after one pass of local Newton steps from x (share 1: the vertices of
// more than the mean squared gradient). A start's energy is often set by a few badly
// shaped triangles (a jittered vertex, a star moved out of a fold) that such
// a pass removes for the cost of a gradient, as the optimizer's own sweeps
// do, while the iterations go to the smooth distortion that no vertex alone
// removes; after one pass the energies compare the latter. One pass only:
// each further pass reaches one ring further and removes smooth distortion
// too.
double energy_after_one_sweep(const Objective& objective, const LocalNewtonSweep<2>& sweep, Eigen::VectorXd x) {
  Eigen::VectorXd gradient;
  if (!std::isfinite(objective.value_and_gradient(x, &gradient))) return objective.value(x);
  sweep.sweep(gradient, 1.0, &x);
  return objective.value(x);
}

// setup->x0 = `map` (a conformal map, `kind`, or empty if its system did
// not solve) at the energy's best uniform scale where it is flip-free once
// the vertices of its folds are moved into their stars' kernels (its folds
// are a few boundary triangles, fold_repair.h), its boundary does not
// cross itself with global injectivity, and, with ConformalStart::kAuto,
// its energy is below that of the start in setup->x0 (the Tutte map or a
// conformal map taken before; or that one's is not finite), both after one
// local sweep (energy_after_one_sweep): both are maps the optimizer can
// start from, and the lower one is nearer the minimum. On a developable
// disk a conformal map is an isometry, the minimum of every isometric
// energy; where a region is far from developable the least-squares map
// shrinks it exponentially, the boundary-first map less (its boundary
// keeps its lengths), and Tutte's map is often lower than both.
void take_conformal_start(const ParamConfig& config, ConformalStart mode, const Eigen::MatrixXd& map, InitialMap kind,
                          ParamSetup* setup) {
  const Objective& objective = *setup->objective;
  std::string why_not;
  Eigen::VectorXd x;
  std::vector<int> unfolded;
  if (map.rows() == 0) {
    why_not = "its system did not solve";
  } else {
    Eigen::MatrixXd unfolded_map = map;
    unfolded = unfold_by_star_kernels(setup->objective->elements(), &unfolded_map);
    x = stack_uv(unfolded_map);
    if (const int inverted = objective.count_inverted(x); inverted > 0)
      why_not = "it inverts " + std::to_string(inverted) + " triangle" + (inverted == 1 ? "" : "s");
    else if (config.global_injectivity && setup->boundary_contact->count_crossings(x) > 0)
      why_not = "its boundary crosses itself";
  }
  if (!why_not.empty()) {
    if (mode == ConformalStart::kAlways)
      setup->warnings.push_back("the " + std::string(choice_name(kind)) + " map is not the start: " + why_not +
                                "; starting from the Tutte map");
    return;
  }
  x *= best_uniform_scale(objective, x);
  if (mode == ConformalStart::kAuto) {
    const LocalNewtonSweep<2> sweep = distortion_sweep(*setup, config.global_injectivity);
    const double energy = energy_after_one_sweep(objective, sweep, x);
    if (!(std::isfinite(energy) && !(energy_after_one_sweep(objective, sweep, setup->x0) <= energy))) return;
  }
  setup->x0 = std::move(x);
  setup->flaps_moved = 0;
  setup->flaps_shortened = 0;
  setup->folds_unfolded = static_cast<int>(unfolded.size());
  setup->initial_map = kind;
}

// setup->x0 = the Tutte map of the charts of `normalized` (+ flaps), or the
// conformal map of the one chart where take_conformal_start takes it (asked
// for by config.conformal), and setup->vertex_ordering, the mesh's where it is
// used (mesh_vertex_ordering), with K's analysis in setup->analyses where it
// is found beside. The conformal map is computed beside the Tutte solve too.
void start_at_tutte_map(const ParamConfig& config, const TriMesh& normalized, ParamSetup* setup) {
  // The run's threads, the dense kernels' (OpenBLAS) included: the conformal
  // map's factor has the bits of the same thread count wherever the setup runs.
  const ThreadLimit threads(config.threads);
  tbb::task_group beside;
  SpdSolver solver;  // Eigen's
  const bool one_chart = setup->disk.boundary_loops.size() == 1;
  const bool least_squares_tried = config.conformal != ConformalStart::kNever && one_chart;
  const bool boundary_first_tried = config.boundary_first != ConformalStart::kNever && one_chart;
  const bool conformal_tried = least_squares_tried || boundary_first_tried;
  if ((config.conformal == ConformalStart::kAlways || config.boundary_first == ConformalStart::kAlways) && !one_chart)
    setup->warnings.push_back("a conformal map is the start of one chart; these " +
                              std::to_string(setup->disk.boundary_loops.size()) + " charts start from the Tutte map");
  Eigen::MatrixXd conformal, boundary_first;
  // Both beside the Tutte solve; the boundary-first map's two systems have
  // the Tutte system's pattern and take its solver.
  const auto conformal_of = [&] {
    if (least_squares_tried)
      conformal = conformal_map(normalized, setup->objective->rest(), setup->disk.boundary_loops.front(),
                                conformal_solver(*setup));
    if (boundary_first_tried)
      boundary_first = boundary_first_map(normalized, setup->disk.boundary_loops.front(), solver);
  };
  if (tutte_by_cholmod(normalized)) {
    const UpperVertexGraph graph = upper_vertex_graph(normalized.F, normalized.num_vertices());
    setup->vertex_ordering = mesh_vertex_ordering(graph);
    solver = tutte_solver(setup->vertex_ordering);
    if (conformal_tried && !config.global_injectivity) {
      if (!setup->analyses) setup->analyses = std::make_shared<SymbolicAnalysisCache>();
      beside.run([&, pattern = block_upper_pattern<2>(graph)] {
        setup->analyses->prepare(pattern, 2, setup->vertex_ordering.get());
        conformal_of();
      });
    } else {
      beside.run(conformal_of);
    }
  } else if (!config.global_injectivity) {
    if (!setup->analyses) setup->analyses = std::make_shared<SymbolicAnalysisCache>();
    beside.run([&] {
      const UpperVertexGraph graph = upper_vertex_graph(normalized.F, normalized.num_vertices());
      setup->vertex_ordering = mesh_vertex_ordering(graph);
      setup->analyses->prepare(block_upper_pattern<2>(graph), 2, setup->vertex_ordering.get());
      conformal_of();
    });
  } else {
    beside.run(conformal_of);  // ordered and analyzed there (the run's matrices have the barrier's entries too)
  }
  Eigen::MatrixXd UV;
  try {
    UV = tutte_embedding_charts(normalized, setup->disk.boundary_loops, setup->disk.face_chart, config.init,
                                &setup->warnings, solver);
  } catch (...) {
    beside.wait();
    throw;
  }
  beside.wait();
  if (config.optimize_flaps) {
    const Eigen::MatrixXd tutte = UV;
    setup->flaps_moved = optimize_flaps(normalized, &UV);
    if (config.global_injectivity)
      setup->flaps_shortened = shorten_crossing_flaps(*setup->boundary_contact, tutte, &UV);
  }
  setup->x0 = stack_uv(UV);
  setup->initial_map = config.init == TutteWeights::kCotangent ? InitialMap::kCotan : InitialMap::kTutte;
  if (least_squares_tried) take_conformal_start(config, config.conformal, conformal, InitialMap::kConformal, setup);
  if (boundary_first_tried)
    take_conformal_start(config, config.boundary_first, boundary_first, InitialMap::kBoundaryFirst, setup);
}

}  // namespace

ParamSetup prepare_parameterization(const TriMesh& input, const std::string& name, const ParamConfig& config) {
  std::string invalid;
  if (!config.optimizer.is_valid(&invalid)) throw OptionsError(invalid);
  if (!config.line_search_settings.is_valid(&invalid)) throw OptionsError(invalid);
  // Resolve names first so a typo fails before any work.
  std::shared_ptr<const DistortionDensity2D> density = energies_2d().create(config.energy, config.energy_settings);
  require_method(config.preconditioner);
  line_searches().require(config.line_search);

  ParamSetup setup;
  // An exact power-of-two scale first, so that the checks and the Tutte solve
  // see a mesh of extent about 1 whatever the input's units (1e-100 to 1e+100).
  setup.unit_scale = power_of_two_unit_scale(input.V, name);
  setup.gutter = config.gutter;
  setup.min_coverage = config.min_coverage;
  TriMesh unit_input = input;
  unit_input.V *= setup.unit_scale;
  if (config.cut && config.init_from_file)
    throw OptionsError(
        "init 'file' and cut 'auto' cannot be combined: a file's texture coordinates bring their own "
        "seams; start from them without the cut, or cut and start from the Tutte map");
  setup.disk = prepare_disk_mesh(unit_input, name, config.cut, config.repair);
  setup.warnings = setup.disk.warnings;
  TriMesh normalized = setup.disk.mesh;
  setup.normalization = normalize_to_unit_area(&normalized);

  setup.analyses = config.preconditioner_settings.akvf.factor.analysis_cache;
  setup.objective = std::make_shared<DistortionObjective2D>(normalized.F, rest_triangles(normalized), density,
                                                            normalized.num_vertices());
  setup.objective->set_file_numbering(setup.disk.input_vertex, input.index_base);
  setup.boundary_contact = boundary_contact_of(normalized, setup.disk.boundary_loops);
  if (config.init_from_file) {
    if (config.start_uv.rows() == 0)
      throw OptionsError(
          "init 'file' starts from the texture coordinates of the mesh file (akvf param --init file with an OBJ "
          "that has vt or a PLY with u,v); through the API pass the start map instead (Parameterizer::solve(uv0), "
          "Python uv0=)");
    setup.x0 =
        start_from_map(setup, config, config.start_uv, name + ": the texture coordinates", true, &setup.warnings);
    setup.initial_map = InitialMap::kFile;
  } else {
    start_at_tutte_map(config, normalized, &setup);
  }
  if (!usable_start(*setup.objective, setup.x0) && config.energy != kWarmStartEnergy) warm_start(config, &setup);
  return setup;
}

namespace {

// The warm start's rows ahead of the run's, and its time added to the run's
// clock (the run's seconds column is cumulative).
void prepend_warm_start(const OptimizerResult& warm, OptimizerResult* result) {
  if (warm.trace.empty()) return;
  const double warm_seconds = warm.trace.back().seconds;
  for (IterationSummary& row : result->trace) row.seconds += warm_seconds;
  result->trace.insert(result->trace.begin(), warm.trace.begin(), warm.trace.end());
}

}  // namespace

bool stop_on_signal(OptimizerResult* result) {
  if (stop_asked(result->status)) return true;
  if (!interrupt_requested()) return false;
  result->status = TerminationStatus::kInterrupted;
  result->message = "interrupted by a signal";
  return true;
}

ParamRun run_parameterization(const ParamSetup& setup, const ParamConfig& config,
                              const std::vector<IterationCallback>& callbacks) {
  const ThreadLimit threads(config.threads);
  ParamRun run;
  // The rounds of seams and the cuts for the packing look for a signal
  // between their steps, as the optimizer does between iterations.
  std::optional<InterruptibleLoop> interruptible;
  if (config.seams) {
    interruptible.emplace();
    run = run_with_seams(setup, config, callbacks);
  } else {
    run = optimize_from_start(setup, config, callbacks);
    measure_final_map(setup, &run);
    if (config.cut) interruptible.emplace();
  }
  split_for_packing(setup, config, callbacks, &run);
  return run;
}

namespace {

// The warm start left the map near the run's minimum: within a factor e of
// the energy's infimum E_lb. The warm-started energies are exponentials,
// E = exp(f), on which Newton's steps lower f by only about 1 per
// iteration far from the minimum and AKVF's by more
// (switching_preconditioner.h); within that factor one Newton step covers
// what is left of f.
bool warm_start_near_minimum(const ParamSetup& setup) {
  if (setup.warm_start.trace.empty() || setup.warm_start.x != setup.x0) return false;
  return setup.objective->value(setup.x0) < std::exp(1.0) * setup.objective->lower_bound();
}

}  // namespace

ParamRun optimize_from_start(const ParamSetup& setup, const ParamConfig& config,
                             const std::vector<IterationCallback>& callbacks, bool near_minimum) {
  const bool newton_phase = config.preconditioner == "akvf-newton" && (near_minimum || warm_start_near_minimum(setup));
  ParamConfig used = config;
  if (newton_phase) {
    used.preconditioner = "newton";
    used.preconditioner_settings.newton = config.preconditioner_settings.newton_phase;
    used.preconditioner_settings.newton_filter = config.preconditioner_settings.newton_phase_filter;
  }
  ParamRun run = run_from_start(setup, used, callbacks);
  prepend_warm_start(setup.warm_start, &run.result);
  if (newton_phase) {
    run.preconditioner_report = "from the start " + run.preconditioner_name + ": " + run.preconditioner_report;
    run.preconditioner_name = config.preconditioner;
  }
  return run;
}

void measure_final_map(const ParamSetup& setup, ParamRun* run) {
  const Eigen::VectorXd& x = run->result.x;
  run->boundary_crossings = setup.boundary_contact->count_crossings(x);
  run->overlap = measure_uv_overlap(unstack_uv(x), setup.objective->elements(), setup.disk.face_chart);
  run->distortion_energy = setup.objective->value(x);
}

void rebuild_problem(const ParamConfig& config, ParamSetup* setup, bool tutte_start) {
  TriMesh normalized = setup->disk.mesh;
  apply_normalization(setup->normalization, &normalized);
  const Eigen::MatrixXi& F = normalized.F;
  auto objective = std::make_shared<DistortionObjective2D>(F, setup->objective->rest(),
                                                           energies_2d().create(config.energy, config.energy_settings),
                                                           normalized.num_vertices());
  objective->set_file_numbering(setup->disk.input_vertex, normalized.index_base);
  setup->objective = std::move(objective);
  setup->boundary_contact = boundary_contact_of(normalized, setup->disk.boundary_loops);
  setup->vertex_ordering = nullptr;                                             // of the old vertices
  setup->analyses = config.preconditioner_settings.akvf.factor.analysis_cache;  // no old mesh's analysis kept
  setup->warm_start = {};
  if (tutte_start) start_at_tutte_map(config, normalized, setup);
}

namespace {

// The boundary barrier's objective wrapping setup's distortion when the run
// keeps the map globally injective, else null: the run minimizes it.
std::unique_ptr<InjectiveObjective> injective_objective(const ParamSetup& setup, const ParamConfig& config) {
  if (!config.global_injectivity) return nullptr;
  return std::make_unique<InjectiveObjective>(*setup.objective, setup.boundary_contact,
                                              injective_step_horizon(config.line_search_settings.max_initial_step,
                                                                     config.line_search_settings.max_step_fraction));
}

ParamRun run_from_start(const ParamSetup& setup, const ParamConfig& config,
                        const std::vector<IterationCallback>& callbacks) {
  ParamRun run;
  const std::unique_ptr<InjectiveObjective> injective = injective_objective(setup, config);
  const Objective& objective = injective ? static_cast<const Objective&>(*injective) : *setup.objective;
  OptimizerOptions optimizer = config.optimizer;
  optimizer.acceleration_eta =
      acceleration_eta(config.acceleration, preconditioners_2d().has_tag(config.preconditioner, kMomentumByDefault));
  if (config.solver == Solver::kLbfgs || config.preconditioner == kLbfgsMethod) {
    run.preconditioner_name = kLbfgsMethod;
    run.result = minimize_lbfgs(objective, setup.x0, config.optimizer, {}, callbacks);  // no momentum
    return run;
  }
  PreconditionerSettings2D settings = config.preconditioner_settings;
  settings.set_linear_solver(available_linear_solver(config.linear_solver));
  settings.share_vertex_ordering(setup.vertex_ordering);
  if (setup.analyses) settings.share_analyses(setup.analyses);
  settings.akvf_newton_switch.backtracking_factor = config.line_search_settings.rho;
  // The barrier's curvature goes into a factored P (contact_curvature.h),
  // or, for the others, into a low-rank update of theirs.
  const bool takes_contact = preconditioners_2d().has_tag(config.preconditioner, kTakesContactCurvature);
  if (injective && takes_contact)
    settings.share_contact_curvature(
        std::make_shared<ContactCurvature>(setup.boundary_contact, setup.objective->num_vertices()));
  std::unique_ptr<Preconditioner> preconditioner =
      preconditioners_2d().create(config.preconditioner, *setup.objective, settings);
  if (injective && !takes_contact)
    preconditioner = std::make_unique<ContactPreconditioner>(std::move(preconditioner), setup.boundary_contact);
  auto line_search = line_searches().create(
      config.line_search, line_search_settings(config.line_search_settings, optimizer.acceleration_eta));
  std::optional<LocalNewtonSweep<2>> sweep;
  if (config.local_sweep > 0) {
    sweep.emplace(distortion_sweep(setup, injective != nullptr));
    optimizer.after_bound_set_step = [&](const Eigen::VectorXd& gradient, Eigen::VectorXd* x) {
      if (preconditioner->has_element_curvature()) return false;
      return sweep->sweep(gradient, config.local_sweep, x) > 0;
    };
  }
  run.preconditioner_name = preconditioner->name();
  run.result = minimize(objective, *preconditioner, *line_search, setup.x0, optimizer, callbacks);
  run.preconditioner_report = preconditioner->report();
  run.preconditioner_statistics = preconditioner->statistics();
  return run;
}

}  // namespace

Eigen::MatrixXd chart_uv(const ParamSetup& setup, const Eigen::VectorXd& x) {
  // The normalization undone, and nothing else: the input mesh with this
  // map has the optimizer's energy (every energy here depends on J alone,
  // and J is unchanged when mesh and map scale alike).
  const double scale = 1 / (setup.normalization.scale * setup.unit_scale);
  Eigen::MatrixXd out = scale * unstack_uv(x);
  pack_charts(setup.objective->elements(), setup.disk.face_chart, setup.disk.num_charts(), &out, true, setup.gutter,
              PackingGrid::kFine, setup.min_coverage);
  return out;
}

namespace {

// The UV row of each corner of a face set aside (disk.removed_corners): its
// own vertex's row, or a new row after the parameterized vertices' (one per
// interpolated corner, in order); *added counts the new rows.
std::vector<std::array<int, 3>> removed_corner_rows(const DiskMesh& disk, int* added) {
  std::vector<std::array<int, 3>> rows(disk.removed_corners.size());
  int next = disk.mesh.num_vertices();
  for (std::size_t i = 0; i < rows.size(); ++i)
    for (int k = 0; k < 3; ++k) {
      const CornerSource& source = disk.removed_corners[i][k];
      rows[i][k] = source.a >= 0 && source.a == source.b ? source.a : next++;
    }
  *added = next - disk.mesh.num_vertices();
  return rows;
}

}  // namespace

Eigen::MatrixXd output_uv(const ParamSetup& setup, const Eigen::VectorXd& x) {
  const Eigen::MatrixXd UV = chart_uv(setup, x);
  const DiskMesh& disk = setup.disk;
  if (!disk.per_corner_uv()) {
    Eigen::MatrixXd out = Eigen::MatrixXd::Zero(disk.num_input_vertices, 2);
    for (int v = 0; v < UV.rows(); ++v) out.row(disk.input_vertex[v]) = UV.row(v);
    return out;
  }
  int added = 0;
  const std::vector<std::array<int, 3>> rows = removed_corner_rows(disk, &added);
  Eigen::MatrixXd out(UV.rows() + added, 2);
  out.topRows(UV.rows()) = UV;
  for (std::size_t i = 0; i < rows.size(); ++i)
    for (int k = 0; k < 3; ++k) {
      const CornerSource& source = disk.removed_corners[i][k];
      if (rows[i][k] < UV.rows()) continue;
      out.row(rows[i][k]).setZero();
      if (source.a >= 0) out.row(rows[i][k]) = (1 - source.t) * UV.row(source.a) + source.t * UV.row(source.b);
    }
  return out;
}

Eigen::MatrixXi output_uv_faces(const ParamSetup& setup) {
  const DiskMesh& disk = setup.disk;
  // The corners in the file's winding: reversed faces turned back (a copy
  // only then).
  Eigen::MatrixXi turned_back;
  if (!disk.reoriented_faces.empty()) {
    turned_back = disk.mesh.F;
    for (int f : disk.reoriented_faces) std::swap(turned_back(f, 1), turned_back(f, 2));
  }
  const Eigen::MatrixXi& F = disk.reoriented_faces.empty() ? disk.mesh.F : turned_back;
  if (!disk.per_corner_uv()) return F.unaryExpr([&](int v) { return disk.input_vertex[v]; });
  if (disk.removed_faces.empty()) return F;
  int added = 0;
  const std::vector<std::array<int, 3>> rows = removed_corner_rows(disk, &added);
  Eigen::MatrixXi out(F.rows() + static_cast<Eigen::Index>(rows.size()), 3);
  for (int f = 0; f < F.rows(); ++f) out.row(disk.input_face[f]) = F.row(f);
  for (std::size_t i = 0; i < rows.size(); ++i)
    for (int k = 0; k < 3; ++k) out(disk.removed_faces[i], k) = rows[i][k];
  return out;
}

Eigen::VectorXd start_from_map(const ParamSetup& setup, const ParamConfig& config, const Eigen::MatrixXd& uv,
                               const std::string& what, bool allow_mirror, Warnings* warnings) {
  if (setup.disk.cut)
    throw OptionsError("a start map cannot be given with cut 'auto' (the cut mesh's seams are not the input's)");
  if (uv.rows() != setup.disk.num_input_vertices || uv.cols() != 2)
    throw OptionsError(what + " must be #V by 2 (" + std::to_string(setup.disk.num_input_vertices) + " by 2), found " +
                       std::to_string(uv.rows()) + " by " + std::to_string(uv.cols()));
  // The optimizer works on the mesh scaled to area 1: the map is scaled
  // alike (its vertices in the compacted numbering).
  const double scale = setup.unit_scale * setup.normalization.scale;
  Eigen::MatrixXd compact(setup.disk.mesh.num_vertices(), 2);
  for (int v = 0; v < compact.rows(); ++v) compact.row(v) = scale * uv.row(setup.disk.input_vertex[v]);
  if (!compact.allFinite()) throw ValidationError(what + " has a coordinate that is not finite");
  Eigen::VectorXd x0 = stack_uv(compact);
  const int inverted = setup.objective->count_inverted(x0);
  if (allow_mirror && inverted == setup.disk.mesh.num_faces()) {
    compact.col(0) *= -1;
    x0 = stack_uv(compact);
    if (warnings)
      warnings->push_back(what + " invert every triangle (the other orientation convention): mirrored (u -> -u)");
  } else if (inverted > 0) {
    throw ValidationError(what + (allow_mirror ? " invert a triangle: " : " inverts a triangle: ") +
                          setup.objective->first_bad_element(x0));
  }
  // Scaled to the mesh's area (1 here), then to the best uniform scale of
  // the energy the run minimizes (with the boundary barrier under global
  // injectivity): a texture's unit square or any other scale starts alike,
  // and a saved result restarts at the energy it ended with.
  x0 /= std::sqrt(map_area(setup.objective->elements(), compact));
  const std::unique_ptr<InjectiveObjective> injective = injective_objective(setup, config);
  return best_uniform_scale(injective ? static_cast<const Objective&>(*injective) : *setup.objective, x0) * x0;
}

namespace {

// The run's energy with other settings, on the setup's mesh.
std::shared_ptr<DistortionObjective2D> objective_with(const ParamSetup& setup, const std::string& energy,
                                                      const EnergySettings& settings) {
  return std::make_shared<DistortionObjective2D>(setup.objective->elements(), setup.objective->rest(),
                                                 energies_2d().create(energy, settings),
                                                 setup.objective->num_vertices());
}

// One stage of the warm start: `energy` with `settings` minimized from x0
// with the default method (gradient 1e-3, at most `max_iterations`).
OptimizerResult warm_stage(const ParamConfig& config, const ParamSetup& setup, const std::string& energy,
                           const EnergySettings& settings, const Eigen::VectorXd& x0, int max_iterations) {
  ParamConfig stage;
  stage.energy = energy;
  stage.energy_settings = settings;
  stage.global_injectivity = config.global_injectivity;
  stage.optimizer.max_iterations = max_iterations;
  ParamSetup stage_setup = setup;
  stage_setup.analyses = nullptr;  // the prepared analysis is the run's (statistics.symbolic_analyses)
  stage_setup.objective = objective_with(setup, energy, settings);
  stage_setup.x0 = x0;
  return run_from_start(stage_setup, stage, {}).result;
}

// The stage's rows after the warm start's, numbered on and on its clock
// (its row 0, the map the last stage ended at, is left out).
void append_stage(OptimizerResult stage, OptimizerResult* warm) {
  const IterationSummary& last = warm->trace.back();
  const int iterations = last.iteration;
  const double seconds = last.seconds;
  for (std::size_t i = 1; i < stage.trace.size(); ++i) {
    IterationSummary row = stage.trace[i];
    row.iteration += iterations;
    row.seconds += seconds;
    warm->trace.push_back(row);
  }
  warm->status = stage.status;
  warm->message = std::move(stage.message);
  warm->x = std::move(stage.x);
}

// "12 iterations, status converged, energy ..., gradient norm ...".
std::string stage_summary(const OptimizerResult& stage) {
  const IterationSummary& last = stage.trace.back();
  char text[200];
  std::snprintf(text, sizeof text, "%d iterations, status %s, energy %.10g, gradient norm %.3e", last.iteration,
                to_string(stage.status).c_str(), last.energy, last.grad_norm);
  return text;
}

// Halvings of the exponent tried for a continuation stage: k / 2^40 is
// about 1e-12 k.
constexpr int kMaxExponentHalvings = 40;

// The largest exponent k / 2^j (j >= 1) above `above` at which the run's
// energy is finite at x, or 0.
double finite_exponent(const ParamConfig& config, const ParamSetup& setup, const Eigen::VectorXd& x, double above) {
  double exponent = config.energy_settings.exponent;
  for (int j = 1; j <= kMaxExponentHalvings; ++j) {
    exponent /= 2;
    if (!(exponent > above)) return 0;
    EnergySettings settings = config.energy_settings;
    settings.exponent = exponent;
    if (usable_start(*objective_with(setup, config.energy, settings), x)) return exponent;
  }
  return 0;
}

void warm_start(const ParamConfig& config, ParamSetup* setup) {
  // The exponential energies overflow at the Tutte map's slivers. Start them
  // instead from the symmetric Dirichlet map reached by the default method
  // (gradient 1e-3; the warm start's iterations in all are limited).
  const int limit = config.warm_start_max_iterations;
  OptimizerResult warm = warm_stage(config, *setup, kWarmStartEnergy, {}, setup->x0, limit);
  std::string map = warm.status == TerminationStatus::kConverged ? "the symmetric Dirichlet minimizer"
                                                                 : "the symmetric Dirichlet map reached";
  std::string reached = stage_summary(warm);
  // A sliver that map leaves stretched (symmetric Dirichlet in the hundreds)
  // is a tiny share of the mean it minimizes, but exp(k f) overflows there.
  // Continuation in k: the energy with the largest exponent k / 2^j finite
  // at the map is minimized from it, which pulls the largest f down (the
  // exponential weighs it most), and again from its minimizer, until k
  // itself is finite. Each stage's exponent is above the last's.
  // A stage that stalled or found no lower point (E's round-off: the
  // exponential's values are huge where a spike cannot be flattened) has
  // gone as far as its exponent takes it, and the next starts there.
  auto went_its_way = [](TerminationStatus status) {
    return status == TerminationStatus::kConverged || status == TerminationStatus::kStalled ||
           status == TerminationStatus::kLineSearchFailed;
  };
  double exponent = 0;
  std::string exponents;
  while (went_its_way(warm.status) && warm.trace.back().iteration < limit && !usable_start(*setup->objective, warm.x)) {
    exponent = finite_exponent(config, *setup, warm.x, exponent);
    if (exponent == 0) break;
    EnergySettings settings = config.energy_settings;
    settings.exponent = exponent;
    OptimizerResult stage =
        warm_stage(config, *setup, config.energy, settings, warm.x, limit - warm.trace.back().iteration);
    char with[40];
    std::snprintf(with, sizeof with, "%.6g", exponent);
    exponents += (exponents.empty() ? "" : ", then ") + std::string(with);
    reached += "; then with exponent " + std::string(with) + ": " + stage_summary(stage);
    append_stage(std::move(stage), &warm);
  }
  if (!exponents.empty()) map += " minimized further with the exponent " + exponents;
  for (IterationSummary& row : warm.trace) row.warm_start = true;
  setup->warm_start = std::move(warm);
  if (setup->warm_start.status == TerminationStatus::kNumericalFailure ||
      !usable_start(*setup->objective, setup->warm_start.x)) {
    setup->warnings.push_back(config.energy + " overflows (energy or gradient not finite) at the initial map and at " +
                              map + " (" + reached + "); the run will stop at once" +
                              (exponents.empty() ? "" : " (a smaller exponent may keep the energy finite)"));
    return;
  }
  setup->x0 = setup->warm_start.x;
  setup->warnings.push_back(
      config.energy + " overflows (energy or gradient not finite) at the initial map; starting from " + map +
      " instead (warm start: " + reached + "; its rows open the trace, marked warm-start, and its time is counted)");
}

}  // namespace
}  // namespace akvf
