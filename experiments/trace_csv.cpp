#include "experiments/trace_csv.h"

#include <iomanip>

#include "framework/output_file.h"

namespace akvf {

void write_trace_csv(std::ostream& out, const OptimizerResult& result) {
  out << "iter,seconds,energy,grad_norm,step,ls_evals,flips,max_step,precond_seconds,line_search_seconds,status\n";
  out << std::setprecision(17);
  for (std::size_t i = 0; i < result.trace.size(); ++i) {
    const IterationSummary& s = result.trace[i];
    out << s.iteration << ',' << s.seconds << ',' << s.energy << ',' << s.grad_norm << ',' << s.step << ','
        << s.ls_evals << ',' << s.flips << ',' << s.max_step << ',' << s.precond_seconds << ',' << s.line_search_seconds
        << ',' << (i + 1 == result.trace.size() ? to_string(result.status) : "") << '\n';
  }
}

void write_trace_csv(const std::string& path, const OptimizerResult& result) {
  write_file_atomically(path, [&](std::ostream& out) { write_trace_csv(out, result); });
}

}  // namespace akvf
