#pragma once
// Per-triangle rest geometry of a 3D triangle mesh, the data the distortion
// energy (Eq. 1) and the preconditioners need.
#include <Eigen/Core>
#include <string>
#include <vector>

#include "akvf/mesh.h"

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

// Per-tet rest geometry: J_t = Ds Dm^-1 with Dm = [x1 - x0, x2 - x0, x3 - x0]
// of the rest tet, and its (positive) volume.
struct RestTets {
  std::vector<Eigen::Matrix3d> Dm_inv;
  Eigen::VectorXd volume;  // #T
  double total_volume = 0;
};

RestTets rest_tets(const TetMesh& mesh);

// The measure (area or volume) of each element, for the element-generic code.
inline const Eigen::VectorXd& rest_measure(const RestTriangles& rest) { return rest.area; }
inline const Eigen::VectorXd& rest_measure(const RestTets& rest) { return rest.volume; }

// Total 3D surface area.
double surface_area(const TriMesh& mesh);

// Scale factor and translation applied to bring the mesh to total area 1,
// centred at the origin: V_normalized = (V - center) * scale.
struct Normalization {
  double scale = 1;
  Eigen::RowVector3d center = Eigen::RowVector3d::Zero();
  double input_area = 0;  // of the mesh given to normalize_to_unit_area
};

Normalization normalize_to_unit_area(TriMesh* mesh);
// The same normalization applied to another mesh of those vertices (a copy
// with some vertices repeated, say).
void apply_normalization(const Normalization& normalization, TriMesh* mesh);

// The power of two 2^k that brings the largest extent of the bounding box of
// V (#V by 3) into [0.5, 1). Multiplying by it is exact, so a mesh scaled by
// it normalizes to the same bits, while areas and squared lengths of meshes
// at scales like 1e-100 or 1e+100 no longer underflow or overflow. Throws
// ValidationError naming `name` when the extent is zero or subnormal (too
// small to normalize).
double power_of_two_unit_scale(const Eigen::MatrixXd& V, const std::string& name);

}  // namespace akvf
