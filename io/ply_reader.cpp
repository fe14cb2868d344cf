#include "io/ply_reader.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <iterator>
#include <limits>
#include <optional>
#include <vector>

#include "akvf/error.h"
#include "akvf/mesh_io.h"
#include "framework/process/output_file.h"
#include "io/mesh_text.h"
#include "io/polygon_triangulation.h"
#include "io/text_reader.h"

namespace akvf {

namespace {

enum class Format { kAscii, kLittleEndian, kBigEndian };

struct ScalarType {
  int bytes = 0;
  bool real = false, is_signed = false;
};

std::optional<ScalarType> scalar_type(std::string_view name) {
  if (name == "char" || name == "int8") return ScalarType{1, false, true};
  if (name == "uchar" || name == "uint8") return ScalarType{1, false, false};
  if (name == "short" || name == "int16") return ScalarType{2, false, true};
  if (name == "ushort" || name == "uint16") return ScalarType{2, false, false};
  if (name == "int" || name == "int32") return ScalarType{4, false, true};
  if (name == "uint" || name == "uint32") return ScalarType{4, false, false};
  if (name == "float" || name == "float32") return ScalarType{4, true, true};
  if (name == "double" || name == "float64") return ScalarType{8, true, true};
  return std::nullopt;
}

struct Property {
  std::string name;
  ScalarType type;
  bool list = false;
  ScalarType count_type;  // of a list
};

struct Element {
  std::string name;
  long long count = 0;
  long header_line = 0;
  std::vector<Property> properties;
  int find(std::string_view property) const {
    for (std::size_t i = 0; i < properties.size(); ++i)
      if (properties[i].name == property) return static_cast<int>(i);
    return -1;
  }
  // Bytes of a row in a binary file, lists counted as empty: a lower bound.
  long long min_row_bytes() const {
    long long bytes = 0;
    for (const Property& p : properties) bytes += p.list ? p.count_type.bytes : p.type.bytes;
    return bytes;
  }
};

// What a body value is, spelled out only for a message: property P of
// ELEMENT ROW, the length of its list, or an item of it.
struct Where {
  const std::string* element = nullptr;
  long long row = 0;
  const std::string* property = nullptr;
  int item = -1;  // -1: a scalar property, -2: a list's length, k >= 0: item k of a list
  std::string text() const {
    const std::string of = "property '" + *property + "' of " + *element + " " + std::to_string(row);
    if (item == -2) return "the length of " + of;
    if (item >= 0) return "item " + std::to_string(item) + " of " + of;
    return of;
  }
};

std::vector<std::string_view> split(std::string_view line) {
  std::vector<std::string_view> tokens;
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && std::isspace(static_cast<unsigned char>(line[i]))) ++i;
    const std::size_t start = i;
    while (i < line.size() && !std::isspace(static_cast<unsigned char>(line[i]))) ++i;
    if (i > start) tokens.push_back(line.substr(start, i - start));
  }
  return tokens;
}

// The values of the file's body, one at a time: ASCII tokens (with their
// line numbers) or binary scalars (with their byte offsets).
class Body {
 public:
  Body(const std::string& data, std::size_t start, long first_line, Format format, const std::string& file)
      : data_(data), position_(start), line_(first_line), format_(format), file_(file) {}

  double value(const ScalarType& type, const Where& where) {
    if (format_ == Format::kAscii) {
      const std::string_view token = next_token(where);
      if (!type.real) {  // within its type's range, so every integer read fits a long long
        long long i = 0;
        const int bits = 8 * type.bytes;
        const long long low = type.is_signed ? -(1LL << (bits - 1)) : 0;
        const long long high = type.is_signed ? (1LL << (bits - 1)) - 1 : (1LL << bits) - 1;
        if (!parse_integer(token, &i) || i < low || i > high)
          fail("'" + std::string(token) + "' is not an integer of the declared type (" + where.text() + ")");
        return static_cast<double>(i);
      }
      double v = 0;
      if (!parse_real(token, &v)) fail("'" + std::string(token) + "' is not a number (" + where.text() + ")");
      return v;
    }
    if (data_.size() - position_ < static_cast<std::size_t>(type.bytes))
      fail("the file ends inside " + where.text() + " (truncated?)");
    unsigned char bytes[8];
    std::memcpy(bytes, data_.data() + position_, type.bytes);
    const std::size_t at = position_;
    position_ += type.bytes;
    if (format_ == Format::kBigEndian) std::reverse(bytes, bytes + type.bytes);
    double v = 0;
    if (type.real) {
      if (type.bytes == 4) {
        float f;
        std::memcpy(&f, bytes, 4);
        v = f;
      } else {
        std::memcpy(&v, bytes, 8);
      }
      if (!std::isfinite(v)) fail_at(at, where.text() + " is not finite");
      return v;
    }
    unsigned long long u = 0;
    for (int b = type.bytes - 1; b >= 0; --b) u = (u << 8) | bytes[b];
    if (type.is_signed && type.bytes < 8 && (u >> (8 * type.bytes - 1)) & 1) {
      const long long negative = static_cast<long long>(u) - (1LL << (8 * type.bytes));
      return static_cast<double>(negative);
    }
    return static_cast<double>(u);
  }

  // ASCII: each element row ends its line.
  void end_row(const Where& where) {
    if (format_ != Format::kAscii) return;
    if (token_ < tokens_.size())
      fail("more values than the header declares for " + *where.element + " " + std::to_string(where.row));
    tokens_.clear();
    token_ = 0;
  }

  // After the last element: only white space may follow (ASCII), nothing (binary).
  void finish() {
    if (format_ == Format::kAscii) {
      while (next_line()) fail("more rows than the header's element counts declare; fix the counts in the header");
      return;
    }
    if (position_ != data_.size())
      fail_at(position_, std::to_string(data_.size() - position_) +
                             " bytes follow the last element the header declares; fix the counts in the header");
  }

  [[noreturn]] void fail(const std::string& problem) const {
    if (format_ == Format::kAscii) throw InputError(file_, line_, problem);
    fail_at(position_, problem);
  }
  [[noreturn]] void fail_at(std::size_t offset, const std::string& problem) const {
    throw InputError(file_, 0, "byte " + std::to_string(offset) + ": " + problem);
  }

 private:
  bool next_line() {
    while (position_ < data_.size()) {
      std::size_t end = data_.find('\n', position_);
      if (end == std::string::npos) end = data_.size();
      const std::string_view line(data_.data() + position_, end - position_);
      position_ = end + 1;
      ++line_;
      tokens_ = split(line);
      token_ = 0;
      if (!tokens_.empty()) return true;
    }
    return false;
  }
  std::string_view next_token(const Where& where) {
    if (token_ == tokens_.size()) {
      if (!tokens_.empty()) fail("the line ends before " + where.text());
      if (!next_line()) fail("the file ends before " + where.text());
    }
    return tokens_[token_++];
  }

  const std::string& data_;
  std::size_t position_;
  long line_;
  Format format_;
  const std::string& file_;
  std::vector<std::string_view> tokens_;
  std::size_t token_ = 0;
};

// The header: format and elements; `body_start` receives the offset of the
// first byte after `end_header`, `body_line` the header's line count.
std::vector<Element> read_header(const std::string& data, const std::string& file, Format* format,
                                 std::size_t* body_start, long* body_line) {
  std::size_t position = data.compare(0, 3, "\xEF\xBB\xBF") == 0 ? 3 : 0;
  long line = 0;
  std::vector<Element> elements;
  bool have_format = false;
  while (true) {
    if (position >= data.size()) throw InputError(file, line, "the header has no 'end_header' line");
    std::size_t end = data.find('\n', position);
    if (end == std::string::npos) end = data.size();
    std::string_view text(data.data() + position, end - position);
    position = end + 1;
    ++line;
    if (!text.empty() && text.back() == '\r') text.remove_suffix(1);
    const std::vector<std::string_view> t = split(text);
    const auto fail = [&](const std::string& problem) { throw InputError(file, line, problem); };
    if (line == 1) {
      if (t.size() != 1 || t[0] != "ply") fail("not a PLY file (the first line must be 'ply')");
      continue;
    }
    if (t.empty() || t[0] == "comment" || t[0] == "obj_info") continue;
    if (t[0] == "end_header") break;
    if (t[0] == "format") {
      if (t.size() != 3) fail("expected 'format ascii|binary_little_endian|binary_big_endian 1.0'");
      if (t[1] == "ascii")
        *format = Format::kAscii;
      else if (t[1] == "binary_little_endian")
        *format = Format::kLittleEndian;
      else if (t[1] == "binary_big_endian")
        *format = Format::kBigEndian;
      else
        fail("unknown PLY format '" + std::string(t[1]) + "'");
      if (t[2] != "1.0") fail("unsupported PLY version '" + std::string(t[2]) + "' (expected 1.0)");
      have_format = true;
    } else if (t[0] == "element") {
      if (t.size() != 3) fail("expected 'element NAME COUNT'");
      long long count = 0;
      if (!parse_integer(t[2], &count) || count < 0 || count > std::numeric_limits<int>::max())
        fail("element count '" + std::string(t[2]) + "' is not a count between 0 and 2^31 - 1");
      elements.push_back({std::string(t[1]), count, line, {}});
    } else if (t[0] == "property") {
      if (elements.empty()) fail("a property before any element");
      Property p;
      if (t.size() == 5 && t[1] == "list") {
        const auto count = scalar_type(t[2]), item = scalar_type(t[3]);
        if (!count || !item) fail("unknown property type in '" + std::string(text) + "'");
        if (count->real) fail("a list count must have an integer type, found '" + std::string(t[2]) + "'");
        p = {std::string(t[4]), *item, true, *count};
      } else if (t.size() == 3) {
        const auto type = scalar_type(t[1]);
        if (!type) fail("unknown property type '" + std::string(t[1]) + "'");
        p = {std::string(t[2]), *type, false, {}};
      } else {
        fail("expected 'property TYPE NAME' or 'property list COUNT_TYPE ITEM_TYPE NAME'");
      }
      if (elements.back().find(p.name) >= 0) fail("property '" + p.name + "' appears twice");
      elements.back().properties.push_back(p);
    } else {
      fail("unknown header line '" + std::string(t[0]) + "'");
    }
  }
  if (!have_format) throw InputError(file, line, "the header has no 'format' line");
  // Rows of no property hold nothing to read: billions of them would be
  // counted one by one.
  for (const Element& element : elements)
    if (element.count > 0 && element.properties.empty())
      throw InputError(
          file, element.header_line,
          "element '" + element.name + "' declares " + std::to_string(element.count) + " rows but no property");
  *body_start = position;
  *body_line = line;
  return elements;
}

}  // namespace

TriMesh read_ply(std::istream& in, const std::string& file_name, Eigen::MatrixXd* uv, Eigen::MatrixXd* corner_uv,
                 Warnings* warnings) {
  const std::string data{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  Format format = Format::kAscii;
  std::size_t body_start = 0;
  long body_line = 0;
  const std::vector<Element> elements = read_header(data, file_name, &format, &body_start, &body_line);

  const auto vertex_element =
      std::find_if(elements.begin(), elements.end(), [](const Element& e) { return e.name == "vertex"; });
  const auto face_element =
      std::find_if(elements.begin(), elements.end(), [](const Element& e) { return e.name == "face"; });
  if (vertex_element == elements.end())
    throw InputError(file_name, body_line, "the header declares no 'vertex' element");
  if (face_element == elements.end())
    throw InputError(file_name, body_line, "the header declares no 'face' element (a point cloud is not a mesh)");
  const Element& vertices = *vertex_element;
  const Element& faces = *face_element;
  const int x = vertices.find("x"), y = vertices.find("y"), z = vertices.find("z");
  for (const auto& [index, name] : {std::pair{x, "x"}, {y, "y"}, {z, "z"}})
    if (index < 0 || vertices.properties[index].list)
      throw InputError(file_name, vertices.header_line,
                       std::string("the vertex element has no '") + name + "' property");
  int u = -1, v = -1;
  for (const auto& [a, b] : {std::pair{"u", "v"}, {"s", "t"}, {"texture_u", "texture_v"}})
    if (u < 0 && vertices.find(a) >= 0 && vertices.find(b) >= 0) {
      u = vertices.find(a);
      v = vertices.find(b);
    }
  int corners = faces.find("vertex_indices");
  if (corners < 0) corners = faces.find("vertex_index");
  if (corners < 0 || !faces.properties[corners].list || faces.properties[corners].type.real)
    throw InputError(file_name, faces.header_line, "the face element has no integer list 'vertex_indices'");
  int texcoord = faces.find("texcoord");
  if (texcoord >= 0 && (!faces.properties[texcoord].list || !faces.properties[texcoord].type.real))
    throw InputError(file_name, faces.header_line,
                     "the face property 'texcoord' is " +
                         std::string(faces.properties[texcoord].list ? "a list of integers" : "not a list") +
                         "; texture coordinates are a float or double list (u, v per corner)");
  if (vertices.count == 0) throw InputError(file_name, vertices.header_line, "the file has no vertices");
  if (faces.count == 0) throw InputError(file_name, faces.header_line, "the file has no faces");
  // A binary file must hold at least what its header declares before any
  // count is trusted.
  if (format != Format::kAscii) {
    long long needed = 0;
    for (const Element& e : elements) needed += e.count * e.min_row_bytes();
    if (static_cast<long long>(data.size() - body_start) < needed)
      throw InputError(file_name, 0,
                       "the header declares at least " + std::to_string(needed) + " bytes of data but the file has " +
                           std::to_string(data.size() - body_start) + " (truncated, or wrong counts)");
  }

  std::vector<double> coords, texture, corner_texture;
  std::vector<int> triangle_corners, sizes;  // the faces' corners one after another, and per face its count
  std::vector<long long> texcoord_counts;
  coords.reserve(3 * std::min(vertices.count, kMaxReserve));
  if (u >= 0) texture.reserve(2 * std::min(vertices.count, kMaxReserve));
  if (texcoord >= 0) corner_texture.reserve(6 * std::min(faces.count, kMaxReserve));
  triangle_corners.reserve(3 * std::min(faces.count, kMaxReserve));
  Body body(data, body_start, body_line, format, file_name);
  std::vector<double> scalars;
  for (const Element& element : elements) {
    scalars.assign(element.properties.size(), 0.0);
    for (long long row = 0; row < element.count; ++row) {
      Where where{&element.name, row, nullptr, -1};
      for (std::size_t p = 0; p < element.properties.size(); ++p) {
        const Property& property = element.properties[p];
        where.property = &property.name;
        where.item = -1;
        if (!property.list) {
          scalars[p] = body.value(property.type, where);
          continue;
        }
        where.item = -2;
        const double count = body.value(property.count_type, where);
        if (count < 0) body.fail("negative list length in " + where.text());
        const bool is_corners = &element == &faces && static_cast<int>(p) == corners;
        const bool is_texcoord = &element == &faces && static_cast<int>(p) == texcoord;
        if (is_corners && count < 3)
          body.fail("face " + std::to_string(row) + " has " + std::to_string(static_cast<long long>(count)) +
                    " corners; a face needs at least three");
        if (is_corners) sizes.push_back(static_cast<int>(count));
        if (is_texcoord) texcoord_counts.push_back(static_cast<long long>(count));
        for (long long k = 0; k < static_cast<long long>(count); ++k) {
          where.item = static_cast<int>(std::min<long long>(k, std::numeric_limits<int>::max()));
          const double item = body.value(property.type, where);
          if (is_texcoord) {
            if (!std::isfinite(item)) body.fail("a texcoord value of face " + std::to_string(row) + " is not finite");
            corner_texture.push_back(item);
          }
          if (!is_corners) continue;
          if (item < 0 || item >= static_cast<double>(vertices.count))
            body.fail("face " + std::to_string(row) + ": vertex index " + std::to_string(static_cast<long long>(item)) +
                      " out of range (" + std::to_string(vertices.count) + " vertices, numbered from 0)");
          triangle_corners.push_back(static_cast<int>(item));
        }
      }
      body.end_row(where);
      if (&element == &vertices) {
        for (const int c : {x, y, z}) {
          if (!std::isfinite(scalars[c])) body.fail("a coordinate of vertex " + std::to_string(row) + " is not finite");
          coords.push_back(scalars[c]);
        }
        if (u >= 0) {
          texture.push_back(scalars[u]);
          texture.push_back(scalars[v]);
        }
      }
    }
  }
  body.finish();
  for (std::size_t f = 0; f < texcoord_counts.size(); ++f)
    if (texcoord_counts[f] != 2LL * sizes[f])
      throw InputError(file_name, 0,
                       "face " + std::to_string(f) + " has " + std::to_string(texcoord_counts[f]) +
                           " texcoord values; its " + std::to_string(sizes[f]) + " corners need " +
                           std::to_string(2 * sizes[f]) + " (u, v per corner)");
  TriMesh mesh{rows_to_matrix<double, 3>(coords), Eigen::MatrixXi(), 0};
  const auto triangulated = triangulate_polygons(mesh.V, &triangle_corners, sizes, file_name, warnings);
  if (triangulated) {
    if (texcoord >= 0) {
      std::vector<double> by_triangle;
      by_triangle.reserve(2 * triangulated->source_corner.size());
      for (const long long c : triangulated->source_corner) {
        by_triangle.push_back(corner_texture[2 * c]);
        by_triangle.push_back(corner_texture[2 * c + 1]);
      }
      corner_texture = std::move(by_triangle);
    }
  }
  mesh.F = rows_to_matrix<int, 3>(triangle_corners);
  if (uv) *uv = u >= 0 ? Eigen::MatrixXd(rows_to_matrix<double, 2>(texture)) : Eigen::MatrixXd(0, 2);
  if (corner_uv)
    *corner_uv = texcoord >= 0 ? Eigen::MatrixXd(rows_to_matrix<double, 2>(corner_texture)) : Eigen::MatrixXd(0, 2);
  return mesh;
}

namespace {

// Little-endian bytes of a value.
void put(std::ostream& out, const auto& value) {
  char bytes[sizeof(value)];
  std::memcpy(bytes, &value, sizeof(value));
  if constexpr (std::endian::native == std::endian::big) std::reverse(bytes, bytes + sizeof(value));
  out.write(bytes, sizeof(value));
}

}  // namespace

void write_ply_with_uv(const std::string& path, const TriMesh& mesh, const Eigen::MatrixXd& UV) {
  if (UV.rows() != mesh.V.rows() || UV.cols() != 2)
    throw OutputError("UV matrix is " + std::to_string(UV.rows()) + "x" + std::to_string(UV.cols()) + ", expected " +
                      std::to_string(mesh.V.rows()) + "x2");
  static_assert(sizeof(double) == 8 && sizeof(int) == 4, "PLY double and int");
  write_file_atomically(path, [&](std::ostream& out) {
    out << "ply\nformat binary_little_endian 1.0\ncomment written by akvf: s, t are the parameterization\n"
        << "element vertex " << mesh.num_vertices()
        << "\nproperty double x\nproperty double y\nproperty double z\nproperty double s\nproperty double t\n"
        << "element face " << mesh.num_faces() << "\nproperty list uchar int vertex_indices\nend_header\n";
    for (int v = 0; v < mesh.num_vertices(); ++v) {
      for (int k = 0; k < 3; ++k) put(out, mesh.V(v, k));
      for (int k = 0; k < 2; ++k) put(out, UV(v, k));
    }
    for (int f = 0; f < mesh.num_faces(); ++f) {
      put(out, static_cast<unsigned char>(3));
      for (int k = 0; k < 3; ++k) put(out, static_cast<int>(mesh.F(f, k)));
    }
  });
}

void write_ply_with_uv(const std::string& path, const TriMesh& mesh, const Eigen::MatrixXd& UV,
                       const Eigen::MatrixXi& UV_faces) {
  check_corner_uv(mesh, UV, UV_faces);
  static_assert(sizeof(float) == 4, "PLY float");
  write_file_atomically(path, [&](std::ostream& out) {
    out << "ply\nformat binary_little_endian 1.0\ncomment written by akvf: texcoord (per corner) is the "
           "parameterization\n"
        << "element vertex " << mesh.num_vertices() << "\nproperty double x\nproperty double y\nproperty double z\n"
        << "element face " << mesh.num_faces()
        << "\nproperty list uchar int vertex_indices\nproperty list uchar float texcoord\nend_header\n";
    for (int v = 0; v < mesh.num_vertices(); ++v)
      for (int k = 0; k < 3; ++k) put(out, mesh.V(v, k));
    for (int f = 0; f < mesh.num_faces(); ++f) {
      put(out, static_cast<unsigned char>(3));
      for (int k = 0; k < 3; ++k) put(out, static_cast<int>(mesh.F(f, k)));
      put(out, static_cast<unsigned char>(6));
      for (int k = 0; k < 3; ++k)
        for (int c = 0; c < 2; ++c) put(out, static_cast<float>(UV(UV_faces(f, k), c)));
    }
  });
}

}  // namespace akvf
