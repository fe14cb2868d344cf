#pragma once
// The per-iteration trace as CSV: a header, then one row per iteration with
// row 0 for the initial map. Columns:
//   iter,seconds,energy,grad_norm,step,ls_evals,flips,max_step,
//   precond_seconds,line_search_seconds,status
// `seconds` is cumulative optimizer time; `status` is empty except on the
// last row, which says why the run stopped.
#include <map>
#include <ostream>
#include <string>
#include <vector>

#include "framework/optimization/optimizer.h"

namespace akvf {

void write_trace_csv(std::ostream& out, const OptimizerResult& result);
void write_trace_csv(const std::string& path, const OptimizerResult& result);

// A trace file read back: every numeric column by its header name (the
// status column is kept as text). Throws InputError naming the file and
// line for a missing header, a short row or a non-number.
struct TraceTable {
  std::map<std::string, std::vector<double>> columns;
  std::vector<std::string> status;
  const std::vector<double>& column(const std::string& name, const std::string& file) const;
};
TraceTable read_trace_csv(const std::string& path);

}  // namespace akvf
