#include "akvf/tet_mesh_io.h"

#include <cctype>
#include <iomanip>
#include <limits>

#include "akvf/error.h"
#include "framework/process/output_file.h"
#include "io/gmsh_reader.h"
#include "io/mesh_text.h"
#include "io/text_reader.h"

namespace akvf {

namespace {

// Reads `count` rows of `columns` numbers (coordinates when `is_vertex`,
// else 1-based or 0-based indices shifted by `index_base`).
void read_rows(TextReader& reader, long long count, const char* what, bool is_vertex, int index_base,
               std::vector<double>* coords, std::vector<int>* corners, std::vector<long>* lines = nullptr) {
  const int columns = is_vertex ? 3 : 4;
  for (long long i = 0; i < count; ++i) {
    if (!reader.next_line())
      reader.fail("file ends after " + std::to_string(i) + " of " + std::to_string(count) + " " + what);
    if (static_cast<int>(reader.tokens().size()) < columns)
      reader.fail(std::string(what) + " row has " + std::to_string(reader.tokens().size()) + " numbers, expected " +
                  std::to_string(columns));
    for (int k = 0; k < columns; ++k) {
      if (is_vertex) {
        coords->push_back(reader.real(k, "vertex coordinate"));
      } else {
        const long long index = reader.integer(k, "tet vertex index") - index_base;
        if (index < 0 || index > std::numeric_limits<int>::max())
          reader.fail("tet vertex index " + std::to_string(index + index_base) + " is out of range");
        corners->push_back(static_cast<int>(index));
      }
    }
    if (lines) lines->push_back(reader.line_number());
  }
}

long long read_count(TextReader& reader, const std::string& section) {
  // The count follows the keyword on its line or on the next one.
  if (reader.tokens().size() < 2 && !reader.next_line()) reader.fail("file ends after '" + section + "'");
  const long long count = reader.integer(reader.tokens().size() >= 2 ? 1 : 0, "count");
  if (count < 0) reader.fail(section + " count must be >= 0, found " + std::to_string(count));
  return count;
}

TetMesh checked_mesh(const std::string& file_name, const std::vector<double>& coords, const std::vector<int>& corners,
                     const std::vector<long>& tet_lines, int index_base) {
  const long long nv = static_cast<long long>(coords.size() / 3);
  if (nv == 0) throw InputError(file_name, 0, "no vertices");
  if (corners.empty()) throw InputError(file_name, 0, "no tetrahedra");
  for (std::size_t t = 0; t < corners.size() / 4; ++t)
    for (int k = 0; k < 4; ++k)
      if (corners[4 * t + k] >= nv)
        throw InputError(file_name, tet_lines[t],
                         "tet " + file_number(t, index_base) + " uses vertex " +
                             file_number(corners[4 * t + k], index_base) + ", out of range (" + std::to_string(nv) +
                             " vertices)" + numbering_note(index_base));
  return {rows_to_matrix<double, 3>(coords), rows_to_matrix<int, 4>(corners), index_base};
}

}  // namespace

TetMesh read_medit(std::istream& in, const std::string& file_name) {
  TextReader reader(in, file_name);
  std::vector<double> coords;
  std::vector<int> corners;
  std::vector<long> tet_lines;
  while (reader.next_line()) {
    const std::string key(reader.tokens()[0]);
    if (key == "End") break;
    if (!std::isalpha(static_cast<unsigned char>(key[0])))
      reader.fail("expected a section keyword (Vertices, Tetrahedra, ...), found '" + key + "'");
    if (key == "MeshVersionFormatted") {
      read_count(reader, key);
    } else if (key == "Dimension") {
      const long long dimension = read_count(reader, key);
      if (dimension != 3) reader.fail("dimension " + std::to_string(dimension) + ": only 3 is supported");
    } else if (key == "Vertices") {
      const long long count = read_count(reader, key);
      coords.reserve(3 * std::min(count, kMaxReserve));
      read_rows(reader, count, "vertices", true, 0, &coords, nullptr);
    } else if (key == "Tetrahedra") {
      const long long count = read_count(reader, key);
      corners.reserve(4 * std::min(count, kMaxReserve));
      read_rows(reader, count, "tetrahedra", false, 1, nullptr, &corners, &tet_lines);
    } else {
      // Triangles, Edges, Corners, ...: one record per line, skipped.
      const long long count = read_count(reader, key);
      for (long long i = 0; i < count; ++i)
        if (!reader.next_line())
          reader.fail("file ends after " + std::to_string(i) + " of " + std::to_string(count) + " " + key);
    }
  }
  return checked_mesh(file_name, coords, corners, tet_lines, 1);
}

TetMesh read_tet_obj(std::istream& in, const std::string& file_name, Warnings* warnings) {
  const RawElements raw =
      read_obj_elements(in, file_name, 4, "tet", "expected 4 (one tetrahedron per `f` line)", warnings);
  return {rows_to_matrix<double, 3>(raw.coords), rows_to_matrix<int, 4>(raw.corners), 1};
}

TetMesh read_tet_file(std::istream& in, const std::string& file_name) {
  // Two header lines the tokenizer would drop as comments.
  skip_utf8_bom(in);
  long long counts[2] = {0, 0};
  const char* keys[2] = {"#num of vertex:", "#num of tetrahedra:"};
  std::string line;
  for (int h = 0; h < 2; ++h) {
    if (!std::getline(in, line)) throw InputError(file_name, h + 1, std::string("expected '") + keys[h] + " N'");
    const std::string key = keys[h];
    if (!line.empty() && line.back() == '\r') line.pop_back();
    std::string value = line.rfind(key, 0) == 0 ? line.substr(key.size()) : "";
    value.erase(0, std::min(value.size(), value.find_first_not_of(" \t")));
    if (!parse_integer(value, &counts[h]) || counts[h] < 0)
      throw InputError(file_name, h + 1, "expected '" + key + " N', found '" + line + "'");
  }
  TextReader reader(in, file_name, 2);
  std::vector<double> coords;
  std::vector<int> corners;
  coords.reserve(3 * std::min(counts[0], kMaxReserve));
  corners.reserve(4 * std::min(counts[1], kMaxReserve));
  read_rows(reader, counts[0], "vertices", true, 0, &coords, nullptr);
  std::vector<long> tet_lines;
  read_rows(reader, counts[1], "tetrahedra", false, 0, nullptr, &corners, &tet_lines);
  return checked_mesh(file_name, coords, corners, tet_lines, 0);
}

TetMesh read_tet_mesh(const std::string& path, Warnings* warnings) {
  const std::string ext = lowercase_extension(path);
  if (ext != ".mesh" && ext != ".obj" && ext != ".tet" && ext != ".msh")
    throw InputError(path, 0, "unsupported tet mesh format '" + ext + "' (expected .mesh, .msh, .obj or .tet)");
  std::ifstream in = open_mesh_file(path);
  if (ext == ".msh") return read_gmsh(in, path);
  if (ext == ".mesh") return read_medit(in, path);
  if (ext == ".obj") return read_tet_obj(in, path, warnings);
  return read_tet_file(in, path);
}

void write_medit(const std::string& path, const TetMesh& mesh) {
  write_file_atomically(path, [&](std::ostream& out) {
    out << std::setprecision(17) << "MeshVersionFormatted 1\nDimension 3\nVertices\n" << mesh.num_vertices() << '\n';
    for (int v = 0; v < mesh.num_vertices(); ++v)
      out << mesh.V(v, 0) << ' ' << mesh.V(v, 1) << ' ' << mesh.V(v, 2) << " 0\n";
    out << "Tetrahedra\n" << mesh.num_tets() << '\n';
    for (int t = 0; t < mesh.num_tets(); ++t)
      out << mesh.T(t, 0) + 1 << ' ' << mesh.T(t, 1) + 1 << ' ' << mesh.T(t, 2) + 1 << ' ' << mesh.T(t, 3) + 1
          << " 0\n";
    out << "End\n";
  });
}

void write_vtk(const std::string& path, const TetMesh& mesh) {
  write_file_atomically(path, [&](std::ostream& out) {
    out << std::setprecision(17) << "# vtk DataFile Version 3.0\nakvf tet mesh\nASCII\nDATASET UNSTRUCTURED_GRID\n";
    out << "POINTS " << mesh.num_vertices() << " double\n";
    for (int v = 0; v < mesh.num_vertices(); ++v)
      out << mesh.V(v, 0) << ' ' << mesh.V(v, 1) << ' ' << mesh.V(v, 2) << '\n';
    out << "CELLS " << mesh.num_tets() << ' ' << 5 * mesh.num_tets() << '\n';
    for (int t = 0; t < mesh.num_tets(); ++t)
      out << "4 " << mesh.T(t, 0) << ' ' << mesh.T(t, 1) << ' ' << mesh.T(t, 2) << ' ' << mesh.T(t, 3) << '\n';
    out << "CELL_TYPES " << mesh.num_tets() << '\n';
    for (int t = 0; t < mesh.num_tets(); ++t) out << "10\n";  // VTK_TETRA
  });
}

}  // namespace akvf
