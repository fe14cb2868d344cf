#include "io/mesh_text.h"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <limits>
#include <map>
#include <set>

#include "akvf/error.h"
#include "io/text_reader.h"

namespace akvf {

namespace {

// The vertex index of an OBJ element corner `a`, `a/b`, `a//c` or `a/b/c`.
long long obj_corner_index(const TextReader& reader, std::string_view token, long long vertices_so_far,
                           const std::string& element) {
  const std::string_view head = token.substr(0, token.find('/'));
  long long index = 0;
  if (!parse_integer(head, &index)) {
    const bool digits = !head.empty() && std::all_of(head.begin() + (head[0] == '-' || head[0] == '+'), head.end(),
                                                     [](char c) { return c >= '0' && c <= '9'; });
    if (digits) reader.fail(element + " index " + std::string(head) + " is too large");
    reader.fail(element + " corner '" + std::string(token) + "' does not start with a vertex index (a whole number)");
  }
  if (index == 0) reader.fail(element + " corner '" + std::string(token) + "': OBJ indices start at 1, not 0");
  if (index < 0) {
    const long long resolved = vertices_so_far + index;
    if (resolved < 0)
      reader.fail("relative " + element + " index " + std::to_string(index) + " reaches before the first vertex (" +
                  std::to_string(vertices_so_far) + " vertices so far)");
    return resolved;
  }
  return index - 1;
}

// The `vt` index of a corner `a/b` or `a/b/c` (0-based); -1 for `a` and
// `a//c`; -2 for an index that names no `vt` read so far (the geometry is
// still read; only what uses the texture needs it, and it names the face).
int obj_texture_index(std::string_view token, long long textures_so_far) {
  const std::size_t slash = token.find('/');
  if (slash == std::string_view::npos) return -1;
  std::string_view rest = token.substr(slash + 1);
  rest = rest.substr(0, rest.find('/'));
  if (rest.empty()) return -1;
  long long index = 0;
  if (!parse_integer(rest, &index) || index == 0) return -2;
  const long long resolved = index < 0 ? textures_so_far + index : index - 1;
  return resolved >= 0 && resolved < textures_so_far ? static_cast<int>(resolved) : -2;
}

// The `vn` index of a corner `a/b/c` or `a//c` (0-based), or -1 (none, or
// one that names no `vn` read so far).
int obj_normal_index(std::string_view token, long long normals_so_far) {
  const std::size_t first = token.find('/');
  if (first == std::string_view::npos) return -1;
  const std::size_t second = token.find('/', first + 1);
  if (second == std::string_view::npos) return -1;
  long long index = 0;
  if (!parse_integer(token.substr(second + 1), &index) || index == 0) return -1;
  const long long resolved = index < 0 ? normals_so_far + index : index - 1;
  return resolved >= 0 && resolved < normals_so_far ? static_cast<int>(resolved) : -1;
}

// Records the current line of `reader` in `passthrough`: its kind, and what
// the OBJ writer needs to put it back (obj_passthrough.h).
void keep_line(const TextReader& reader, long long vertices_so_far, long long normals_so_far, long long corners_so_far,
               ObjPassthrough& passthrough) {
  using Kind = ObjPassthrough::Kind;
  const auto& t = reader.tokens();
  if (t[0] == "v") {
    passthrough.add(Kind::kVertices);
    if (t.size() > 4 || !passthrough.vertex_tail_count.empty()) {  // none before: zeros up to here
      passthrough.vertex_tail_count.resize(static_cast<std::size_t>(vertices_so_far), 0);
      passthrough.vertex_tail_count.push_back(static_cast<std::uint8_t>(t.size() - 4));
      for (std::size_t i = 4; i < t.size(); ++i) passthrough.vertex_tail.push_back(reader.real(i, "vertex colour"));
    }
  } else if (t[0] == "vt") {
    passthrough.add(Kind::kTextures);
  } else if (t[0] == "f") {
    passthrough.add(Kind::kFaces);
    std::vector<int>& normal = passthrough.corner_normal;
    for (std::size_t i = 1; i < t.size(); ++i) {
      const int n = obj_normal_index(t[i], normals_so_far);
      if (n < 0 && normal.empty()) continue;
      normal.resize(static_cast<std::size_t>(corners_so_far) + i - 1, -1);  // none before: -1 up to here
      normal.push_back(n);
    }
  } else {
    passthrough.add(Kind::kStatements);
    std::string_view line = reader.line();
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    passthrough.statements.append(line).push_back('\n');
    if (t[0] == "mtllib")
      for (std::size_t i = 1; i < t.size(); ++i) passthrough.material_libraries.emplace_back(t[i]);
  }
}

// A UTF-16 byte-order mark at the start: a text reader of bytes would see
// no statement at all.
void refuse_utf16(std::istream& in, const std::string& file_name) {
  const int first = in.peek();
  if (first != 0xFF && first != 0xFE) return;
  in.get();
  const int second = in.peek();
  in.unget();
  if ((first == 0xFF && second == 0xFE) || (first == 0xFE && second == 0xFF))
    throw InputError(file_name, 1, "the file is UTF-16; save it as UTF-8 or ASCII");
}

}  // namespace

RawElements read_obj_elements(std::istream& in, const std::string& file_name, int corners, const std::string& element,
                              const std::string& advice, Warnings* warnings, ObjPassthrough* passthrough) {
  // Statements of the OBJ format that carry nothing a distortion energy uses.
  static const std::set<std::string, std::less<>> kIgnored = {"vn", "vp", "g", "o", "s", "usemtl", "mtllib", "l", "p"};
  refuse_utf16(in, file_name);
  TextReader reader(in, file_name, 0, true);
  RawElements raw;
  std::vector<long> element_lines;
  std::map<std::string, std::pair<long, long>> unknown;  // statement -> (first line, count)
  long long normals = 0;
  while (reader.next_line()) {
    const auto& t = reader.tokens();
    if (t[0].find('\0') != std::string_view::npos)
      reader.fail("a NUL byte: the file is not text (UTF-16? save it as UTF-8 or ASCII)");
    const long long vertices_before = static_cast<long long>(raw.coords.size() / 3);
    const long long corners_before = static_cast<long long>(raw.corners.size());
    if (t[0] == "v") {
      // x y z, an optional weight w, or the common x y z r g b colour extension.
      if (t.size() < 4) reader.fail("vertex needs three coordinates, found " + std::to_string(t.size() - 1));
      if (t.size() != 4 && t.size() != 5 && t.size() != 7)
        reader.fail("vertex has " + std::to_string(t.size() - 1) +
                    " numbers; expected x y z, x y z w, or x y z r g b (extra tokens after the coordinates)");
      for (std::size_t i = 1; i <= 3; ++i) raw.coords.push_back(reader.real(i, "vertex coordinate"));
      for (std::size_t i = 4; i < t.size(); ++i) reader.real(i, t.size() == 5 ? "vertex weight w" : "vertex colour");
    } else if (t[0] == "vt") {
      // u [v [w]]; only u and v are used (a start map, akvf param --init file).
      if (t.size() < 2 || t.size() > 4) reader.fail("vt needs u, v (and an optional w)");
      raw.texture.push_back(reader.real(1, "texture coordinate"));
      raw.texture.push_back(t.size() > 2 ? reader.real(2, "texture coordinate") : 0.0);
    } else if (t[0] == "f") {
      const int found = static_cast<int>(t.size()) - 1;
      if (corners == 3 ? found < 3 : found != corners)
        reader.fail(element + " has " + std::to_string(found) + (found == 1 ? " corner; " : " corners; ") + advice);
      raw.sizes.push_back(found);
      for (int i = 1; i <= found; ++i) {
        const long long index = obj_corner_index(reader, t[i], vertices_before, element);
        if (index > std::numeric_limits<int>::max())
          reader.fail(element + " index " + std::to_string(index + 1) + " is too large");
        raw.corners.push_back(static_cast<int>(index));
        raw.corner_texture.push_back(obj_texture_index(t[i], static_cast<long long>(raw.texture.size() / 2)));
      }
      element_lines.push_back(reader.line_number());
    } else if (!kIgnored.count(t[0])) {
      auto [it, inserted] = unknown.try_emplace(std::string(t[0]), reader.line_number(), 0);
      ++it->second.second;
    }
    if (passthrough) keep_line(reader, vertices_before, normals, corners_before, *passthrough);
    if (t[0] == "vn") ++normals;
  }
  if (warnings)
    for (const auto& [statement, where] : unknown)
      warnings->push_back("line " + std::to_string(where.first) + " of " + file_name + ": unknown OBJ statement '" +
                          statement + "' ignored (" + std::to_string(where.second) + " line" +
                          (where.second == 1 ? "" : "s") + ")");
  const long long nv = static_cast<long long>(raw.coords.size() / 3);
  std::size_t first = 0;
  for (std::size_t e = 0; e < element_lines.size(); first += raw.sizes[e], ++e)
    for (int k = 0; k < raw.sizes[e]; ++k)
      if (raw.corners[first + k] >= nv)
        throw InputError(file_name, element_lines[e],
                         element + " index " + std::to_string(static_cast<long long>(raw.corners[first + k]) + 1) +
                             " out of range (" + std::to_string(nv) + " vertices)");
  if (nv == 0) throw InputError(file_name, 0, "no vertices");
  if (element_lines.empty()) throw InputError(file_name, 0, "no " + element + "s");
  return raw;
}

std::string lowercase_extension(const std::string& path) {
  const auto slash = path.find_last_of('/');
  const auto dot = path.find_last_of('.');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return "";
  std::string ext = path.substr(dot);
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext;
}

std::ifstream open_mesh_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, 0, std::string("cannot open: ") + std::strerror(errno));
  return in;
}

}  // namespace akvf
