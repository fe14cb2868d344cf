#pragma once
// The akvf command line as a function, so tests can run it in-process.
#include <ostream>
#include <string>
#include <vector>

namespace akvf {

// Runs `akvf ARGS...` and returns the process exit code (exit_codes.h).
// Errors are reported on `err`; nothing is thrown.
int run_akvf(std::vector<std::string> args, std::ostream& out, std::ostream& err);

}  // namespace akvf
