#pragma once
// NumPy arrays (or anything numpy.asarray takes) in, Eigen matrices out, with
// messages that name the argument: a float64 array of the wrong shape is an
// InputError ("V must be an (n, 3) array, found shape (4,)"); other dtypes
// and layouts are converted; indices must be integers of any dtype.
#include <pybind11/pybind11.h>

#include <Eigen/Core>
#include <string>

namespace akvf::python {

// An (n, columns) array of finite reals, as float64. InputError for another
// shape, a non-numeric dtype, or a NaN or inf (naming its row).
Eigen::MatrixXd float_matrix(const pybind11::handle& array, const std::string& name, int columns);
// An (n, columns) array of integers (any integer dtype) that fit an int.
Eigen::MatrixXi index_matrix(const pybind11::handle& array, const std::string& name, int columns);
// A 1-D array of integers, as a column.
Eigen::MatrixXi index_vector(const pybind11::handle& array, const std::string& name);

}  // namespace akvf::python
