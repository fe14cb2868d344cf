#pragma once
// Per-triangle rest geometry of a 3D triangle mesh, the data the distortion
// energy (Eq. 1) and the preconditioners need.
#include <Eigen/Core>
#include <vector>

#include "framework/mesh.h"

namespace akvf {

struct RestTriangles {
  // Inverse of the rest edge matrix Dm = [x1 - x0, x2 - x0] of each triangle
  // in an isometric 2D frame, so that J_f = Ds Dm^-1 with Ds the same edges in
  // the parameterization (§3: "J_f modulo a rigid transformation from 3D to
  // the plane").
  std::vector<Eigen::Matrix2d> Dm_inv;
  // Rest area A_hat_f of each triangle (#F).
  Eigen::VectorXd area;
  double total_area = 0;
};

RestTriangles rest_triangles(const TriMesh& mesh);

// Total 3D surface area.
double surface_area(const TriMesh& mesh);

// Scale factor and translation applied to bring the mesh to total area 1,
// centred at the origin: V_normalized = (V - center) * scale.
struct Normalization {
  double scale = 1;
  Eigen::RowVector3d center = Eigen::RowVector3d::Zero();
  double input_area = 0;
};

Normalization normalize_to_unit_area(TriMesh* mesh);

}  // namespace akvf
