#pragma once
// The symmetric Dirichlet distortion of each face of a map, as the view and
// the layouts of a map given as arrays colour it.
#include <Eigen/Core>

#include "akvf/mesh.h"

namespace akvf {

// Each face's symmetric Dirichlet distortion under the map scaled to the
// surface's area (the energy's scale: 4 is isometric; +infinity where the
// map inverts or collapses a face), and each face's area.
//   uv        #T by 2
//   uv_faces  #F by 3 rows of uv
struct MapDistortion {
  Eigen::VectorXd value, area;
};
MapDistortion map_distortion(const TriMesh& mesh, const Eigen::MatrixXd& uv, const Eigen::MatrixXi& uv_faces);

}  // namespace akvf
