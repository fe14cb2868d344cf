#include "framework/mesh/corner_copies.h"

#include "framework/mesh/mesh_topology.h"

namespace akvf {

CornerCopies split_corners(const Eigen::MatrixXi& F, int nv, const std::vector<FaceJoin>& joins) {
  const int nf = static_cast<int>(F.rows());
  auto corner = [&](int f, int v) { return 3 * f + (F(f, 0) == v ? 0 : F(f, 1) == v ? 1 : 2); };
  DisjointSets corners(3 * nf);
  for (const FaceJoin& join : joins)
    for (int v : {join.a, join.b}) corners.unite(corner(join.face0, v), corner(join.face1, v));
  CornerCopies copies;
  copies.copy_of_corner.assign(3 * nf, -1);
  std::vector<int> copy_of_root(3 * nf, -1);
  const VertexFaces around = vertex_faces(F, nv);
  for (int v = 0; v < nv; ++v)
    for (int i = around.offsets[v]; i < around.offsets[v + 1]; ++i) {
      const int root = corners.find(around.face_corner[i]);
      if (copy_of_root[root] < 0) {
        copy_of_root[root] = static_cast<int>(copies.source_vertex.size());
        copies.source_vertex.push_back(v);
      }
      copies.copy_of_corner[around.face_corner[i]] = copy_of_root[root];
    }
  return copies;
}

}  // namespace akvf
