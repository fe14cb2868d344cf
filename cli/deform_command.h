#pragma once
// The `akvf deform` command; returns the process exit code (exit_codes.h).
#include <ostream>
#include <string>
#include <vector>

namespace akvf {

int deform_command(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);

}  // namespace akvf
