#pragma once
// Triangle mesh readers (OBJ, OFF) and the UV writer. Readers throw
// InputError naming the file, the line and the problem.
#include <istream>
#include <string>

#include "akvf/mesh.h"
#include "akvf/obj_passthrough.h"

namespace akvf {

// OBJ: `v x y z` and `f` with corners `a`, `a/b`, `a//c` or `a/b/c`
// (1-based, negative = relative to the vertices read so far). `vt`, `vn` and
// the other statements OBJ allows are ignored, unknown ones with a warning
// (mesh_text.h); faces with more than three corners are triangulated, with a
// warning (polygon_triangulation.h), faces with fewer are rejected.
// A leading UTF-8 byte-order mark is skipped by every reader.
// `texture` (if given) receives the `vt` rows and each corner's row.
// `passthrough` (if given) receives the rest (obj_passthrough.h).
TriMesh read_obj(std::istream& in, const std::string& file_name, Warnings* warnings = nullptr,
                 MeshTexture* texture = nullptr, ObjPassthrough* passthrough = nullptr);

// OFF: header `OFF` (or COFF/NOFF), counts `#V #F [#E]`, vertex rows, then
// face rows `n i j k ...` (0-based; polygons triangulated with a warning,
// polygon_triangulation.h). Counts that disagree with the file, in either
// direction, are errors naming the line.
TriMesh read_off(std::istream& in, const std::string& file_name, Warnings* warnings = nullptr);

// Dispatches on the extension (.obj, .off, .ply or .stl, case-insensitive;
// ply_reader.h, stl_reader.h).
// `texture` (if given) receives the file's texture coordinates (OBJ vt,
// PLY u,v), or stays empty; `passthrough` (if given) what an OBJ carries
// besides.
TriMesh read_triangle_mesh(const std::string& path, Warnings* warnings = nullptr, MeshTexture* texture = nullptr,
                           ObjPassthrough* passthrough = nullptr);

// InputError naming `file_name`, the face and the corner unless every face
// corner has a texture coordinate; `use` ("--init file") says what needs them.
void require_corner_texture(const TriMesh& mesh, const MeshTexture& texture, const std::string& file_name,
                            const std::string& use);

// One UV per vertex from a file's texture (#V by 2, for --init file).
// InputError naming the vertex when one has two different UVs (a seam),
// or the face corner that has none.
Eigen::MatrixXd per_vertex_uv(const TriMesh& mesh, const MeshTexture& texture, const std::string& file_name);

// Writes the mesh with one `vt` per vertex and faces `f a/a b/b c/c`, so the
// vertex and face numbering of the input is kept.
//   UV  #V by 2
//   material_library  "" or an MTL file name (beside the OBJ) whose material
//                     "checker" the faces use: `mtllib` and `usemtl` lines
//                     that replace the source's
//   source            what the OBJ the mesh was read from carries besides
//                     (normals, groups, materials, colours, ...): written
//                     back in the file's order, corners keep their `vn`
void write_obj_with_uv(const std::string& path, const TriMesh& mesh, const Eigen::MatrixXd& UV,
                       const std::string& material_library = "", const ObjPassthrough* source = nullptr);

// The same with per-corner texture coordinates (seams: a vertex with one
// `vt` per side): faces `f a/i b/j c/k` with i, j, k from UV_faces.
//   UV        #T by 2
//   UV_faces  #F by 3 rows of UV
void write_obj_with_uv(const std::string& path, const TriMesh& mesh, const Eigen::MatrixXd& UV,
                       const Eigen::MatrixXi& UV_faces, const std::string& material_library = "",
                       const ObjPassthrough* source = nullptr);

// OutputError unless UV has 2 columns and UV_faces is #F by 3 rows of UV.
void check_corner_uv(const TriMesh& mesh, const Eigen::MatrixXd& UV, const Eigen::MatrixXi& UV_faces);

// How write_mesh writes the texture coordinates.
struct MeshWriteOptions {
  // OBJ: "checker" writes PATH.mtl and the checkerboard PATH_checker.png
  // beside the OBJ ("my uv.obj" -> my_uv.mtl) and vt scaled into the unit
  // square, keeping the aspect ratio; "none" writes vt as given. A GLB always
  // embeds the checkerboard with unit-square UV; a PLY has them as given.
  std::string texture = "checker";
  // What the OBJ the mesh was read from carries besides (normals, groups,
  // materials, colours): kept in an OBJ output. Null for none.
  const ObjPassthrough* obj_source = nullptr;
};

// Writes the mesh with its map, the format chosen by the extension: .obj,
// .ply or .glb (any case; a device or FIFO without one gets an OBJ). Atomically; when an OBJ fails, the side files this
// call created are removed with it.
//   uv        #V by 2 (one row per vertex), or #T by 2 with uv_faces
//   uv_faces  #F by 3 rows of uv; empty = F
// Returns the factor of the unit-square coordinates written (checker OBJ,
// GLB: uv = (written - offset) / factor), or 0 when written as given.
// OptionsError for another extension or texture mode, OutputError when
// the shapes disagree or a file cannot be written.
double write_mesh(const std::string& path, const TriMesh& mesh, const Eigen::MatrixXd& uv,
                  const Eigen::MatrixXi& uv_faces = Eigen::MatrixXi(), const MeshWriteOptions& options = {});

}  // namespace akvf
