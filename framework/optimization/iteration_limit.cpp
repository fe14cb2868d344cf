#include "framework/optimization/iteration_limit.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "akvf/error.h"

namespace akvf {

namespace {

// value to two significant digits by `rounding` (std::round, std::ceil):
// the rates and medians here are rough.
std::string two_digits(double value, double (*rounding)(double) = std::round) {
  if (!(value > 0)) return number_text(value);
  const double unit = std::pow(10.0, std::floor(std::log10(value)) - 1);
  return number_text(rounding(value / unit) * unit);
}

double median(std::vector<double> values) {
  const auto middle = values.begin() + static_cast<long>(values.size() / 2);
  std::nth_element(values.begin(), middle, values.end());
  return *middle;
}

}  // namespace

std::string step_diagnosis(const std::vector<IterationSummary>& rows) {
  std::vector<double> shortened;  // step / first trial, where the search took less than its first trial
  std::vector<double> cut;        // the step, where the bound set the first trial and it was taken
  std::size_t lengthened = 0, own = 0, known = 0;
  for (const IterationSummary& row : rows) {
    if (!(row.initial_step > 0) || row.warm_start) continue;  // the search did not say
    ++known;
    if (row.step < row.initial_step)
      shortened.push_back(row.step / row.initial_step);
    else if (row.step > row.initial_step)
      ++lengthened;  // a Wolfe search's growth
    else if (row.bound_cut_initial_step)
      cut.push_back(row.step);
    else
      ++own;
  }
  if (known == 0) return "";
  const auto of = [&](std::size_t n) { return std::to_string(n) + " of the last " + std::to_string(known); };
  if (2 * shortened.size() > known)
    return "; the line search shortened " + of(shortened.size()) + " first trials (to a median " +
           two_digits(median(shortened)) +
           " of them): the preconditioner's model is softer than the energy along its directions";
  if (2 * lengthened > known)
    return "; the line search lengthened " + of(lengthened) +
           " first trials: the preconditioner's model is stiffer than the energy along its directions";
  if (2 * cut.size() > known)
    return "; the flip-free bound cut " + of(cut.size()) + " first trials (to a median step of " +
           two_digits(median(cut)) + "): elements near collapse hold the steps";
  if (2 * own > known)
    return "; " + of(own) +
           " steps were the direction's own, accepted at once: the preconditioner's model is stiffer than the energy "
           "in some directions, where the steps fall short";
  return "; of the last " + std::to_string(known) + " steps the line search shortened " +
         std::to_string(shortened.size()) + (lengthened > 0 ? ", lengthened " + std::to_string(lengthened) : "") +
         ", the flip-free bound cut " + std::to_string(cut.size()) + ", " + std::to_string(own) +
         " were the direction's own";
}

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
  const std::vector<IterationSummary> last_block(trace.end() - block, trace.end());
  if (!(to < from) || !(to > 0)) return message + ": it did not fall" + step_diagnosis(last_block);
  if (!(gradient_tolerance > 0)) return message + step_diagnosis(last_block);  // no gradient target (a fixed budget)
  const double rate = std::log(to / from) / block;                             // per iteration, < 0
  const double more = std::max(std::log(gradient_tolerance / to) / rate, 1.0);
  return message + ": about " + two_digits(std::ceil(more), std::ceil) + " more iterations at that rate" +
         step_diagnosis(last_block);
}

}  // namespace akvf
