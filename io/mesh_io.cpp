#include "akvf/mesh_io.h"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <iomanip>
#include <string_view>
#include <vector>

#include "akvf/error.h"
#include "framework/process/output_file.h"
#include "io/mesh_text.h"
#include "io/ply_reader.h"
#include "io/polygon_triangulation.h"
#include "io/stl_reader.h"
#include "io/text_reader.h"

namespace akvf {

TriMesh read_obj(std::istream& in, const std::string& file_name, Warnings* warnings, MeshTexture* texture,
                 ObjPassthrough* passthrough) {
  RawElements raw = read_obj_elements(in, file_name, 3, "face", "a face needs at least three", warnings, passthrough);
  TriMesh mesh{rows_to_matrix<double, 3>(raw.coords), Eigen::MatrixXi(), 1};
  if (auto triangulated = triangulate_polygons(mesh.V, &raw.corners, raw.sizes, file_name, warnings)) {
    std::vector<int> corner_texture(triangulated->source_corner.size());
    for (std::size_t k = 0; k < corner_texture.size(); ++k)
      corner_texture[k] = raw.corner_texture[triangulated->source_corner[k]];
    raw.corner_texture = std::move(corner_texture);
    if (passthrough) {
      passthrough->face_sizes = raw.sizes;
      passthrough->face_vertices = std::move(triangulated->file_corners);
      passthrough->triangle_source_corner = triangulated->source_corner;
    }
  }
  mesh.F = rows_to_matrix<int, 3>(raw.corners);
  if (texture && !raw.texture.empty()) {
    texture->uv = rows_to_matrix<double, 2>(raw.texture);
    texture->corner = rows_to_matrix<int, 3>(raw.corner_texture);
  }
  return mesh;
}

void require_corner_texture(const TriMesh& mesh, const MeshTexture& texture, const std::string& file_name,
                            const std::string& use) {
  if (texture.empty())
    throw InputError(file_name, 0, "has no texture coordinates (OBJ vt, PLY u,v or texcoord) for " + use);
  const int b = mesh.index_base;
  for (int f = 0; f < mesh.num_faces(); ++f)
    for (int c = 0; c < 3; ++c) {
      const int t = texture.corner(f, c);
      if (t >= 0) continue;
      const std::string corner = "corner " + std::to_string(c + 1) + " of face " + file_number(f, b);
      throw InputError(file_name, 0,
                       (t == -1 ? corner + " has no texture coordinate"
                                : corner + " names a texture coordinate the file does not have (its `vt` index is "
                                           "out of range)") +
                           numbering_note(b) + "; " + use + " needs one at every corner");
    }
}

Eigen::MatrixXd per_vertex_uv(const TriMesh& mesh, const MeshTexture& texture, const std::string& file_name) {
  require_corner_texture(mesh, texture, file_name, "--init file");
  Eigen::MatrixXd uv(mesh.num_vertices(), 2);
  std::vector<int> row_of(mesh.num_vertices(), -1);
  const int b = mesh.index_base;
  for (int f = 0; f < mesh.num_faces(); ++f)
    for (int c = 0; c < 3; ++c) {
      const int v = mesh.F(f, c), t = texture.corner(f, c);
      if (row_of[v] < 0) {
        row_of[v] = t;
        uv.row(v) = texture.uv.row(t);
      } else if (row_of[v] != t && texture.uv.row(row_of[v]) != texture.uv.row(t)) {
        throw InputError(file_name, 0,
                         "vertex " + std::to_string(v + b) + " has two different UVs (rows " +
                             std::to_string(row_of[v] + b) + " and " + std::to_string(t + b) +
                             "): a seam; --init file needs one UV per vertex of the disk");
      }
    }
  for (int v = 0; v < mesh.num_vertices(); ++v)
    if (row_of[v] < 0) uv.row(v).setZero();  // in no face: dropped by validation
  return uv;
}

TriMesh read_off(std::istream& in, const std::string& file_name, Warnings* warnings) {
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
    reader.fail("the counts (" + std::to_string(nv) + " vertices, " + std::to_string(nf) +
                (nf == 1 ? " face" : " faces") + ") are too large");

  std::vector<double> coords;
  std::vector<int> corners, sizes;
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
    if (n < 3) reader.fail("face has " + std::to_string(n) + " corners; a face needs at least three");
    if (n > static_cast<long long>(reader.tokens().size()) - 1)
      reader.fail("face lists fewer than its " + std::to_string(n) + " vertex indices");
    for (std::size_t k = 1; k <= static_cast<std::size_t>(n); ++k) {
      const long long index = reader.integer(k, "face index");
      if (index < 0 || index >= nv)
        reader.fail("face index " + std::to_string(index) + " out of range (" + std::to_string(nv) + " vertices)");
      corners.push_back(static_cast<int>(index));
    }
    sizes.push_back(static_cast<int>(n));
  }
  // The header's count must match the file in both directions.
  if (reader.next_line())
    reader.fail("more faces than the header's face count " + std::to_string(nf) +
                " (or stray text after the last face); fix the count on the header line");
  TriMesh mesh{rows_to_matrix<double, 3>(coords), Eigen::MatrixXi(), 0};
  triangulate_polygons(mesh.V, &corners, sizes, file_name, warnings);
  mesh.F = rows_to_matrix<int, 3>(corners);
  return mesh;
}

TriMesh read_triangle_mesh(const std::string& path, Warnings* warnings, MeshTexture* texture,
                           ObjPassthrough* passthrough) {
  const std::string ext = lowercase_extension(path);
  if (ext != ".obj" && ext != ".off" && ext != ".ply" && ext != ".stl")
    throw InputError(path, 0, "unsupported mesh format '" + ext + "' (expected .obj, .off, .ply or .stl)");
  std::ifstream in = open_mesh_file(path);
  if (ext == ".ply") {
    Eigen::MatrixXd uv, corner_uv;
    TriMesh mesh = read_ply(in, path, &uv, &corner_uv, warnings);
    if (texture && corner_uv.rows() > 0) {  // per corner: corner 3 f + k uses row 3 f + k
      Eigen::MatrixXi corner(mesh.num_faces(), 3);
      for (int f = 0; f < mesh.num_faces(); ++f) corner.row(f) << 3 * f, 3 * f + 1, 3 * f + 2;
      *texture = {corner_uv, corner};
    } else if (texture && uv.rows() > 0) {  // per vertex: a corner's row is its vertex
      *texture = {uv, mesh.F};
    }
    return mesh;
  }
  if (ext == ".stl") return read_stl(in, path);
  return ext == ".obj" ? read_obj(in, path, warnings, texture, passthrough) : read_off(in, path, warnings);
}

void write_obj_with_uv(const std::string& path, const TriMesh& mesh, const Eigen::MatrixXd& UV,
                       const std::string& material_library, const ObjPassthrough* source) {
  if (UV.rows() != mesh.V.rows() || UV.cols() != 2)
    throw OutputError("UV matrix is " + std::to_string(UV.rows()) + "x" + std::to_string(UV.cols()) + ", expected " +
                      std::to_string(mesh.V.rows()) + "x2");
  write_obj_with_uv(path, mesh, UV, mesh.F, material_library, source);
}

namespace {

// The source's statement lines as the output keeps them: without `mtllib`
// and `usemtl` when the output names its own material, and `l` corners
// without the texture index (the file's `vt` rows are replaced).
void write_statement(std::ostream& out, std::string_view line, bool own_material) {
  std::vector<std::string_view> tokens;
  for (std::size_t pos = 0; pos < line.size();) {
    const std::size_t start = line.find_first_not_of(" \t", pos);
    if (start == std::string_view::npos) break;
    const std::size_t end = std::min(line.find_first_of(" \t", start), line.size());
    tokens.push_back(line.substr(start, end - start));
    pos = end;
  }
  if (tokens.empty()) return;
  if (own_material && (tokens[0] == "mtllib" || tokens[0] == "usemtl")) return;
  if (tokens[0] != "l") {
    out << line << '\n';
    return;
  }
  out << 'l';
  for (std::size_t i = 1; i < tokens.size() && tokens[i][0] != '#'; ++i)
    out << ' ' << tokens[i].substr(0, tokens[i].find('/'));
  out << '\n';
}

long long count_of(const ObjPassthrough& source, ObjPassthrough::Kind kind) {
  long long n = 0;
  for (const ObjPassthrough::Run& run : source.runs)
    if (run.kind == kind) n += run.count;
  return n;
}

}  // namespace

void write_obj_with_uv(const std::string& path, const TriMesh& mesh, const Eigen::MatrixXd& UV,
                       const Eigen::MatrixXi& UV_faces, const std::string& material_library,
                       const ObjPassthrough* source) {
  using Kind = ObjPassthrough::Kind;
  check_corner_uv(mesh, UV, UV_faces);
  if (source) {
    long long triangles = count_of(*source, Kind::kFaces);
    if (!source->face_sizes.empty()) {
      triangles = 0;
      for (const int n : source->face_sizes) triangles += n - 2;
    }
    if (count_of(*source, Kind::kVertices) != mesh.num_vertices() || triangles != mesh.num_faces())
      throw OutputError("cannot write " + path + ": the OBJ source's vertex and face counts differ from the mesh's");
  }
  const bool own_material = !material_library.empty();
  write_file_atomically(path, [&](std::ostream& out) {
    out << std::setprecision(17);
    out << "# " << mesh.num_vertices() << " vertices, " << mesh.num_faces() << " faces, written by akvf\n";
    if (own_material) out << "mtllib " << material_library << '\n';
    int v = 0, f = 0;
    std::size_t tail = 0, statement = 0;
    bool uv_written = false;
    auto write_vertices = [&](long long count) {
      for (; count > 0; --count, ++v) {
        out << "v " << mesh.V(v, 0) << ' ' << mesh.V(v, 1) << ' ' << mesh.V(v, 2);
        if (source && static_cast<std::size_t>(v) < source->vertex_tail_count.size())
          for (int k = 0; k < source->vertex_tail_count[v]; ++k) out << ' ' << source->vertex_tail[tail++];
        out << '\n';
      }
    };
    // A corner: vertex / texture row / the source corner's normal.
    const std::size_t normals = source ? source->corner_normal.size() : 0;  // corners after these have none
    auto write_corner = [&](int vertex, int uv, long long source_corner) {
      out << ' ' << vertex + 1 << '/' << uv + 1;
      if (source_corner < static_cast<long long>(normals) && source->corner_normal[source_corner] >= 0)
        out << '/' << source->corner_normal[source_corner] + 1;
    };
    const bool polygons = source && !source->face_sizes.empty();
    long long polygon = 0, polygon_corner = 0;  // the next `f` line of a source with polygons, its first corner
    auto write_faces = [&](long long count) {   // `count` faces of the source (triangles without a source)
      if (!uv_written) {
        for (int i = 0; i < UV.rows(); ++i) out << "vt " << UV(i, 0) << ' ' << UV(i, 1) << '\n';
        if (own_material) out << "usemtl checker\n";
        uv_written = true;
      }
      for (; count > 0 && !polygons; --count, ++f) {
        out << 'f';
        for (int k = 0; k < 3; ++k) write_corner(mesh.F(f, k), UV_faces(f, k), 3LL * f + k);
        out << '\n';
      }
      // A polygon is written as itself when each of its corners has one
      // texture row in all of its triangles (no seam inside it), else as
      // its triangles.
      for (; count > 0 && polygons; --count, ++polygon) {
        const int n = source->face_sizes[polygon];
        std::vector<int> row(n, -1);
        bool whole = true;
        for (int t = f; t < f + n - 2; ++t)
          for (int k = 0; k < 3; ++k) {
            int& r = row[source->triangle_source_corner[3LL * t + k] - polygon_corner];
            whole = whole && (r < 0 || r == UV_faces(t, k));
            r = UV_faces(t, k);
          }
        if (whole) {
          out << 'f';
          for (int k = 0; k < n; ++k)
            write_corner(source->face_vertices[polygon_corner + k], row[k], polygon_corner + k);
          out << '\n';
        } else {
          for (int t = f; t < f + n - 2; ++t) {
            out << 'f';
            for (int k = 0; k < 3; ++k)
              write_corner(mesh.F(t, k), UV_faces(t, k), source->triangle_source_corner[3LL * t + k]);
            out << '\n';
          }
        }
        f += n - 2;
        polygon_corner += n;
      }
    };
    if (!source || source->empty()) {
      write_vertices(mesh.num_vertices());
      write_faces(mesh.num_faces());
      return;
    }
    for (const ObjPassthrough::Run& run : source->runs) {
      if (run.kind == Kind::kVertices) write_vertices(run.count);
      if (run.kind == Kind::kFaces) write_faces(run.count);
      if (run.kind != Kind::kStatements) continue;
      for (long long i = 0; i < run.count; ++i) {
        const std::size_t end = source->statements.find('\n', statement);
        write_statement(out, std::string_view(source->statements).substr(statement, end - statement), own_material);
        statement = end + 1;
      }
    }
  });
}

void check_corner_uv(const TriMesh& mesh, const Eigen::MatrixXd& UV, const Eigen::MatrixXi& UV_faces) {
  if (UV.cols() != 2) throw OutputError("UV matrix has " + std::to_string(UV.cols()) + " columns, expected 2");
  if (UV_faces.rows() != mesh.F.rows() || UV_faces.cols() != 3)
    throw OutputError("UV faces are " + std::to_string(UV_faces.rows()) + "x" + std::to_string(UV_faces.cols()) +
                      ", expected " + std::to_string(mesh.F.rows()) + "x3");
  if (UV_faces.size() > 0 && (UV_faces.minCoeff() < 0 || UV_faces.maxCoeff() >= UV.rows()))
    throw OutputError("UV faces index a row outside the " + std::to_string(UV.rows()) + " UV rows");
}

}  // namespace akvf
