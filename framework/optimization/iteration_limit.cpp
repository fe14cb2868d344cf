#include "framework/optimization/iteration_limit.h"

#include <algorithm>
#include <cmath>

#include "akvf/error.h"

namespace akvf {

std::string iteration_limit_message(const std::vector<IterationSummary>& trace, double gradient_tolerance,
                                    int max_iterations) {
  std::string message = "reached " + std::to_string(max_iterations) + " iterations";
  const auto first = std::find_if(trace.begin(), trace.end(), [](const IterationSummary& r) { return !r.warm_start; });
  const long steps = (trace.end() - first) - 1;
  if (steps < 2) return message;
  // Two blocks of a tenth of the run each (at least 10 iterations, at most
  // half), the last ones; each block's least gradient norm, so that a
  // gradient that oscillates from one iteration to the next (a line search
  // that alternates between step lengths) is compared at like points.
  const long block = std::min(steps / 2, std::max<long>(10, steps / 10));
  const auto least = [&](long begin, long end) {  // rows [begin, end) from the back
    double value = trace[trace.size() - 1 - begin].grad_norm;
    for (long i = begin; i < end; ++i) value = std::min(value, trace[trace.size() - 1 - i].grad_norm);
    return value;
  };
  const double to = least(0, block), from = least(block, 2 * block);
  const int last = trace.back().iteration;
  const auto span = [&](long begin, long end) {
    return std::to_string(last - end + 1) + "-" + std::to_string(last - begin);
  };
  message += "; the least gradient norm of iterations " + span(block, 2 * block) + " was " + number_text(from) +
             ", of " + span(0, block) + " " + number_text(to) + " (tolerance " + number_text(gradient_tolerance) + ")";
  if (!(to < from) || !(to > 0)) return message + ": it did not fall";
  if (!(gradient_tolerance > 0)) return message;    // no gradient target (a fixed budget)
  const double rate = std::log(to / from) / block;  // per iteration, < 0
  const double more = std::max(std::log(gradient_tolerance / to) / rate, 1.0);
  // Two significant digits: the rate is a rough one.
  const double unit = std::pow(10.0, std::max(0.0, std::floor(std::log10(more)) - 1));
  return message + ": about " + number_text(std::ceil(more / unit) * unit) + " more iterations at that rate";
}

}  // namespace akvf
