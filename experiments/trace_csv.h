#pragma once
// The per-iteration trace as CSV: a header, then one row per iteration with
// row 0 for the initial map. Columns:
//   iter,seconds,energy,grad_norm,step,ls_evals,flips,max_step,
//   precond_seconds,line_search_seconds,status
// `seconds` is cumulative optimizer time; `status` is empty except on the
// last row, which says why the run stopped.
#include <ostream>
#include <string>

#include "framework/optimizer.h"

namespace akvf {

void write_trace_csv(std::ostream& out, const OptimizerResult& result);
void write_trace_csv(const std::string& path, const OptimizerResult& result);

}  // namespace akvf
