#pragma once
// The `akvf view` command: a textured mesh (an OBJ with vt, a PLY with u, v
// per vertex or texcoord per corner)
// as one self-contained HTML page (pictures/html_view.h).
#include <ostream>
#include <string>
#include <vector>

namespace akvf {

int view_command(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);

}  // namespace akvf
