#pragma once
// Faces with more than three corners (quads and n-gons of OBJ, OFF and PLY
// files, as modelling tools write them) split into triangles that keep the
// face's orientation.
#include <Eigen/Core>
#include <array>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace akvf {

// Triangles of the polygon `ring` (vertex indices into V's rows, in order):
// ring.size() - 2 of them, each as three positions in `ring` (0-based), so a
// caller can carry per-corner data (texture rows, normals) along. The
// polygon is projected on the plane of its Newell normal and cut by ear
// clipping, each step taking the valid ear with the shortest diagonal (for a
// quad: the shorter diagonal that leaves two triangles of its orientation),
// an ear whose diagonal is_edge(u, v) names an edge of the mesh (another
// face's side) only if no other ear is valid. A polygon with no valid ear
// left (self-intersecting, or flat to a line) is finished as a fan, and one
// of more than 256 corners is cut as a fan.
std::vector<std::array<int, 3>> triangulate_polygon(const Eigen::MatrixXd& V, const std::vector<int>& ring,
                                                    const std::function<bool(int, int)>& is_edge = {});

// Polygons from a file, triangulated.
struct TriangulatedPolygons {
  std::vector<int> triangles;  // 3 vertex indices per triangle
  // Per triangle corner, the index of the file's face corner it comes from
  // (into the flattened corners of every face), for per-corner data.
  std::vector<long long> source_corner;
  // The faces' corners as the file gives them (filled by triangulate_polygons).
  std::vector<int> file_corners;
  // Per triangle, the file's face (0-based).
  std::vector<int> source_face;
  int polygons = 0;  // faces with more than three corners
  int largest = 3;   // the most corners of a face
};

// Triangulates faces given as `sizes[f]` consecutive entries of `corners`
// (vertex indices into V). Faces of three corners pass as they are.
TriangulatedPolygons triangulate_faces(const Eigen::MatrixXd& V, const std::vector<int>& corners,
                                       const std::vector<int>& sizes);

// What the readers do with a file's faces: when one has more than three
// corners, `corners` becomes the triangles' corners, one warning goes to
// `warnings` (if given), and the triangulation is returned for per-corner
// data (its `triangles` moved to `corners`, `file_corners` holding what
// `corners` held); otherwise nothing changes and nullopt is returned.
std::optional<TriangulatedPolygons> triangulate_polygons(const Eigen::MatrixXd& V, std::vector<int>* corners,
                                                         const std::vector<int>& sizes, const std::string& file_name,
                                                         std::vector<std::string>* warnings);

}  // namespace akvf
