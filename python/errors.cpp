#include "python/errors.h"

#include "akvf/error.h"

namespace py = pybind11;

namespace akvf::python {

namespace {

// A new exception class module.name deriving from the given bases.
py::object exception_class(py::module_& module, const char* name, const py::tuple& bases) {
  const std::string qualified = std::string("akvf.") + name;
  py::object type = py::reinterpret_steal<py::object>(PyErr_NewException(qualified.c_str(), bases.ptr(), nullptr));
  if (!type) throw py::error_already_set();
  module.add_object(name, type);
  return type;
}

}  // namespace

void register_errors(py::module_& module) {
  const py::object base = exception_class(module, "Error", py::make_tuple(py::handle(PyExc_Exception)));
  // Kept alive by the module; the translator reads them through these handles.
  static py::handle input, validation, options, numerical, output, error;
  error = base;
  input = exception_class(module, "InputError", py::make_tuple(base, py::handle(PyExc_ValueError)));
  validation = exception_class(module, "ValidationError", py::make_tuple(base, py::handle(PyExc_ValueError)));
  options = exception_class(module, "OptionsError", py::make_tuple(base, py::handle(PyExc_ValueError)));
  numerical = exception_class(module, "NumericalError", py::make_tuple(base, py::handle(PyExc_RuntimeError)));
  output = exception_class(module, "OutputError", py::make_tuple(base, py::handle(PyExc_OSError)));
  py::register_exception_translator([](std::exception_ptr thrown) {
    try {
      if (thrown) std::rethrow_exception(thrown);
    } catch (const InputError& e) {
      PyErr_SetString(input.ptr(), e.what());
    } catch (const ValidationError& e) {
      PyErr_SetString(validation.ptr(), e.what());
    } catch (const OptionsError& e) {
      PyErr_SetString(options.ptr(), e.what());
    } catch (const NumericalError& e) {
      PyErr_SetString(numerical.ptr(), e.what());
    } catch (const OutputError& e) {
      PyErr_SetString(output.ptr(), e.what());
    } catch (const Error& e) {
      PyErr_SetString(error.ptr(), e.what());
    }
  });
}

}  // namespace akvf::python
