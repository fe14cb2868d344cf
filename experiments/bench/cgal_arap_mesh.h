#pragma once
// The CGAL types and mesh conversion shared by cgal_arap.cpp (the timed run)
// and cgal_arap_iterates.cpp (the run that writes its iterates).
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <Eigen/Core>
#include <vector>

namespace akvf::bench::cgal {

using Kernel = CGAL::Simple_cartesian<double>;
using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;
using Vertex = Mesh::Vertex_index;
using UvMap = Mesh::Property_map<Vertex, Kernel::Point_2>;
// lambda of the ARAP/ASAP family: CGAL takes ARAP's closed-form rotation when
// its per-triangle coefficients are below 1e-10 lambda, which for a mesh of
// unit area holds everywhere, while lambda s^2 (s = a^2 + b^2 - 1, zero up
// to rounding for a rotation) stays far below its energy.
inline constexpr double kArapLambda = 1e12;

// The mesh in CGAL's Surface_mesh (of any point type); a face CGAL cannot
// add (non-manifold input) is left out, so the face count tells.
template <class SurfaceMesh = Mesh>
SurfaceMesh make_mesh(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F) {
  using Point = typename SurfaceMesh::Point;
  SurfaceMesh mesh;
  std::vector<typename SurfaceMesh::Vertex_index> vertex;
  for (int i = 0; i < V.rows(); ++i) vertex.push_back(mesh.add_vertex(Point(V(i, 0), V(i, 1), V(i, 2))));
  for (int f = 0; f < F.rows(); ++f) mesh.add_face(vertex[F(f, 0)], vertex[F(f, 1)], vertex[F(f, 2)]);
  return mesh;
}

// A halfedge of the mesh's longest boundary loop, where CGAL's
// parameterizers start.
template <class SurfaceMesh>
typename SurfaceMesh::Halfedge_index longest_border(const SurfaceMesh& mesh) {
  return CGAL::Polygon_mesh_processing::longest_border(mesh).first;
}

}  // namespace akvf::bench::cgal
