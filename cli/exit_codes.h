#pragma once
// Process exit codes of the akvf program.
namespace akvf {

enum ExitCode : int {
  kExitOk = 0,                // finished normally (converged, or an iteration/time limit)
  kExitInputError = 1,        // the mesh file is malformed or the mesh is invalid
  kExitUsageError = 2,        // bad command line
  kExitOptimizerFailure = 3,  // line search or numerical failure; outputs hold the last valid iterate
  kExitOutputError = 4,       // an output file could not be written
  kExitInterrupted = 130,     // SIGINT/SIGTERM: outputs hold the last accepted iterate (128 + SIGINT)
};

}  // namespace akvf
