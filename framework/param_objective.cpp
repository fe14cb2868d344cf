#include "framework/param_objective.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <limits>

#include "framework/flip_free_step.h"

namespace akvf {

namespace {
constexpr int kGrain = 1024;
constexpr double kInfinity = std::numeric_limits<double>::infinity();

template <class Body>
void for_each_index(int n, const Body& body) {
  tbb::parallel_for(tbb::blocked_range<int>(0, n, kGrain), [&](const tbb::blocked_range<int>& r) {
    for (int i = r.begin(); i != r.end(); ++i) body(i);
  });
}
}  // namespace

ParamObjective::ParamObjective(Eigen::MatrixXi F, RestTriangles rest, std::shared_ptr<const DistortionDensity2> density,
                               int num_vertices)
    : F_(std::move(F)),
      rest_(std::move(rest)),
      density_(std::move(density)),
      num_vertices_(num_vertices),
      weights_(rest_.area / rest_.total_area),
      incidence_(vertex_faces(F_, num_vertices)),
      face_value_(F_.rows()),
      face_gradient_(F_.rows()) {}

Eigen::Matrix2d ParamObjective::edge_matrix(const Eigen::VectorXd& x, int f) const {
  const int i = 2 * F_(f, 0), j = 2 * F_(f, 1), k = 2 * F_(f, 2);
  Eigen::Matrix2d Ds;
  Ds << x[j] - x[i], x[k] - x[i], x[j + 1] - x[i + 1], x[k + 1] - x[i + 1];
  return Ds;
}

Eigen::Matrix2d ParamObjective::jacobian(const Eigen::VectorXd& x, int f) const {
  return edge_matrix(x, f) * rest_.Dm_inv[f];
}

double ParamObjective::sum_face_values() const {
  // Serial in face order: the same sum for any thread count.
  double sum = 0;
  for (double v : face_value_) sum += v;
  return sum;
}

double ParamObjective::value(const Eigen::VectorXd& x) const {
  for_each_index(static_cast<int>(F_.rows()),
                 [&](int f) { face_value_[f] = weights_[f] * density_->value(jacobian(x, f)); });
  return sum_face_values();
}

double ParamObjective::value_and_gradient(const Eigen::VectorXd& x, Eigen::VectorXd* gradient) const {
  for_each_index(static_cast<int>(F_.rows()), [&](int f) {
    Eigen::Matrix2d dD_dJ;
    face_value_[f] = weights_[f] * density_->value_and_gradient(jacobian(x, f), &dD_dJ);
    // J = Ds Dm^-1, so dE/dDs = w dD/dJ Dm^-T; column c is dE/d(x_{c+1} - x_0).
    face_gradient_[f] = weights_[f] * dD_dJ * rest_.Dm_inv[f].transpose();
  });
  gradient->resize(num_variables());
  for_each_index(num_vertices_, [&](int v) {
    Eigen::Vector2d g = Eigen::Vector2d::Zero();
    for (int e = incidence_.offsets[v]; e < incidence_.offsets[v + 1]; ++e) {
      const int f = incidence_.face_corner[e] / 3, corner = incidence_.face_corner[e] % 3;
      const Eigen::Matrix2d& G = face_gradient_[f];
      g += corner == 0 ? Eigen::Vector2d(-G.col(0) - G.col(1)) : Eigen::Vector2d(G.col(corner - 1));
    }
    gradient->segment<2>(2 * v) = g;
  });
  return sum_face_values();
}

double ParamObjective::max_feasible_step(const Eigen::VectorXd& x, const Eigen::VectorXd& d) const {
  for_each_index(static_cast<int>(F_.rows()), [&](int f) {
    const Eigen::Matrix2d Ds = edge_matrix(x, f), Dd = edge_matrix(d, f);
    face_value_[f] = triangle_flip_step(Ds.data(), Dd.data());
  });
  double step = kInfinity;
  for (double t : face_value_) step = std::min(step, t);
  return step;
}

int ParamObjective::count_inverted(const Eigen::VectorXd& x) const {
  int inverted = 0;
  for (int f = 0; f < F_.rows(); ++f) inverted += !(edge_matrix(x, f).determinant() > 0);
  return inverted;
}

Eigen::VectorXd ParamObjective::face_distortion(const Eigen::VectorXd& x) const {
  Eigen::VectorXd D(F_.rows());
  for_each_index(static_cast<int>(F_.rows()), [&](int f) { D[f] = density_->value(jacobian(x, f)); });
  return D;
}

Eigen::VectorXd stack_uv(const Eigen::MatrixXd& UV) {
  const Eigen::MatrixXd T = UV.transpose();
  return Eigen::Map<const Eigen::VectorXd>(T.data(), T.size());
}

Eigen::MatrixXd unstack_uv(const Eigen::VectorXd& x) {
  return Eigen::Map<const Eigen::MatrixXd>(x.data(), 2, x.size() / 2).transpose();
}

}  // namespace akvf
