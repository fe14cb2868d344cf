#include "framework/optimization/distortion_objective.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <Eigen/LU>
#include <cmath>
#include <limits>
#include <sstream>

#include "framework/optimization/flip_free_step.h"

namespace akvf {

namespace {
constexpr int kGrain = 1024;
template <class Body>
void for_each_index(int n, const Body& body) {
  tbb::parallel_for(tbb::blocked_range<int>(0, n, kGrain), [&](const tbb::blocked_range<int>& r) {
    for (int i = r.begin(); i != r.end(); ++i) body(i);
  });
}
}  // namespace

template <int D>
DistortionObjective<D>::DistortionObjective(Eigen::MatrixXi elements, Rest rest,
                                            std::shared_ptr<const DistortionDensity<D>> density, int num_vertices)
    : elements_(std::move(elements)),
      rest_(std::move(rest)),
      density_(std::move(density)),
      num_vertices_(num_vertices),
      weights_(rest_measure(rest_) / rest_measure(rest_).sum()),
      incidence_(vertex_faces(elements_, num_vertices)),
      element_value_(elements_.rows()),
      element_gradient_(elements_.rows()) {}

template <int D>
typename DistortionObjective<D>::Matrix DistortionObjective<D>::edge_matrix(const Eigen::VectorXd& x, int e) const {
  Matrix Ds;
  const auto x0 = x.segment<D>(D * elements_(e, 0));
  for (int k = 0; k < D; ++k) Ds.col(k) = x.segment<D>(D * elements_(e, k + 1)) - x0;
  return Ds;
}

template <int D>
typename DistortionObjective<D>::Matrix DistortionObjective<D>::jacobian(const Eigen::VectorXd& x, int e) const {
  return edge_matrix(x, e) * rest_.Dm_inv[e];
}

template <int D>
double DistortionObjective<D>::sum_element_values() const {
  // Serial in element order: the same sum for any thread count.
  double sum = 0;
  for (double v : element_value_) sum += v;
  return sum;
}

template <int D>
double DistortionObjective<D>::value(const Eigen::VectorXd& x) const {
  for_each_index(static_cast<int>(elements_.rows()),
                 [&](int e) { element_value_[e] = weights_[e] * density_->value(jacobian(x, e)); });
  return sum_element_values();
}

template <int D>
double DistortionObjective<D>::value_and_gradient(const Eigen::VectorXd& x, Eigen::VectorXd* gradient) const {
  for_each_index(static_cast<int>(elements_.rows()), [&](int e) {
    Matrix dD_dJ;
    element_value_[e] = weights_[e] * density_->value_and_gradient(jacobian(x, e), &dD_dJ);
    // J = Ds Dm^-1, so dE/dDs = w dD/dJ Dm^-T; column c is dE/d(x_{c+1} - x_0).
    element_gradient_[e] = weights_[e] * dD_dJ * rest_.Dm_inv[e].transpose();
  });
  gradient->resize(num_variables());
  for_each_index(num_vertices_, [&](int v) {
    Eigen::Matrix<double, D, 1> g = Eigen::Matrix<double, D, 1>::Zero();
    for (int i = incidence_.offsets[v]; i < incidence_.offsets[v + 1]; ++i) {
      const int e = incidence_.face_corner[i] / kCorners, corner = incidence_.face_corner[i] % kCorners;
      const Matrix& G = element_gradient_[e];
      if (corner == 0)
        g -= G.rowwise().sum();
      else
        g += G.col(corner - 1);
    }
    gradient->template segment<D>(D * v) = g;
  });
  return sum_element_values();
}

template <int D>
double DistortionObjective<D>::max_feasible_step(const Eigen::VectorXd& x, const Eigen::VectorXd& d) const {
  for_each_index(static_cast<int>(elements_.rows()), [&](int e) {
    const Matrix Ds = edge_matrix(x, e), Dd = edge_matrix(d, e);
    if constexpr (D == 2)
      element_value_[e] = triangle_flip_step(Ds.data(), Dd.data());
    else
      element_value_[e] = tet_flip_step(Ds, Dd);
  });
  double step = std::numeric_limits<double>::infinity();
  for (double t : element_value_) step = std::min(step, t);
  return step;
}

template <int D>
int DistortionObjective<D>::count_inverted(const Eigen::VectorXd& x) const {
  for_each_index(static_cast<int>(elements_.rows()),
                 [&](int e) { element_value_[e] = !(edge_matrix(x, e).determinant() > 0); });
  int inverted = 0;
  for (double flag : element_value_) inverted += flag != 0;
  return inverted;
}

template <int D>
std::string DistortionObjective<D>::first_bad_element(const Eigen::VectorXd& x) const {
  auto describe = [&](int e, const std::string& problem) {
    std::ostringstream message;
    message << (D == 2 ? "triangle " : "tet ") << e + index_base_ << " (vertices";
    for (int k = 0; k < kCorners; ++k) {
      const int v = elements_(e, k);
      message << (k ? ", " : " ") << (vertex_number_.empty() ? v : vertex_number_[v]) + index_base_;
    }
    message << ")" << numbering_note(index_base_) << ": " << problem;
    return message.str();
  };
  // Each element finite on its own, yet the sum or the gradient's norm may
  // overflow: then the element with the largest distortion is named.
  int largest = -1;
  double largest_density = 0;
  for (int e = 0; e < elements_.rows(); ++e) {
    std::ostringstream problem;
    problem.precision(3);
    bool finite_corners = true;
    for (int k = 0; k < kCorners; ++k) finite_corners &= x.segment<D>(D * elements_(e, k)).allFinite();
    const double det = finite_corners ? edge_matrix(x, e).determinant() : 0;
    Matrix dD_dJ = Matrix::Zero();
    const double density = finite_corners && det > 0 ? density_->value_and_gradient(jacobian(x, e), &dD_dJ) : 0;
    if (!finite_corners)
      problem << "a corner has a non-finite coordinate";
    else if (!(det > 0))
      problem << "inverted or collapsed (det = " << det << ")";
    else if (!std::isfinite(density))
      problem << "distortion " << density;
    else if (!dD_dJ.allFinite())
      problem << "non-finite distortion gradient";
    else {
      if (largest < 0 || density > largest_density) {
        largest = e;
        largest_density = density;
      }
      continue;
    }
    return describe(e, problem.str());
  }
  const std::string base = Objective::first_bad_element(x);
  if (!base.empty() || largest < 0) return base;
  Eigen::VectorXd gradient;
  if (std::isfinite(value_and_gradient(x, &gradient)) && std::isfinite(gradient.norm())) return "";
  std::ostringstream problem;
  problem.precision(3);
  problem << "the largest distortion, " << largest_density << " (the energy or its gradient overflows)";
  return describe(largest, problem.str());
}

template <int D>
Eigen::VectorXd DistortionObjective<D>::face_distortion(const Eigen::VectorXd& x) const {
  Eigen::VectorXd values(elements_.rows());
  for_each_index(static_cast<int>(elements_.rows()), [&](int e) { values[e] = density_->value(jacobian(x, e)); });
  return values;
}

template class DistortionObjective<2>;
template class DistortionObjective<3>;

Eigen::VectorXd stack_rows(const Eigen::MatrixXd& P) {
  const Eigen::MatrixXd T = P.transpose();
  return Eigen::Map<const Eigen::VectorXd>(T.data(), T.size());
}

Eigen::MatrixXd unstack_rows(const Eigen::VectorXd& x, int dimension) {
  return Eigen::Map<const Eigen::MatrixXd>(x.data(), dimension, x.size() / dimension).transpose();
}

}  // namespace akvf
