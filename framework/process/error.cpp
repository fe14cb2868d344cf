#include "akvf/error.h"

#include <sstream>

namespace akvf {

namespace {
std::string locate(const std::string& file, long line, const std::string& problem) {
  if (line <= 0) return file + ": " + problem;
  return "line " + std::to_string(line) + " of " + file + ": " + problem;
}
}  // namespace

InputError::InputError(const std::string& file, long line, const std::string& problem)
    : Error(locate(file, line, problem)) {}

std::string number_text(double value) {
  std::ostringstream text;
  text << value;
  return text.str();
}

}  // namespace akvf
