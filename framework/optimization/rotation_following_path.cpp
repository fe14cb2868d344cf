// MeshObjective::rotation_following_term (akvf/mesh_objective.h).
//
// A rigid motion v(y) = W (y - c) + u (W skew) moves each point along a
// circle; the point's acceleration on it is (grad v) v = W v. So for a
// direction d whose velocity gradient G_e = Dd Ds^-1 on element e has the
// skew part W_e = (G_e - G_e^T) / 2, the path x_v + t d_v + (t^2 / 2) W_v d_v
// follows the turn of the elements around v to second order, where the
// straight path x + t d stretches a turning element by sqrt(1 + t^2 w^2) and
// so raises any energy with a minimum at rotations. W_v averages W_e over
// the elements around v, weighted by their current measure det Ds.
#include "akvf/mesh_objective.h"

namespace akvf {

template <int D>
bool MeshObjective<D>::rotation_following_term(const Eigen::VectorXd& x, const Eigen::VectorXd& d,
                                               Eigen::VectorXd* a) const {
  const Eigen::MatrixXi& elements = this->elements();
  const int n = num_vertices();
  std::vector<Matrix> turn(n, Matrix::Zero());
  Eigen::VectorXd measure = Eigen::VectorXd::Zero(n);
  for (Eigen::Index e = 0; e < elements.rows(); ++e) {
    Matrix Ds, Dd;
    for (int j = 0; j < D; ++j) {
      Ds.col(j) = x.segment<D>(D * elements(e, j + 1)) - x.segment<D>(D * elements(e, 0));
      Dd.col(j) = d.segment<D>(D * elements(e, j + 1)) - d.segment<D>(D * elements(e, 0));
    }
    const double det = Ds.determinant();
    if (!(det > 0)) continue;  // no turn is defined on a collapsed element
    const Matrix G = Dd * Ds.inverse();
    const Matrix weighted_skew = (0.5 * det) * (G - G.transpose());
    for (int j = 0; j <= D; ++j) {
      turn[elements(e, j)] += weighted_skew;
      measure[elements(e, j)] += det;
    }
  }
  a->setZero(D * n);
  for (int v = 0; v < n; ++v)
    if (measure[v] > 0) a->segment<D>(D * v) = turn[v] * d.segment<D>(D * v) / measure[v];
  return true;
}

template bool MeshObjective<2>::rotation_following_term(const Eigen::VectorXd&, const Eigen::VectorXd&,
                                                        Eigen::VectorXd*) const;
template bool MeshObjective<3>::rotation_following_term(const Eigen::VectorXd&, const Eigen::VectorXd&,
                                                        Eigen::VectorXd*) const;

}  // namespace akvf
