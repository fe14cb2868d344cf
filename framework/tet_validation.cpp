#include "framework/tet_validation.h"

#include <Eigen/Geometry>
#include <numeric>

#include "framework/error.h"

namespace akvf {

double signed_tet_volume(const TetMesh& mesh, int t) {
  const Eigen::Vector3d x0 = mesh.V.row(mesh.T(t, 0));
  const Eigen::Vector3d e1 = Eigen::Vector3d(mesh.V.row(mesh.T(t, 1))) - x0;
  const Eigen::Vector3d e2 = Eigen::Vector3d(mesh.V.row(mesh.T(t, 2))) - x0;
  const Eigen::Vector3d e3 = Eigen::Vector3d(mesh.V.row(mesh.T(t, 3))) - x0;
  return e1.dot(e2.cross(e3)) / 6;
}

namespace {

int count_tet_components(const TetMesh& m) {
  std::vector<int> parent(m.num_vertices());
  std::iota(parent.begin(), parent.end(), 0);
  auto find = [&](int v) {
    while (parent[v] != v) v = parent[v] = parent[parent[v]];
    return v;
  };
  std::vector<char> used(m.num_vertices(), 0);
  for (int t = 0; t < m.num_tets(); ++t)
    for (int k = 0; k < 4; ++k) {
      used[m.T(t, k)] = 1;
      const int a = find(m.T(t, 0)), b = find(m.T(t, k));
      if (a != b) parent[std::max(a, b)] = std::min(a, b);
    }
  int components = 0;
  for (int v = 0; v < m.num_vertices(); ++v) components += used[v] && find(v) == v;
  return components;
}

}  // namespace

TetMesh prepare_tet_mesh(const TetMesh& input, const std::string& name, Warnings* warnings) {
  if (input.num_tets() == 0) throw ValidationError(name + ": mesh has no tetrahedra");
  for (int v = 0; v < input.num_vertices(); ++v)
    if (!input.V.row(v).allFinite())
      throw ValidationError(name + ": vertex " + std::to_string(v) + " has a non-finite coordinate");
  std::vector<char> used(input.num_vertices(), 0);
  for (int t = 0; t < input.num_tets(); ++t) {
    for (int k = 0; k < 4; ++k) {
      if (input.T(t, k) < 0 || input.T(t, k) >= input.num_vertices())
        throw ValidationError(name + ": tet " + std::to_string(t) + " has vertex index " +
                              std::to_string(input.T(t, k)) + " out of range (" + std::to_string(input.num_vertices()) +
                              " vertices)");
      used[input.T(t, k)] = 1;
      for (int l = 0; l < k; ++l)
        if (input.T(t, k) == input.T(t, l))
          throw ValidationError(name + ": tet " + std::to_string(t) + " uses vertex " + std::to_string(input.T(t, k)) +
                                " twice");
    }
  }
  const double diagonal = (input.V.colwise().maxCoeff() - input.V.colwise().minCoeff()).norm();
  const double tolerance = 1e-14 * diagonal * diagonal * diagonal;
  int positive = 0, first_positive = -1, first_negative = -1;
  for (int t = 0; t < input.num_tets(); ++t) {
    const double volume = signed_tet_volume(input, t);
    if (!(std::abs(volume) > tolerance))
      throw ValidationError(name + ": tet " + std::to_string(t) + " is degenerate (volume " + std::to_string(volume) +
                            "); remove flat tets first");
    if (volume > 0) {
      if (positive++ == 0) first_positive = t;
    } else if (first_negative < 0) {
      first_negative = t;
    }
  }
  TetMesh mesh = input;
  if (positive > 0 && positive < mesh.num_tets())
    throw ValidationError(name + ": inconsistent orientation: tet " + std::to_string(first_positive) +
                          " is positively oriented but tet " + std::to_string(first_negative) +
                          " negatively; every tet must have the same orientation");
  if (positive == 0) {
    mesh.T.col(2).swap(mesh.T.col(3));
    if (warnings) warnings->push_back(name + ": every tet was negatively oriented; flipped them all");
  }
  const int components = count_tet_components(mesh);
  if (components != 1)
    throw ValidationError(name + ": mesh has " + std::to_string(components) +
                          " connected components; deform one component at a time");
  const auto unused = std::count(used.begin(), used.end(), 0);
  if (unused > 0 && warnings)
    warnings->push_back(name + ": " + std::to_string(unused) + " vertices are in no tet; they stay where they are");
  return mesh;
}

}  // namespace akvf
