#pragma once
// gmsh .msh tetrahedral meshes, ASCII format 2.2 and 4.1: what gmsh, TetGen
// and fTetWild pipelines write. The 4-node tetrahedra (element type 4) are
// read with the nodes they use; points, lines, triangles and other element
// types, and every other section ($Entities, $PhysicalNames, $NodeData, ...)
// are skipped. Node tags may be any positive numbers in any order; vertices
// are numbered by the order of the $Nodes section, tetrahedra by their order
// in $Elements (from 0). Binary .msh is refused with the gmsh setting that
// writes ASCII. Errors name the file, the line and the problem.
#include <istream>
#include <string>

#include "akvf/mesh.h"

namespace akvf {

TetMesh read_gmsh(std::istream& in, const std::string& file_name);

}  // namespace akvf
