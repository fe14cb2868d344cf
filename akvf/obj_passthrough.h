#pragma once
// What an OBJ file carries besides the positions, faces and texture
// coordinates akvf reads: normals, groups, objects, smoothing groups,
// materials, lines, points, vertex colours and weights, and each
// face corner's normal. The OBJ writer puts it back around the new `vt`, in
// the file's own order, so writing a parameterized OBJ loses nothing but
// comment lines.
#include <cstdint>
#include <string>
#include <vector>

namespace akvf {

struct ObjPassthrough {
  enum class Kind : std::uint8_t { kVertices, kTextures, kFaces, kStatements };
  // The file as consecutive runs of one kind of line.
  struct Run {
    Kind kind;
    long long count;
  };
  std::vector<Run> runs;
  // The kept lines (kStatements), each ending in '\n', in file order.
  std::string statements;
  // Per vertex the numbers after x y z (a weight w, or a colour r g b):
  // vertex_tail_count[v] of them, in order in vertex_tail. Vertices past
  // the end of vertex_tail_count have none.
  std::vector<std::uint8_t> vertex_tail_count;
  std::vector<double> vertex_tail;
  // Per corner of the `f` lines (one after another) the `vn` row it names
  // (0-based), or -1. Corners past its end name none.
  std::vector<int> corner_normal;
  // The `mtllib` file names, as written in the file.
  std::vector<std::string> material_libraries;
  // Faces with more than three corners (triangulated for the mesh): per `f`
  // line its corner count and vertices, and per corner of the mesh's
  // triangles the `f` corner it comes from (polygon_triangulation.h). Empty
  // when every face is a triangle.
  std::vector<int> face_sizes;
  std::vector<int> face_vertices;
  std::vector<long long> triangle_source_corner;

  bool empty() const { return runs.empty(); }
  // Appends one line of `kind`; consecutive lines of a kind share a run.
  void add(Kind kind) {
    if (runs.empty() || runs.back().kind != kind) runs.push_back({kind, 0});
    ++runs.back().count;
  }
};

// The files an OBJ's materials name, for checks that no output replaces them:
// each `mtllib` resolved against the OBJ's folder, and the texture maps
// (`map_Kd`, `bump`, ...) the libraries that exist name, resolved against
// each library's folder.
std::vector<std::string> material_files(const std::string& obj_path, const ObjPassthrough& source);

}  // namespace akvf
