#include "framework/mesh/mesh_subdivision.h"

#include <unordered_map>

#include "akvf/error.h"
#include "framework/mesh/mesh_topology.h"

namespace akvf {

namespace {

TriMesh subdivide_once(const TriMesh& mesh) {
  const int n = mesh.num_vertices();
  std::unordered_map<long long, int> midpoint;  // edge (lo, hi) -> new vertex
  midpoint.reserve(static_cast<std::size_t>(mesh.num_faces()) * 2);
  std::vector<Eigen::RowVector3d> added;
  const auto vertex_on = [&](int a, int b) {
    const long long key = undirected_edge_key(a, b, n);
    const auto [it, inserted] = midpoint.emplace(key, n + static_cast<int>(added.size()));
    if (inserted) added.push_back(0.5 * (mesh.V.row(a) + mesh.V.row(b)));
    return it->second;
  };
  TriMesh out;
  out.F.resize(4 * mesh.num_faces(), 3);
  for (int f = 0; f < mesh.num_faces(); ++f) {
    const int a = mesh.F(f, 0), b = mesh.F(f, 1), c = mesh.F(f, 2);
    const int ab = vertex_on(a, b), bc = vertex_on(b, c), ca = vertex_on(c, a);
    out.F.row(4 * f) << a, ab, ca;
    out.F.row(4 * f + 1) << ab, b, bc;
    out.F.row(4 * f + 2) << ca, bc, c;
    out.F.row(4 * f + 3) << ab, bc, ca;
  }
  out.V.resize(n + static_cast<Eigen::Index>(added.size()), 3);
  out.V.topRows(n) = mesh.V;
  for (std::size_t i = 0; i < added.size(); ++i) out.V.row(n + static_cast<Eigen::Index>(i)) = added[i];
  return out;
}

}  // namespace

TriMesh subdivide_midpoint(const TriMesh& mesh, int rounds, long long max_faces) {
  if (rounds < 0) throw OptionsError("subdivision rounds must be >= 0");
  long long faces = mesh.num_faces();
  for (int r = 0; r < rounds; ++r) faces *= 4;
  if (faces > max_faces)
    throw ValidationError(std::to_string(rounds) + " subdivision rounds would make " + std::to_string(faces) +
                          " faces (more than " + std::to_string(max_faces) + ")");
  TriMesh out = mesh;
  for (int r = 0; r < rounds; ++r) out = subdivide_once(out);
  return out;
}

}  // namespace akvf
