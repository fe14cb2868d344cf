#include "io/seam_split_mesh.h"

#include <map>
#include <vector>

#include "akvf/mesh_io.h"

namespace akvf {

SeamSplitMesh split_at_seams(const TriMesh& mesh, const Eigen::MatrixXd& UV, const Eigen::MatrixXi& UV_faces) {
  check_corner_uv(mesh, UV, UV_faces);
  std::map<std::pair<int, int>, int> vertex_of;
  std::vector<std::pair<int, int>> pairs;
  SeamSplitMesh out;
  out.mesh.F.resize(mesh.num_faces(), 3);
  for (int f = 0; f < mesh.num_faces(); ++f)
    for (int k = 0; k < 3; ++k) {
      const std::pair<int, int> pair(mesh.F(f, k), UV_faces(f, k));
      const auto [it, added] = vertex_of.emplace(pair, static_cast<int>(pairs.size()));
      if (added) pairs.push_back(pair);
      out.mesh.F(f, k) = it->second;
    }
  out.mesh.V.resize(static_cast<Eigen::Index>(pairs.size()), 3);
  out.uv.resize(static_cast<Eigen::Index>(pairs.size()), 2);
  for (std::size_t i = 0; i < pairs.size(); ++i) {
    out.mesh.V.row(i) = mesh.V.row(pairs[i].first);
    out.uv.row(i) = UV.row(pairs[i].second);
  }
  out.mesh.index_base = mesh.index_base;
  return out;
}

}  // namespace akvf
