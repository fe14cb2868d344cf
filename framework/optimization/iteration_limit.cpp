#include "framework/optimization/iteration_limit.h"

#include <algorithm>
#include <cmath>

#include "akvf/error.h"

namespace akvf {

std::string iteration_limit_message(const std::vector<IterationSummary>& trace, double gradient_tolerance,
                                    int max_iterations) {
  std::string message = "reached " + std::to_string(max_iterations) + " iterations";
  const auto first = std::find_if(trace.begin(), trace.end(), [](const IterationSummary& r) { return !r.warm_start; });
  const long rows = trace.end() - first;
  if (rows < 2) return message;
  // The last tenth of the run, at least 10 iterations (or all there were).
  const int window = static_cast<int>(std::min<long>(rows - 1, std::max<long>(10, (rows - 1) / 10)));
  const double from = trace[trace.size() - 1 - window].grad_norm, to = trace.back().grad_norm;
  message += "; over the last " + std::to_string(window) + " the gradient norm ";
  const std::string range =
      "from " + number_text(from) + " to " + number_text(to) + " (tolerance " + number_text(gradient_tolerance) + ")";
  if (!(to < from) || !(to > 0)) return message + "did not fall: " + range;
  const double rate = std::log(to / from) / window;  // per iteration, < 0
  const double more = std::max(std::log(gradient_tolerance / to) / rate, 1.0);
  // Two significant digits: the rate is a rough one.
  const double unit = std::pow(10.0, std::max(0.0, std::floor(std::log10(more)) - 1));
  return message + "fell " + range + ": about " + number_text(std::ceil(more / unit) * unit) + " more at that rate";
}

}  // namespace akvf
