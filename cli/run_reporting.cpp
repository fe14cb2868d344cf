#include "cli/run_reporting.h"

#include <cstdio>
#include <filesystem>

#include "akvf/error.h"
#include "cli/exit_codes.h"

namespace akvf {

IterationCallback progress_printer(std::ostream& err) {
  return [&err](const IterationSummary& s, const Eigen::VectorXd&) {
    char line[200];
    std::snprintf(line, sizeof line, "iter %4d  t %8.3fs  E %.10g  |g| %.3e  step %.2e  ls %3d  flips %d\n",
                  s.iteration, s.seconds, s.energy, s.grad_norm, s.step, s.ls_evals, s.flips);
    err << line << std::flush;
    return CallbackAction::kContinue;
  };
}

std::string summary_line(const OptimizerResult& result) {
  const IterationSummary& last = result.trace.back();
  char summary[1024];
  std::snprintf(
      summary, sizeof summary, "status %s after %d iterations, %.3f s: energy %.10g, gradient norm %.3e, %d inverted\n",
      status_with_reason(result).c_str(), last.iteration, last.seconds, last.energy, last.grad_norm, last.flips);
  if (result.status == TerminationStatus::kMaxIterations && !result.message.empty())
    return summary + ("not converged: " + result.message + "\n");
  return summary;
}

int exit_code_of(const OptimizerResult& result) {
  if (result.status == TerminationStatus::kInterrupted) return kExitInterrupted;
  return is_normal_termination(result.status) ? kExitOk : kExitOptimizerFailure;
}

}  // namespace akvf
