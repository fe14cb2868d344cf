#include "akvf/rest_geometry.h"

#include <Eigen/Geometry>
#include <Eigen/LU>
#include <cmath>
#include <limits>
#include <sstream>

#include "akvf/error.h"

namespace akvf {

RestTriangles rest_triangles(const TriMesh& mesh) {
  RestTriangles rest;
  const int nf = mesh.num_faces();
  rest.Dm_inv.resize(nf);
  rest.area.resize(nf);
  for (int f = 0; f < nf; ++f) {
    const Eigen::Vector3d p0 = mesh.V.row(mesh.F(f, 0));
    const Eigen::Vector3d e1 = Eigen::Vector3d(mesh.V.row(mesh.F(f, 1))) - p0;
    const Eigen::Vector3d e2 = Eigen::Vector3d(mesh.V.row(mesh.F(f, 2))) - p0;
    const double length = e1.norm();
    const double twice_area = e1.cross(e2).norm();
    Eigen::Matrix2d Dm;
    Dm << length, e1.dot(e2) / length, 0, twice_area / length;
    rest.Dm_inv[f] = Dm.inverse();
    rest.area[f] = 0.5 * twice_area;
  }
  rest.total_area = rest.area.sum();
  return rest;
}

RestTets rest_tets(const TetMesh& mesh) {
  RestTets rest;
  rest.Dm_inv.resize(mesh.num_tets());
  rest.volume.resize(mesh.num_tets());
  for (int t = 0; t < mesh.num_tets(); ++t) {
    Eigen::Matrix3d Dm;
    for (int k = 0; k < 3; ++k) Dm.col(k) = (mesh.V.row(mesh.T(t, k + 1)) - mesh.V.row(mesh.T(t, 0))).transpose();
    rest.Dm_inv[t] = Dm.inverse();
    rest.volume[t] = Dm.determinant() / 6;
  }
  rest.total_volume = rest.volume.sum();
  return rest;
}

double surface_area(const TriMesh& mesh) { return rest_triangles(mesh).total_area; }

Normalization normalize_to_unit_area(TriMesh* mesh) {
  Normalization n;
  n.input_area = surface_area(*mesh);
  n.scale = 1.0 / std::sqrt(n.input_area);
  n.center = mesh->V.colwise().mean();
  apply_normalization(n, mesh);
  return n;
}

void apply_normalization(const Normalization& normalization, TriMesh* mesh) {
  mesh->V = (mesh->V.rowwise() - normalization.center) * normalization.scale;
}

double power_of_two_unit_scale(const Eigen::MatrixXd& V, const std::string& name) {
  if (V.rows() == 0) return 1;
  double extent = (V.colwise().maxCoeff() - V.colwise().minCoeff()).maxCoeff();
  if (!std::isfinite(extent)) extent = V.cwiseAbs().maxCoeff();  // spans beyond double's range
  if (!(extent >= std::numeric_limits<double>::min())) {
    if (extent == 0) throw ValidationError(name + ": every vertex is at the same position; the mesh has no area");
    std::ostringstream text;
    text << name << ": coordinates too small to normalize: the mesh's extent " << extent
         << " is below the smallest normal double, so its area underflows";
    throw ValidationError(text.str());
  }
  int exponent = 0;
  std::frexp(extent, &exponent);  // extent = m 2^exponent, m in [0.5, 1)
  return std::ldexp(1.0, -exponent);
}

}  // namespace akvf
