#pragma once
// The columns of a run's trace, in one place: the trace CSV
// (experiments/report/trace_csv.h) and the Python module's `trace` dict have
// these, in this order, then `status`. A column marked `optional` is there
// only for the runs that have it (constraint_distance: runs with positional
// constraints), decided by the trace's first row.
#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "akvf/optimizer.h"

namespace akvf {

struct TraceColumn {
  const char* name;
  bool integer;  // written without a fraction
  double (*value)(const IterationSummary&);
  bool optional = false;  // NaN for the runs that do not have it (module comment)
};

inline const std::array<TraceColumn, 11>& trace_columns() {
  static const std::array<TraceColumn, 11> columns{{
      {"iter", true, [](const IterationSummary& s) { return double(s.iteration); }},
      {"seconds", false, [](const IterationSummary& s) { return s.seconds; }},
      {"energy", false, [](const IterationSummary& s) { return s.energy; }},
      {"grad_norm", false, [](const IterationSummary& s) { return s.grad_norm; }},
      {"step", false, [](const IterationSummary& s) { return s.step; }},
      {"ls_evals", true, [](const IterationSummary& s) { return double(s.ls_evals); }},
      {"flips", true, [](const IterationSummary& s) { return double(s.flips); }},
      {"max_step", false, [](const IterationSummary& s) { return s.max_step; }},
      {"precond_seconds", false, [](const IterationSummary& s) { return s.precond_seconds; }},
      {"line_search_seconds", false, [](const IterationSummary& s) { return s.line_search_seconds; }},
      {"constraint_distance", false, [](const IterationSummary& s) { return s.constraint_distance; }, true},
  }};
  return columns;
}

// The columns a trace whose first row is `first` has.
inline std::vector<const TraceColumn*> present_trace_columns(const IterationSummary& first) {
  std::vector<const TraceColumn*> present;
  for (const TraceColumn& column : trace_columns())
    if (!column.optional || !std::isnan(column.value(first))) present.push_back(&column);
  return present;
}

// The columns of a whole trace (its first row's; an empty trace has the
// columns every run has).
inline std::vector<const TraceColumn*> present_trace_columns(const std::vector<IterationSummary>& trace) {
  return present_trace_columns(trace.empty() ? IterationSummary{} : trace.front());
}

// The status column: on the last row why the run stopped (`final_status`,
// as status_with_reason gives it), "warm-start" on the rows of a warm start,
// empty elsewhere.
inline std::string trace_status_cell(const std::vector<IterationSummary>& trace, std::size_t row,
                                     const std::string& final_status) {
  if (row + 1 == trace.size()) return final_status;
  return trace[row].warm_start ? "warm-start" : "";
}

}  // namespace akvf
