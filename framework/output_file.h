#pragma once
// Writes an output file through a temporary name and renames it into place,
// so a failed or killed run never leaves a truncated file behind.
#include <functional>
#include <ostream>
#include <string>

namespace akvf {

void write_file_atomically(const std::string& path, const std::function<void(std::ostream&)>& write);

}  // namespace akvf
