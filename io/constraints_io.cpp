#include "io/constraints_io.h"

#include <unordered_map>

#include "akvf/error.h"
#include "io/mesh_text.h"
#include "io/text_reader.h"

namespace akvf {

PositionConstraints read_constraints(std::istream& in, const std::string& file_name, int num_vertices) {
  TextReader reader(in, file_name);
  std::vector<int> vertices;
  std::vector<double> targets;
  std::unordered_map<int, long> first_line;
  while (reader.next_line()) {
    if (reader.tokens().size() != 4)
      reader.fail("expected 4 columns `vertex_index x y z`, found " + std::to_string(reader.tokens().size()));
    const long long v = reader.integer(0, "vertex index");
    if (v < 0 || v >= num_vertices)
      reader.fail("vertex index " + std::to_string(v) + " out of range (" + std::to_string(num_vertices) +
                  " vertices, 0-based)");
    const auto [it, inserted] = first_line.emplace(static_cast<int>(v), reader.line_number());
    if (!inserted)
      reader.fail("vertex " + std::to_string(v) + " is already constrained on line " + std::to_string(it->second));
    vertices.push_back(static_cast<int>(v));
    for (std::size_t k = 1; k <= 3; ++k) targets.push_back(reader.real(k, "target coordinate"));
  }
  if (vertices.empty()) throw InputError(file_name, 0, "no constraints");
  return {vertices, rows_to_matrix<double, 3>(targets)};
}

PositionConstraints read_constraints_file(const std::string& path, int num_vertices) {
  std::ifstream in = open_mesh_file(path);
  return read_constraints(in, path, num_vertices);
}

}  // namespace akvf
