#pragma once
// Positional constraints file: one `vertex_index x y z` per line (0-based
// index), `#` comments and blank lines ignored. Errors name the file and the
// line (InputError).
#include <istream>
#include <string>

#include "akvf/position_constraints.h"

namespace akvf {

PositionConstraints read_constraints(std::istream& in, const std::string& file_name, int num_vertices);
PositionConstraints read_constraints_file(const std::string& path, int num_vertices);

}  // namespace akvf
