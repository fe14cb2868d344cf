#include "framework/mesh_io.h"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <iomanip>

#include "framework/error.h"
#include "framework/output_file.h"
#include "framework/text_reader.h"

namespace akvf {

namespace {

// Upper bound on what a header count may make us reserve before the data is
// seen; larger meshes simply grow their vectors as rows arrive.
constexpr long long kMaxReserve = 1 << 20;

TriMesh to_mesh(const std::vector<double>& coords, const std::vector<int>& corners) {
  TriMesh mesh;
  const auto nv = static_cast<Eigen::Index>(coords.size() / 3);
  const auto nf = static_cast<Eigen::Index>(corners.size() / 3);
  mesh.V = Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>>(coords.data(), nv, 3);
  mesh.F = Eigen::Map<const Eigen::Matrix<int, Eigen::Dynamic, 3, Eigen::RowMajor>>(corners.data(), nf, 3);
  return mesh;
}

// The vertex index of an OBJ face corner `a`, `a/b`, `a//c` or `a/b/c`.
long long obj_corner_index(const TextReader& reader, std::string_view token, long long vertices_so_far) {
  const std::string_view head = token.substr(0, token.find('/'));
  long long index = 0;
  if (!parse_integer(head, &index))
    reader.fail("face corner '" + std::string(token) + "' does not start with a vertex index");
  if (index == 0) reader.fail("face corner '" + std::string(token) + "': OBJ indices start at 1, not 0");
  if (index < 0) {
    const long long resolved = vertices_so_far + index;
    if (resolved < 0)
      reader.fail("relative face index " + std::to_string(index) + " reaches before the first vertex (" +
                  std::to_string(vertices_so_far) + " vertices so far)");
    return resolved;
  }
  return index - 1;
}

std::string lowercase_extension(const std::string& path) {
  const auto slash = path.find_last_of('/');
  const auto dot = path.find_last_of('.');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return "";
  std::string ext = path.substr(dot);
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext;
}

}  // namespace

TriMesh read_obj(std::istream& in, const std::string& file_name) {
  TextReader reader(in, file_name);
  std::vector<double> coords;
  std::vector<int> corners;
  std::vector<long> face_lines;
  std::vector<long long> raw;
  while (reader.next_line()) {
    const auto& t = reader.tokens();
    if (t[0] == "v") {
      if (t.size() < 4) reader.fail("vertex needs three coordinates, found " + std::to_string(t.size() - 1));
      for (std::size_t i = 1; i <= 3; ++i) coords.push_back(reader.real(i, "vertex coordinate"));
    } else if (t[0] == "f") {
      if (t.size() != 4)
        reader.fail("face has " + std::to_string(t.size() - 1) +
                    " corners; only triangles are supported (triangulate the mesh first)");
      const long long vertices_so_far = static_cast<long long>(coords.size() / 3);
      raw.clear();
      for (std::size_t i = 1; i <= 3; ++i) raw.push_back(obj_corner_index(reader, t[i], vertices_so_far));
      for (long long index : raw) {
        if (index > std::numeric_limits<int>::max())
          reader.fail("face index " + std::to_string(index + 1) + " is too large");
        corners.push_back(static_cast<int>(index));
      }
      face_lines.push_back(reader.line_number());
    }
    // vt, vn, vp, g, o, s, l, usemtl, mtllib and unknown records carry nothing we use.
  }
  const long long nv = static_cast<long long>(coords.size() / 3);
  for (std::size_t f = 0; f < face_lines.size(); ++f)
    for (int k = 0; k < 3; ++k)
      if (corners[3 * f + k] >= nv)
        throw InputError(file_name, face_lines[f],
                         "face index " + std::to_string(corners[3 * f + k] + 1) + " out of range (" +
                             std::to_string(nv) + " vertices)");
  if (nv == 0) throw InputError(file_name, 0, "no vertices");
  if (face_lines.empty()) throw InputError(file_name, 0, "no faces");
  return to_mesh(coords, corners);
}

TriMesh read_off(std::istream& in, const std::string& file_name) {
  TextReader reader(in, file_name);
  if (!reader.next_line()) throw InputError(file_name, 0, "empty file (expected an 'OFF' header)");
  const std::string header(reader.tokens()[0]);
  if (header != "OFF" && header != "COFF" && header != "NOFF" && header != "CNOFF")
    reader.fail("expected an 'OFF' header, found '" + header + "'");
  std::size_t first = 1;  // the counts may follow the header on the same line
  if (reader.tokens().size() == 1) {
    if (!reader.next_line()) throw InputError(file_name, reader.line_number(), "file ends before the counts line");
    first = 0;
  }
  const long long nv = reader.integer(first, "vertex count");
  const long long nf = reader.integer(first + 1, "face count");
  if (nv <= 0) reader.fail("vertex count must be positive, found " + std::to_string(nv));
  if (nf <= 0) reader.fail("face count must be positive, found " + std::to_string(nf));
  if (nv > std::numeric_limits<int>::max() || nf > std::numeric_limits<int>::max())
    reader.fail("counts " + std::to_string(nv) + " vertices, " + std::to_string(nf) + " faces are too large");

  std::vector<double> coords;
  std::vector<int> corners;
  coords.reserve(3 * std::min(nv, kMaxReserve));
  corners.reserve(3 * std::min(nf, kMaxReserve));
  for (long long i = 0; i < nv; ++i) {
    if (!reader.next_line())
      throw InputError(file_name, reader.line_number(),
                       "file ends after " + std::to_string(i) + " of " + std::to_string(nv) + " vertices");
    for (std::size_t k = 0; k < 3; ++k) coords.push_back(reader.real(k, "vertex coordinate"));
  }
  for (long long f = 0; f < nf; ++f) {
    if (!reader.next_line())
      throw InputError(file_name, reader.line_number(),
                       "file ends after " + std::to_string(f) + " of " + std::to_string(nf) + " faces");
    const long long n = reader.integer(0, "face corner count");
    if (n != 3)
      reader.fail("face has " + std::to_string(n) +
                  " corners; only triangles are supported (triangulate the mesh first)");
    if (reader.tokens().size() < 4) reader.fail("face lists fewer than 3 vertex indices");
    for (std::size_t k = 1; k <= 3; ++k) {
      const long long index = reader.integer(k, "face index");
      if (index < 0 || index >= nv)
        reader.fail("face index " + std::to_string(index) + " out of range (" + std::to_string(nv) + " vertices)");
      corners.push_back(static_cast<int>(index));
    }
  }
  return to_mesh(coords, corners);
}

TriMesh read_triangle_mesh(const std::string& path) {
  const std::string ext = lowercase_extension(path);
  if (ext != ".obj" && ext != ".off")
    throw InputError(path, 0, "unsupported mesh format '" + ext + "' (expected .obj or .off)");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, 0, std::string("cannot open: ") + std::strerror(errno));
  return ext == ".obj" ? read_obj(in, path) : read_off(in, path);
}

void write_obj_with_uv(const std::string& path, const TriMesh& mesh, const Eigen::MatrixXd& UV) {
  if (UV.rows() != mesh.V.rows() || UV.cols() != 2)
    throw OutputError("UV matrix is " + std::to_string(UV.rows()) + "x" + std::to_string(UV.cols()) + ", expected " +
                      std::to_string(mesh.V.rows()) + "x2");
  write_file_atomically(path, [&](std::ostream& out) {
    out << std::setprecision(17);
    out << "# " << mesh.num_vertices() << " vertices, " << mesh.num_faces() << " faces, written by akvf\n";
    for (int i = 0; i < mesh.num_vertices(); ++i)
      out << "v " << mesh.V(i, 0) << ' ' << mesh.V(i, 1) << ' ' << mesh.V(i, 2) << '\n';
    for (int i = 0; i < mesh.num_vertices(); ++i) out << "vt " << UV(i, 0) << ' ' << UV(i, 1) << '\n';
    for (int f = 0; f < mesh.num_faces(); ++f) {
      out << 'f';
      for (int k = 0; k < 3; ++k) out << ' ' << mesh.F(f, k) + 1 << '/' << mesh.F(f, k) + 1;
      out << '\n';
    }
  });
}

}  // namespace akvf
