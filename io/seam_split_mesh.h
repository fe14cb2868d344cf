#pragma once
// A textured mesh as viewers and glTF want it: one vertex per distinct
// (vertex, texture coordinate) pair, so a seam vertex appears once per side.
#include <Eigen/Core>

#include "akvf/mesh.h"

namespace akvf {

struct SeamSplitMesh {
  TriMesh mesh;        // the input's positions, repeated along seams; faces in the input's order
  Eigen::MatrixXd uv;  // #mesh.V by 2
};

// Vertices in order of first use by the faces.
//   UV        #T by 2
//   UV_faces  #F by 3 rows of UV (mesh_io.h: check_corner_uv)
SeamSplitMesh split_at_seams(const TriMesh& mesh, const Eigen::MatrixXd& UV, const Eigen::MatrixXi& UV_faces);

}  // namespace akvf
