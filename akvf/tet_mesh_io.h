#pragma once
// Tetrahedral mesh readers and writers, with the readers' errors naming the
// file, the line and the problem (InputError).
#include <istream>
#include <string>

#include "akvf/mesh.h"

namespace akvf {

// MEDIT .mesh: `Vertices` (count, then `x y z ref` rows) and `Tetrahedra`
// (count, then `a b c d ref` rows, 1-based); other sections are skipped.
TetMesh read_medit(std::istream& in, const std::string& file_name);

// The OBJ-like form of SLIM's data: `v x y z` and `f a b c d` (1-based).
TetMesh read_tet_obj(std::istream& in, const std::string& file_name, Warnings* warnings = nullptr);

// The .tet form: `#num of vertex: N`, `#num of tetrahedra: M`, then N rows
// `x y z` and M rows `a b c d` (0-based).
TetMesh read_tet_file(std::istream& in, const std::string& file_name);

// Dispatches on the extension: .mesh, .msh (gmsh_reader.h), .obj or .tet.
TetMesh read_tet_mesh(const std::string& path, Warnings* warnings = nullptr);

// MEDIT .mesh (1-based, reference 0) and VTK legacy ASCII unstructured grid.
void write_medit(const std::string& path, const TetMesh& mesh);
void write_vtk(const std::string& path, const TetMesh& mesh);

}  // namespace akvf
