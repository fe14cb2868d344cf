#include "io/stl_reader.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <iterator>
#include <limits>
#include <sstream>
#include <unordered_map>
#include <vector>

#include "akvf/error.h"
#include "io/mesh_text.h"
#include "io/text_reader.h"

namespace akvf {

namespace {

using Corner = std::array<double, 3>;

// Corners of a binary file: 84 + 50 n bytes, little endian float32.
std::vector<Corner> binary_corners(const std::string& data, const std::string& file) {
  std::uint32_t facets = 0;
  std::memcpy(&facets, data.data() + 80, 4);  // little endian, as x86 and the format
  std::vector<Corner> corners;
  corners.reserve(3 * std::min<std::size_t>(facets, kMaxReserve));
  for (std::uint32_t f = 0; f < facets; ++f) {
    const char* record = data.data() + 84 + 50 * static_cast<std::size_t>(f);
    for (int c = 0; c < 3; ++c) {
      Corner p;
      for (int k = 0; k < 3; ++k) {
        float value;
        std::memcpy(&value, record + 12 + 12 * c + 4 * k, 4);  // after the 12-byte normal
        if (!std::isfinite(value))
          throw InputError(file, 0, "facet " + std::to_string(f) + ": a corner coordinate is not finite");
        p[k] = value;
      }
      corners.push_back(p);
    }
  }
  return corners;
}

// The keyword a line starts with, in lower case (writers differ: "SOLID").
std::string keyword(const TextReader& reader) {
  std::string word(reader.tokens()[0]);
  std::transform(word.begin(), word.end(), word.begin(), [](unsigned char c) { return std::tolower(c); });
  return word;
}

// Whether `data` starts with "solid" in any case (after a UTF-8 byte-order mark).
bool starts_ascii(const std::string& data) {
  const std::size_t at = data.compare(0, 3, "\xEF\xBB\xBF") == 0 ? 3 : 0;
  if (data.size() < at + 5) return false;
  std::string word = data.substr(at, 5);
  std::transform(word.begin(), word.end(), word.begin(), [](unsigned char c) { return std::tolower(c); });
  return word == "solid";
}

// Corners of an ASCII file: solid / facet normal / outer loop / 3 x vertex /
// endloop / endfacet / endsolid, keywords in any case.
std::vector<Corner> ascii_corners(const std::string& data, const std::string& file) {
  std::istringstream in(data);
  TextReader reader(in, file);
  std::vector<Corner> corners;
  const auto expect = [&](const char* word) {
    if (!reader.next_line()) reader.fail(std::string("the file ends where '") + word + "' was expected");
    if (keyword(reader) != word)
      reader.fail(std::string("expected '") + word + "', found '" + std::string(reader.tokens()[0]) + "'");
  };
  expect("solid");
  while (true) {
    if (!reader.next_line()) reader.fail("the file ends before 'endsolid'");
    const std::string word = keyword(reader);
    if (word == "endsolid") break;
    if (word != "facet") reader.fail("expected 'facet' or 'endsolid', found '" + std::string(word) + "'");
    expect("outer");
    for (int c = 0; c < 3; ++c) {
      expect("vertex");
      if (reader.tokens().size() != 4) reader.fail("a vertex line needs three coordinates");
      corners.push_back({reader.real(1, "vertex coordinate"), reader.real(2, "vertex coordinate"),
                         reader.real(3, "vertex coordinate")});
    }
    if (!reader.next_line()) reader.fail("the file ends before 'endloop'");
    if (keyword(reader) == "vertex") reader.fail("a facet with more than 3 vertices; only triangles are supported");
    if (keyword(reader) != "endloop")
      reader.fail("expected 'endloop', found '" + std::string(reader.tokens()[0]) + "'");
    expect("endfacet");
  }
  if (reader.next_line()) reader.fail("text after 'endsolid'");
  return corners;
}

// Welds corners within `tolerance` (grid cells at least that large from the
// bounding box's low corner, and at least 2^-40 of the diagonal, so cell
// numbers stay below 2^40; a corner joins the first earlier vertex within
// the tolerance in its own or a neighbouring cell).
TriMesh weld(const std::vector<Corner>& corners, const Corner& low, double diagonal, double tolerance) {
  struct CellHash {
    std::size_t operator()(const std::array<long long, 3>& c) const {
      const auto u = [](long long v) { return static_cast<unsigned long long>(v); };  // wraps, never overflows
      return std::hash<unsigned long long>()(u(c[0]) * 73856093ULL ^ u(c[1]) * 19349663ULL ^ u(c[2]) * 83492791ULL);
    }
  };
  const double cell = std::max(tolerance, std::ldexp(diagonal, -40));
  std::unordered_map<std::array<long long, 3>, std::vector<int>, CellHash> grid;
  std::vector<Corner> vertices;
  std::vector<int> index;
  index.reserve(corners.size());
  const auto cell_of = [&](const Corner& p) {
    return std::array<long long, 3>{static_cast<long long>(std::floor((p[0] - low[0]) / cell)),
                                    static_cast<long long>(std::floor((p[1] - low[1]) / cell)),
                                    static_cast<long long>(std::floor((p[2] - low[2]) / cell))};
  };
  for (const Corner& p : corners) {
    const auto cell = cell_of(p);
    int found = -1;
    for (long long dx = -1; dx <= 1 && found < 0; ++dx)
      for (long long dy = -1; dy <= 1 && found < 0; ++dy)
        for (long long dz = -1; dz <= 1 && found < 0; ++dz) {
          const auto it = grid.find({cell[0] + dx, cell[1] + dy, cell[2] + dz});
          if (it == grid.end()) continue;
          for (const int v : it->second) {
            const Corner& q = vertices[v];
            if (std::hypot(p[0] - q[0], p[1] - q[1], p[2] - q[2]) <= tolerance) {
              found = v;
              break;
            }
          }
        }
    if (found < 0) {
      found = static_cast<int>(vertices.size());
      vertices.push_back(p);
      grid[cell].push_back(found);
    }
    index.push_back(found);
  }
  TriMesh mesh;
  mesh.V.resize(static_cast<Eigen::Index>(vertices.size()), 3);
  for (std::size_t v = 0; v < vertices.size(); ++v)
    mesh.V.row(static_cast<Eigen::Index>(v)) << vertices[v][0], vertices[v][1], vertices[v][2];
  mesh.F = rows_to_matrix<int, 3>(index);
  mesh.index_base = 0;
  return mesh;
}

}  // namespace

TriMesh read_stl(std::istream& in, const std::string& file_name) {
  const std::string data{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  std::vector<Corner> corners;
  std::uint32_t facets = 0;
  if (data.size() >= 84) std::memcpy(&facets, data.data() + 80, 4);
  if (data.size() >= 84 && data.size() == 84 + 50 * static_cast<std::size_t>(facets)) {
    corners = binary_corners(data, file_name);
  } else if (starts_ascii(data)) {
    corners = ascii_corners(data, file_name);
  } else {
    throw InputError(file_name, 0,
                     data.size() >= 84 ? "neither ASCII STL (no 'solid' first) nor binary STL (the size " +
                                             std::to_string(data.size()) + " is not 84 + 50 x the facet count " +
                                             std::to_string(facets) + ")"
                                       : "too short for an STL file (" + std::to_string(data.size()) + " bytes)");
  }
  if (corners.empty()) throw InputError(file_name, 0, "the file has no facets");
  Corner low = corners[0], high = corners[0];
  for (const Corner& p : corners)
    for (int k = 0; k < 3; ++k) {
      low[k] = std::min(low[k], p[k]);
      high[k] = std::max(high[k], p[k]);
    }
  const double diagonal = std::hypot(high[0] - low[0], high[1] - low[1], high[2] - low[2]);
  if (!(diagonal > 0)) throw InputError(file_name, 0, "every corner is the same point");
  if (!std::isfinite(diagonal)) throw InputError(file_name, 0, "the corners span more than a double can hold");
  double shortest_edge = std::numeric_limits<double>::infinity();  // of the facets, zero lengths aside
  for (std::size_t f = 0; f + 2 < corners.size(); f += 3)
    for (int k = 0; k < 3; ++k) {
      const Corner& p = corners[f + k];
      const Corner& q = corners[f + (k + 1) % 3];
      const double length = std::hypot(p[0] - q[0], p[1] - q[1], p[2] - q[2]);
      if (length > 0) shortest_edge = std::min(shortest_edge, length);
    }
  return weld(corners, low, diagonal, std::min(kStlWeldTolerance * diagonal, kStlWeldEdgeFraction * shortest_edge));
}

}  // namespace akvf
