#include "python/arrays.h"

#include <pybind11/numpy.h>

#include <cmath>
#include <limits>

#include "akvf/error.h"

namespace py = pybind11;

namespace akvf::python {

namespace {

std::string shape_text(const py::array& a) {
  std::string text = "(";
  for (py::ssize_t d = 0; d < a.ndim(); ++d) text += (d ? ", " : "") + std::to_string(a.shape(d));
  return text + (a.ndim() == 1 ? ",)" : ")");
}

// numpy.asarray(object) without a copy where none is needed.
py::array as_array(const py::handle& object, const std::string& name) {
  try {
    return py::module_::import("numpy").attr("asarray")(object);
  } catch (py::error_already_set& e) {
    throw InputError(name + " is not an array (" + std::string(e.what()) + ")");
  }
}

void require_shape(const py::array& a, const std::string& name, int columns, const char* element) {
  if (a.ndim() != 2 || a.shape(1) != columns)
    throw InputError(name + " must be an (n, " + std::to_string(columns) + ") array of " + element + ", found shape " +
                     shape_text(a));
}

char kind_of(const py::array& a) { return a.dtype().kind(); }

Eigen::MatrixXi integers(const py::array& a, const std::string& name, py::ssize_t rows, py::ssize_t columns) {
  const char kind = kind_of(a);
  if (kind != 'i' && kind != 'u')
    throw InputError(name + " must hold integers (any integer dtype), found dtype " +
                     py::str(a.dtype()).cast<std::string>());
  const auto values = py::array_t<long long, py::array::c_style | py::array::forcecast>::ensure(a);
  if (kind == 'u' && a.dtype().itemsize() == 8) {  // uint64 beyond int64 would wrap: check on the source
    const auto big = py::array_t<unsigned long long, py::array::c_style | py::array::forcecast>::ensure(a);
    for (py::ssize_t k = 0; k < big.size(); ++k)
      if (big.data()[k] > static_cast<unsigned long long>(std::numeric_limits<int>::max()))
        throw InputError(name + ": index " + std::to_string(big.data()[k]) + " at row " + std::to_string(k / columns) +
                         " does not fit a 32-bit index");
  }
  Eigen::MatrixXi out(rows, columns);
  const long long* data = values.data();
  for (py::ssize_t r = 0; r < rows; ++r)
    for (py::ssize_t c = 0; c < columns; ++c) {
      const long long v = data[r * columns + c];
      if (v < std::numeric_limits<int>::min() || v > std::numeric_limits<int>::max())
        throw InputError(name + ": index " + std::to_string(v) + " at row " + std::to_string(r) +
                         " does not fit a 32-bit index");
      out(r, c) = static_cast<int>(v);
    }
  return out;
}

}  // namespace

Eigen::MatrixXd float_matrix(const py::handle& array, const std::string& name, int columns) {
  const py::array a = as_array(array, name);
  require_shape(a, name, columns, "reals");
  const char kind = kind_of(a);
  if (kind != 'f' && kind != 'i' && kind != 'u')
    throw InputError(name + " must hold real numbers, found dtype " + py::str(a.dtype()).cast<std::string>());
  const auto values = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(a);
  Eigen::MatrixXd out(a.shape(0), columns);
  const double* data = values.data();
  for (py::ssize_t r = 0; r < a.shape(0); ++r)
    for (int c = 0; c < columns; ++c) {
      const double v = data[r * columns + c];
      if (!std::isfinite(v))
        throw InputError(name + ": row " + std::to_string(r) + " has a coordinate that is not finite (" +
                         (std::isnan(v) ? "nan"
                          : v > 0       ? "inf"
                                        : "-inf") +
                         ")");
      out(r, c) = v;
    }
  return out;
}

Eigen::MatrixXi index_matrix(const py::handle& array, const std::string& name, int columns) {
  const py::array a = as_array(array, name);
  require_shape(a, name, columns, "integers");
  return integers(a, name, a.shape(0), columns);
}

Eigen::MatrixXi index_vector(const py::handle& array, const std::string& name) {
  const py::array a = as_array(array, name);
  if (a.ndim() != 1) throw InputError(name + " must be a 1-D array of integers, found shape " + shape_text(a));
  return integers(a, name, a.shape(0), 1);
}

}  // namespace akvf::python
