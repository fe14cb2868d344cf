#include "framework/mesh/tet_validation.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <map>
#include <numeric>

#include "akvf/error.h"
#include "framework/mesh/mesh_topology.h"

namespace akvf {

double signed_tet_volume(const TetMesh& mesh, int t) {
  const Eigen::Vector3d x0 = mesh.V.row(mesh.T(t, 0));
  const Eigen::Vector3d e1 = Eigen::Vector3d(mesh.V.row(mesh.T(t, 1))) - x0;
  const Eigen::Vector3d e2 = Eigen::Vector3d(mesh.V.row(mesh.T(t, 2))) - x0;
  const Eigen::Vector3d e3 = Eigen::Vector3d(mesh.V.row(mesh.T(t, 3))) - x0;
  return e1.dot(e2.cross(e3)) / 6;
}

namespace {

// Warns once about tets that repeat another tet's vertices and once about
// vertices at exactly the position of another: both are legal (the energy
// counts a repeated tet twice; coincident vertices leave a crack) but are
// usually mistakes of the mesh generator.
void warn_about_repeats(const TetMesh& m, const std::string& name, Warnings* warnings) {
  const int b = m.index_base;
  std::map<std::array<int, 4>, int> seen_tets;
  int repeated = 0;
  std::string first;
  for (int t = 0; t < m.num_tets(); ++t) {
    std::array<int, 4> key = {m.T(t, 0), m.T(t, 1), m.T(t, 2), m.T(t, 3)};
    std::sort(key.begin(), key.end());
    const auto [it, inserted] = seen_tets.emplace(key, t);
    if (!inserted && repeated++ == 0) first = "tet " + file_number(t, b) + " repeats tet " + file_number(it->second, b);
  }
  if (repeated > 0)
    warnings->push_back(name + ": " + std::to_string(repeated) + " tets repeat the vertices of another (first: " +
                        first + numbering_note(b) + "); each counts in the energy");
  std::map<std::array<double, 3>, int> seen_positions;
  int coincident = 0;
  for (int v = 0; v < m.num_vertices(); ++v) {
    const auto [it, inserted] = seen_positions.emplace(std::array<double, 3>{m.V(v, 0), m.V(v, 1), m.V(v, 2)}, v);
    if (!inserted && coincident++ == 0)
      first = "vertex " + file_number(v, b) + " is at the position of vertex " + file_number(it->second, b);
  }
  if (coincident > 0)
    warnings->push_back(name + ": " + std::to_string(coincident) +
                        " vertices are at exactly the position of another (first: " + first + numbering_note(b) +
                        "); the mesh has a crack there");
}

}  // namespace

PreparedTetMesh prepare_tet_mesh(const TetMesh& input, const std::string& name, Warnings* warnings) {
  const int b = input.index_base;
  const std::string note = numbering_note(b);
  if (input.num_tets() == 0) throw ValidationError(name + ": mesh has no tetrahedra");
  for (int v = 0; v < input.num_vertices(); ++v)
    if (!input.V.row(v).allFinite())
      throw ValidationError(name + ": vertex " + file_number(v, b) + " has a non-finite coordinate" + note);
  std::vector<char> used(input.num_vertices(), 0);
  for (int t = 0; t < input.num_tets(); ++t) {
    for (int k = 0; k < 4; ++k) {
      if (input.T(t, k) < 0 || input.T(t, k) >= input.num_vertices())
        throw ValidationError(name + ": tet " + file_number(t, b) + " has vertex index " +
                              file_number(input.T(t, k), b) + " out of range (" + std::to_string(input.num_vertices()) +
                              " vertices)" + note);
      used[input.T(t, k)] = 1;
      for (int l = 0; l < k; ++l)
        if (input.T(t, k) == input.T(t, l))
          throw ValidationError(name + ": tet " + file_number(t, b) + " uses vertex " + file_number(input.T(t, k), b) +
                                " twice" + note);
    }
  }
  const double diagonal = (input.V.colwise().maxCoeff() - input.V.colwise().minCoeff()).norm();
  const double tolerance = 1e-14 * diagonal * diagonal * diagonal;
  int positive = 0, first_positive = -1, first_negative = -1;
  for (int t = 0; t < input.num_tets(); ++t) {
    const double volume = signed_tet_volume(input, t);
    if (!(std::abs(volume) > tolerance))
      throw ValidationError(name + ": tet " + file_number(t, b) + " is degenerate (volume " + std::to_string(volume) +
                            ")" + note + "; remove flat tets first");
    if (volume > 0) {
      if (positive++ == 0) first_positive = t;
    } else if (first_negative < 0) {
      first_negative = t;
    }
  }
  PreparedTetMesh out;
  out.num_input_vertices = input.num_vertices();
  TetMesh& mesh = out.mesh;
  mesh = input;
  if (positive > 0 && positive < mesh.num_tets())
    throw ValidationError(name + ": inconsistent orientation: tet " + file_number(first_positive, b) +
                          " is positively oriented but tet " + file_number(first_negative, b) + " negatively" + note +
                          "; every tet must have the same orientation");
  if (positive == 0) {
    mesh.T.col(2).swap(mesh.T.col(3));
    if (warnings) warnings->push_back(name + ": every tet was negatively oriented; flipped them all");
  }
  const int components = count_components(mesh.T, mesh.num_vertices());
  if (components != 1)
    throw ValidationError(name + ": mesh has " + std::to_string(components) +
                          " connected components; deform one component at a time");
  if (warnings) warn_about_repeats(mesh, name, warnings);

  // Drop the vertices that are in no tet (they would make every factored
  // preconditioner singular); the output puts them back where they were.
  std::vector<int> new_index(input.num_vertices(), -1);
  int dropped = 0, first_dropped = -1;
  for (int v = 0; v < input.num_vertices(); ++v) {
    if (used[v]) {
      new_index[v] = static_cast<int>(out.input_vertex.size());
      out.input_vertex.push_back(v);
    } else if (dropped++ == 0) {
      first_dropped = v;
    }
  }
  if (dropped > 0) {
    mesh.V.resize(static_cast<Eigen::Index>(out.input_vertex.size()), 3);
    for (std::size_t i = 0; i < out.input_vertex.size(); ++i) mesh.V.row(i) = input.V.row(out.input_vertex[i]);
    mesh.T = mesh.T.unaryExpr([&](int v) { return new_index[v]; }).eval();
    if (warnings)
      warnings->push_back(name + ": dropped " + std::to_string(dropped) + " vertices that are in no tet (first: " +
                          file_number(first_dropped, b) + note + "); they keep their positions in the output");
  }
  return out;
}

TetMesh PreparedTetMesh::in_input_numbering(const Eigen::MatrixXd& X, const TetMesh& input) const {
  TetMesh result;
  result.V = input.V;
  for (std::size_t i = 0; i < input_vertex.size(); ++i) result.V.row(input_vertex[i]) = X.row(i);
  result.T = mesh.T.unaryExpr([&](int v) { return input_vertex[v]; });
  result.index_base = input.index_base;
  return result;
}

}  // namespace akvf
