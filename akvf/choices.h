#pragma once
// The fixed choices of the options (ParameterizeOptions, DeformOptions) as
// enums, each with the words the command line, the manifests and Python
// use for it (choice_words), so that a name is checked where it is read and
// C++ code cannot misspell one.
#include <span>
#include <string>

namespace akvf {

// How a parameterization is minimized.
enum class Solver {
  kDescent,  // Algorithm 1: preconditioned, flip-free descent with `preconditioner`
  kLbfgs,    // L-BFGS through Ceres (no preconditioner)
};

// AQP's momentum (OptimizerOptions::acceleration_eta).
enum class Acceleration {
  kAuto,  // on for preconditioners tagged "momentum-by-default" (the Laplacian)
  kOn,
  kOff,
};

// The initial map of a parameterization.
enum class InitialMap {
  kAuto,           // one chart: the lowest in energy (swept once) of kTutte, kConformal and kBoundaryFirst
                   // where flip-free; else kTutte
  kTutte,          // Tutte's embedding, uniform weights
  kCotan,          // cotangent weights (uniform where they fold)
  kConformal,      // the least-squares conformal map (kTutte where it folds, or several charts)
  kBoundaryFirst,  // the boundary-first map, boundary lengths kept (kTutte where it folds, or several charts)
  kFile,           // the command line's: the mesh file's texture coordinates
};

// Meshes that are not one disk.
enum class Cut {
  kNone,   // refused, naming the reason
  kAuto,   // cut into one disk chart per component
  kSeams,  // kAuto, then seams until the symmetric Dirichlet energy is bounded
};

// Non-manifold input.
enum class Repair {
  kAuto,  // edges of 3+ faces opened, vertices split into one copy per fan, faces reoriented
  kNone,  // refused, naming the edge or vertex
};

// What the map must keep.
enum class Injectivity {
  kGlobal,  // no overlap in UV: every chart's boundary kept from crossing itself
  kLocal,   // every triangle positive only (the paper's Algorithm 1)
};

// How the preconditioners' linear systems are solved.
enum class LinearSolver {
  kAuto,     // CHOLMOD unless its factor would take more than half the memory, then kAmg
  kCholmod,  // sparse Cholesky
  kAmg,      // CG preconditioned by hypre's algebraic multigrid
};

// Projected Newton's treatment of each element Hessian's negative eigenvalues.
enum class EigenFilter {
  kAuto,      // kClamp for newton, kExact for akvf-newton's Newton phase
  kClamp,     // set to 0
  kAbsolute,  // mirrored
  kAdaptive,  // clamp while the last step matched its model to 1 %, else mirror (Chen et al. 2024)
  // unfiltered while the Hessian is positive definite, else the least
  // filtering that factors; clamped within ARAP's collapse barrier's range
  // and in the boundary barrier's terms until they settle
  kExact,
};

template <class Choice>
struct ChoiceWord {
  Choice choice;
  const char* word;  // a choice's first word is its name; later ones are aliases
};

// The words of each choice (the argument only selects the enum).

inline std::span<const ChoiceWord<Solver>> choice_words(Solver) {
  static constexpr ChoiceWord<Solver> words[] = {{Solver::kDescent, "descent"}, {Solver::kLbfgs, "lbfgs"}};
  return words;
}
inline std::span<const ChoiceWord<Acceleration>> choice_words(Acceleration) {
  static constexpr ChoiceWord<Acceleration> words[] = {
      {Acceleration::kAuto, "auto"}, {Acceleration::kOn, "on"}, {Acceleration::kOff, "off"}};
  return words;
}
inline std::span<const ChoiceWord<InitialMap>> choice_words(InitialMap) {
  static constexpr ChoiceWord<InitialMap> words[] = {{InitialMap::kAuto, "auto"},
                                                     {InitialMap::kTutte, "tutte"},
                                                     {InitialMap::kCotan, "cotan"},
                                                     {InitialMap::kConformal, "conformal"},
                                                     {InitialMap::kBoundaryFirst, "boundary-first"},
                                                     {InitialMap::kFile, "file"},
                                                     {InitialMap::kTutte, "uniform"},
                                                     {InitialMap::kCotan, "cotangent"},
                                                     {InitialMap::kConformal, "lscm"},
                                                     {InitialMap::kBoundaryFirst, "bff"}};
  return words;
}
inline std::span<const ChoiceWord<Cut>> choice_words(Cut) {
  static constexpr ChoiceWord<Cut> words[] = {{Cut::kNone, "none"}, {Cut::kAuto, "auto"}, {Cut::kSeams, "seams"}};
  return words;
}
inline std::span<const ChoiceWord<Repair>> choice_words(Repair) {
  static constexpr ChoiceWord<Repair> words[] = {{Repair::kAuto, "auto"}, {Repair::kNone, "none"}};
  return words;
}
inline std::span<const ChoiceWord<Injectivity>> choice_words(Injectivity) {
  static constexpr ChoiceWord<Injectivity> words[] = {{Injectivity::kGlobal, "global"}, {Injectivity::kLocal, "local"}};
  return words;
}
inline std::span<const ChoiceWord<LinearSolver>> choice_words(LinearSolver) {
  static constexpr ChoiceWord<LinearSolver> words[] = {
      {LinearSolver::kAuto, "auto"}, {LinearSolver::kCholmod, "cholmod"}, {LinearSolver::kAmg, "amg"}};
  return words;
}
inline std::span<const ChoiceWord<EigenFilter>> choice_words(EigenFilter) {
  static constexpr ChoiceWord<EigenFilter> words[] = {{EigenFilter::kAuto, "auto"},
                                                      {EigenFilter::kClamp, "clamp"},
                                                      {EigenFilter::kAbsolute, "abs"},
                                                      {EigenFilter::kAdaptive, "adaptive"},
                                                      {EigenFilter::kExact, "exact"}};
  return words;
}

// The name of a choice ("auto", "lbfgs", ...).
template <class Choice>
std::string choice_name(Choice choice) {
  for (const ChoiceWord<Choice>& entry : choice_words(choice))
    if (entry.choice == choice) return entry.word;
  return "?";
}

}  // namespace akvf
