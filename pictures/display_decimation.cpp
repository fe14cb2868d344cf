#include "pictures/display_decimation.h"

#include <Eigen/Geometry>
#include <array>
#include <cmath>
#include <map>

namespace akvf {

namespace {

double surface_area(const TriMesh& m) {
  double area = 0;
  for (int f = 0; f < m.num_faces(); ++f) {
    const Eigen::Vector3d a = m.V.row(m.F(f, 0)), b = m.V.row(m.F(f, 1)), c = m.V.row(m.F(f, 2));
    area += 0.5 * (b - a).cross(c - a).norm();
  }
  return area;
}

double uv_area(const SeamSplitMesh& m) {
  double area = 0;
  for (int f = 0; f < m.mesh.num_faces(); ++f) {
    const Eigen::RowVector2d e1 = m.uv.row(m.mesh.F(f, 1)) - m.uv.row(m.mesh.F(f, 0));
    const Eigen::RowVector2d e2 = m.uv.row(m.mesh.F(f, 2)) - m.uv.row(m.mesh.F(f, 0));
    area += 0.5 * std::abs(e1.x() * e2.y() - e1.y() * e2.x());
  }
  return area;
}

DisplayMesh cluster(const SeamSplitMesh& in, double h, double h_uv) {
  std::map<std::array<long long, 5>, int> cluster_of_cell;
  std::vector<int> cluster(in.mesh.num_vertices());
  std::vector<Eigen::RowVector3d> position;
  std::vector<Eigen::RowVector2d> uv;
  std::vector<int> members;
  for (int v = 0; v < in.mesh.num_vertices(); ++v) {
    const std::array<long long, 5> cell = {static_cast<long long>(std::floor(in.mesh.V(v, 0) / h)),
                                           static_cast<long long>(std::floor(in.mesh.V(v, 1) / h)),
                                           static_cast<long long>(std::floor(in.mesh.V(v, 2) / h)),
                                           static_cast<long long>(std::floor(in.uv(v, 0) / h_uv)),
                                           static_cast<long long>(std::floor(in.uv(v, 1) / h_uv))};
    const auto [it, added] = cluster_of_cell.emplace(cell, static_cast<int>(position.size()));
    if (added) {
      position.push_back(Eigen::RowVector3d::Zero());
      uv.push_back(Eigen::RowVector2d::Zero());
      members.push_back(0);
    }
    cluster[v] = it->second;
    position[it->second] += in.mesh.V.row(v);
    uv[it->second] += in.uv.row(v);
    ++members[it->second];
  }
  DisplayMesh out;
  std::vector<Eigen::RowVector3i> faces;
  for (int f = 0; f < in.mesh.num_faces(); ++f) {
    const int a = cluster[in.mesh.F(f, 0)], b = cluster[in.mesh.F(f, 1)], c = cluster[in.mesh.F(f, 2)];
    if (a == b || b == c || a == c) continue;
    faces.emplace_back(a, b, c);
    out.source_face.push_back(f);
  }
  out.mesh.mesh.V.resize(static_cast<Eigen::Index>(position.size()), 3);
  out.mesh.uv.resize(static_cast<Eigen::Index>(position.size()), 2);
  for (std::size_t i = 0; i < position.size(); ++i) {
    out.mesh.mesh.V.row(i) = position[i] / members[i];
    out.mesh.uv.row(i) = uv[i] / members[i];
  }
  out.mesh.mesh.F.resize(static_cast<Eigen::Index>(faces.size()), 3);
  for (std::size_t f = 0; f < faces.size(); ++f) out.mesh.mesh.F.row(f) = faces[f];
  return out;
}

}  // namespace

DisplayMesh decimate_for_display(const SeamSplitMesh& mesh, long long max_faces) {
  if (mesh.mesh.num_faces() <= max_faces) {
    DisplayMesh same{mesh, std::vector<int>(mesh.mesh.num_faces())};
    for (int f = 0; f < mesh.mesh.num_faces(); ++f) same.source_face[f] = f;
    return same;
  }
  const double area = surface_area(mesh.mesh);
  // The texture plane's cells are the space cells at the map's mean scale.
  const double uv_scale = std::sqrt(uv_area(mesh) / std::max(area, 1e-300));
  double h = std::sqrt(2 * area / static_cast<double>(max_faces));
  for (;;) {
    DisplayMesh out = cluster(mesh, h, std::max(h * uv_scale, 1e-300));
    if (out.mesh.mesh.num_faces() <= max_faces) return out;
    h *= 2;
  }
}

}  // namespace akvf
