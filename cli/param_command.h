#pragma once
// The `akvf param` and `akvf demo` commands. Each returns the process exit
// code (see exit_codes.h) and prints only to the given streams.
#include <ostream>
#include <string>
#include <vector>

namespace akvf {

int param_command(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);
int demo_command(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);

}  // namespace akvf
