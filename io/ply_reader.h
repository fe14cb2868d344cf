#pragma once
// PLY triangle meshes (Turk's polygon file format), ASCII and binary (little
// and big endian), as MeshLab, Blender, CloudCompare and scanners write them.
//
// Read: the `vertex` element's x, y, z (any numeric type) and, when present,
// a per-vertex start map from u,v or s,t or texture_u,texture_v; the `face`
// element's list `vertex_indices` (or `vertex_index`), which must hold
// triangles (0-based). Other properties and elements are skipped. Errors
// name the file and the header line, the ASCII line, or the binary byte
// offset, and the problem; counts are never trusted for allocation (at most
// kMaxReserve rows are reserved ahead of the data, and a binary file must be
// long enough for what its header declares before anything is read).
#include <Eigen/Core>
#include <istream>
#include <string>

#include "akvf/mesh.h"

namespace akvf {

// uv (if given) receives #V by 2 texture coordinates, or 0 rows when the
// file has none.
// corner_uv (if given) receives the per-corner texture coordinates of a
// face list property `texcoord` (u0 v0 u1 v1 u2 v2, as MeshLab writes and
// write_ply_with_uv below for seams): 3 #F by 2, corner 3 f + k of the
// triangles in row 3 f + k; 0 rows when the file has none.
// Faces with more than three corners are triangulated, with a warning in
// `warnings` (polygon_triangulation.h).
TriMesh read_ply(std::istream& in, const std::string& file_name, Eigen::MatrixXd* uv = nullptr,
                 Eigen::MatrixXd* corner_uv = nullptr, Warnings* warnings = nullptr);

// Binary little-endian PLY with double x, y, z and per-vertex double s, t
// (the names Blender writes; MeshLab and read_ply read them), faces as
// uchar-counted int lists. Written atomically.
//   UV  #V by 2
void write_ply_with_uv(const std::string& path, const TriMesh& mesh, const Eigen::MatrixXd& UV);

// Per-corner texture coordinates (seams): the faces carry a float list
// `texcoord` of u0 v0 u1 v1 u2 v2 (the per-wedge property MeshLab reads and
// writes); the vertices only x, y, z.
//   UV        #T by 2
//   UV_faces  #F by 3 rows of UV
void write_ply_with_uv(const std::string& path, const TriMesh& mesh, const Eigen::MatrixXd& UV,
                       const Eigen::MatrixXi& UV_faces);

}  // namespace akvf
