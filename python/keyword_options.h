#pragma once
// Keyword arguments to ParameterizeOptions / DeformOptions through the options
// schema (akvf/internal/option_schema.h): each keyword is a schema key, its Python
// value is turned into the text the command line and the manifests parse,
// and the schema's parse and range checks run on it, so the three accept the
// same values with the same messages. None stands for the default (no time
// limit, all cores); True and False stand for on and off. An unknown keyword
// is a TypeError, as in Python.
#include <pybind11/pybind11.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "akvf/error.h"
#include "akvf/internal/option_schema.h"
#include "akvf/internal/options.h"

namespace akvf::python {

// The text of a Python value for `field` ("true"/"false" for a switch, 17
// significant digits for a number, which reads back to the same double).
template <class Options>
std::string option_text(const OptionField<Options>& field, const pybind11::handle& value) {
  namespace py = pybind11;
  const std::string type = py::str(py::type::handle_of(value).attr("__name__")).cast<std::string>();
  const auto wrong = [&](const char* expected) {
    return OptionsError(field.key + " must be " + expected + ", found " + type + " " +
                        py::repr(value).cast<std::string>());
  };
  if (value.is_none()) return field.format(Options{});
  const bool is_bool = py::isinstance<py::bool_>(value) || type == "bool_";
  const auto number_text = [&] {
    const double number = py::float_(py::reinterpret_borrow<py::object>(value)).cast<double>();
    if (std::isinf(number) && number > 0) return std::string("inf");
    char text[40];
    std::snprintf(text, sizeof text, "%.17g", number);
    return std::string(text);
  };
  switch (field.kind) {
    case OptionKind::kText:  // a word, or a switch written on|off on the command line (flaps),
                             // or a number where the word may be one (newton_reuse="auto" or 0.03)
      if (is_bool) return py::reinterpret_borrow<py::object>(value).cast<bool>() ? "on" : "off";
      if (py::isinstance<py::str>(value)) return value.cast<std::string>();
      if (py::hasattr(value, "__float__")) return number_text();
      throw wrong("a string");
    case OptionKind::kSwitch:
      if (!is_bool) throw wrong("True or False");
      return py::reinterpret_borrow<py::object>(value).cast<bool>() ? "true" : "false";
    case OptionKind::kInteger:
      if (is_bool || !py::hasattr(value, "__index__")) throw wrong("an integer");
      return py::str(py::module_::import("operator").attr("index")(value)).cast<std::string>();
    case OptionKind::kNumber:
      if (is_bool || !(py::hasattr(value, "__float__"))) throw wrong("a number");
      return number_text();
  }
  throw wrong("a value");
}

template <class Options>
Options options_from_keywords(const pybind11::dict& keywords, const std::vector<OptionField<Options>>& fields,
                              const std::string& function) {
  namespace py = pybind11;
  Options options;
  for (const auto& [key, value] : keywords) {
    const std::string name = py::str(key).cast<std::string>();
    const auto field = std::find_if(fields.begin(), fields.end(), [&](const auto& f) { return f.key == name; });
    if (field == fields.end()) {
      std::string valid;
      for (const auto& f : fields) valid += (valid.empty() ? "" : ", ") + f.key;
      throw py::type_error(function + "() got an unexpected keyword argument '" + name + "' (options: " + valid + ")");
    }
    field->parse(options, option_text(*field, value));
  }
  check_options(options);
  return options;
}

}  // namespace akvf::python
