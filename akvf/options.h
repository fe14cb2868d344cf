#pragma once
// The one conversion from the public options (parameterize.h, deform.h) to
// the pipelines' configurations, with the range check of every option in one
// place: the API's is_valid(), the command line and the experiment runner
// all go through it. OptionsError names the option and the value found.
#include "akvf/deform.h"
#include "akvf/deformation.h"
#include "akvf/parameterization.h"
#include "akvf/parameterize.h"

namespace akvf {

ParamConfig param_config(const ParameterizeOptions& options);
DeformConfig deform_config(const DeformOptions& options);

// Names known to the registries and every value in range; OptionsError otherwise.
void validate(const ParamConfig& config);
void validate(const DeformConfig& config);

// RunStatistics of a finished run.
RunStatistics run_statistics(const OptimizerResult& result, const PreconditionerStatistics& preconditioner);

}  // namespace akvf
