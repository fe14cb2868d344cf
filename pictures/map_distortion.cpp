#include "pictures/map_distortion.h"

#include <Eigen/LU>
#include <cmath>
#include <limits>
#include <vector>

#include "akvf/rest_geometry.h"

namespace akvf {

MapDistortion map_distortion(const TriMesh& mesh, const Eigen::MatrixXd& uv, const Eigen::MatrixXi& uv_faces) {
  const RestTriangles rest = rest_triangles(mesh);
  double uv_area = 0;
  std::vector<Eigen::Matrix2d> Ds(mesh.num_faces());
  for (int f = 0; f < mesh.num_faces(); ++f) {
    const Eigen::RowVector2d p0 = uv.row(uv_faces(f, 0));
    Ds[f].col(0) = (uv.row(uv_faces(f, 1)) - p0).transpose();
    Ds[f].col(1) = (uv.row(uv_faces(f, 2)) - p0).transpose();
    uv_area += 0.5 * Ds[f].determinant();
  }
  const double scale = uv_area > 0 ? std::sqrt(rest.total_area / uv_area) : 1;
  Eigen::VectorXd values(mesh.num_faces());
  for (int f = 0; f < mesh.num_faces(); ++f) {
    const Eigen::Matrix2d J = scale * Ds[f] * rest.Dm_inv[f];
    const double det = J.determinant();
    // ||J||_F^2 + ||J^-1||_F^2, and ||J^-1||_F = ||J||_F / |det J| in 2D.
    values[f] = det > 0 ? J.squaredNorm() * (1 + 1 / (det * det)) : std::numeric_limits<double>::infinity();
  }
  return {values, rest.area};
}

}  // namespace akvf
