#pragma once
// The library's typed errors as Python exceptions, with the command line's
// messages: akvf.Error (the base), akvf.InputError and akvf.ValidationError
// (also ValueError), akvf.OptionsError (ValueError), akvf.NumericalError
// (RuntimeError) and akvf.OutputError (OSError).
#include <pybind11/pybind11.h>

namespace akvf::python {

void register_errors(pybind11::module_& module);

}  // namespace akvf::python
