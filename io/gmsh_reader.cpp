#include "io/gmsh_reader.h"

#include <algorithm>
#include <limits>
#include <unordered_map>
#include <vector>

#include "akvf/error.h"
#include "io/mesh_text.h"
#include "io/text_reader.h"

namespace akvf {

namespace {

constexpr long long kTetrahedron = 4;  // gmsh element type of the 4-node tet

struct Reading {
  TextReader& reader;
  std::vector<double> coords;
  std::vector<long long> tet_tags;  // 4 node tags per tet, resolved after $Nodes
  std::vector<long> tet_lines;
  std::unordered_map<long long, int> node_index;  // node tag -> vertex

  // The next line (a count or a row); fails naming what was expected.
  void next(const std::string& what) {
    if (!reader.next_line()) reader.fail("the file ends before " + what);
  }
  long long count(std::size_t i, const char* what) {
    const long long n = reader.integer(i, what);
    if (n < 0 || n > std::numeric_limits<int>::max())
      reader.fail(std::string(what) + " " + std::to_string(n) + " is out of range");
    return n;
  }
  void node(long long tag, double x, double y, double z) {
    if (tag <= 0) reader.fail("node tag " + std::to_string(tag) + " (tags are positive)");
    if (!node_index.emplace(tag, static_cast<int>(coords.size() / 3)).second)
      reader.fail("node " + std::to_string(tag) + " appears twice");
    coords.insert(coords.end(), {x, y, z});
  }
  void tet(const std::vector<long long>& tags) {
    tet_tags.insert(tet_tags.end(), tags.begin(), tags.end());
    tet_lines.push_back(reader.line_number());
  }
  // Skips to `$End<name>`.
  void skip_section(const std::string& name) {
    const std::string end = "$End" + name.substr(1);
    while (true) {
      next("'" + end + "'");
      if (reader.tokens()[0] == end) return;
    }
  }
  void expect_end(const std::string& end) {
    next("'" + end + "'");
    if (reader.tokens()[0] != end)
      reader.fail("expected '" + end + "' (the counts of the section disagree with its rows?), found '" +
                  std::string(reader.tokens()[0]) + "'");
  }
};

void nodes_22(Reading& r) {
  r.next("the node count");
  const long long n = r.count(0, "node count");
  r.coords.reserve(3 * std::min(n, kMaxReserve));
  for (long long i = 0; i < n; ++i) {
    r.next("node " + std::to_string(i + 1) + " of " + std::to_string(n));
    if (r.reader.tokens().size() < 4) r.reader.fail("a node needs a tag and x y z");
    r.node(r.reader.integer(0, "node tag"), r.reader.real(1, "x"), r.reader.real(2, "y"), r.reader.real(3, "z"));
  }
  r.expect_end("$EndNodes");
}

void elements_22(Reading& r) {
  r.next("the element count");
  const long long n = r.count(0, "element count");
  for (long long i = 0; i < n; ++i) {
    r.next("element " + std::to_string(i + 1) + " of " + std::to_string(n));
    const auto& t = r.reader.tokens();
    if (t.size() < 3) r.reader.fail("an element needs a tag, a type and a tag count");
    const long long type = r.reader.integer(1, "element type");
    const long long tags = r.reader.integer(2, "element tag count");
    if (tags < 0 || tags > 1000) r.reader.fail("element tag count " + std::to_string(tags) + " is out of range");
    if (type != kTetrahedron) continue;  // points, lines, triangles, ...
    const std::size_t first = 3 + static_cast<std::size_t>(tags);
    if (t.size() != first + 4) r.reader.fail("a tetrahedron (type 4) needs 4 nodes after its tags");
    std::vector<long long> nodes;
    for (std::size_t k = first; k < first + 4; ++k) nodes.push_back(r.reader.integer(k, "node tag"));
    r.tet(nodes);
  }
  r.expect_end("$EndElements");
}

void nodes_41(Reading& r) {
  r.next("the $Nodes counts");
  const long long blocks = r.count(0, "entity block count");
  const long long total = r.count(1, "node count");
  r.coords.reserve(3 * std::min(total, kMaxReserve));
  for (long long b = 0; b < blocks; ++b) {
    r.next("node block " + std::to_string(b + 1));
    if (r.reader.tokens().size() != 4) r.reader.fail("a node block header is 'entityDim entityTag parametric count'");
    const long long parametric = r.reader.integer(2, "parametric flag");
    if (parametric != 0 && parametric != 1) r.reader.fail("the parametric flag must be 0 or 1");
    const long long n = r.count(3, "nodes in the block");
    if (static_cast<long long>(r.coords.size() / 3) + n > total)
      r.reader.fail("the blocks hold more nodes than the $Nodes count " + std::to_string(total));
    std::vector<long long> tags;
    tags.reserve(std::min(n, kMaxReserve));
    for (long long i = 0; i < n; ++i) {
      r.next("a node tag");
      tags.push_back(r.reader.integer(0, "node tag"));
    }
    for (long long i = 0; i < n; ++i) {
      r.next("the coordinates of node " + std::to_string(tags[i]));
      if (r.reader.tokens().size() < 3) r.reader.fail("a node needs x y z");
      r.node(tags[i], r.reader.real(0, "x"), r.reader.real(1, "y"), r.reader.real(2, "z"));
    }
  }
  if (static_cast<long long>(r.coords.size() / 3) != total)
    r.reader.fail("the blocks hold " + std::to_string(r.coords.size() / 3) + " nodes, the $Nodes count says " +
                  std::to_string(total));
  r.expect_end("$EndNodes");
}

void elements_41(Reading& r) {
  r.next("the $Elements counts");
  const long long blocks = r.count(0, "entity block count");
  r.count(1, "element count");
  for (long long b = 0; b < blocks; ++b) {
    r.next("element block " + std::to_string(b + 1));
    if (r.reader.tokens().size() != 4) r.reader.fail("an element block header is 'entityDim entityTag type count'");
    const long long type = r.reader.integer(2, "element type");
    const long long n = r.count(3, "elements in the block");
    for (long long i = 0; i < n; ++i) {
      r.next("an element of block " + std::to_string(b + 1));
      if (type != kTetrahedron) continue;
      if (r.reader.tokens().size() != 5) r.reader.fail("a tetrahedron (type 4) is 'tag n1 n2 n3 n4'");
      std::vector<long long> nodes;
      for (std::size_t k = 1; k <= 4; ++k) nodes.push_back(r.reader.integer(k, "node tag"));
      r.tet(nodes);
    }
  }
  r.expect_end("$EndElements");
}

}  // namespace

TetMesh read_gmsh(std::istream& in, const std::string& file_name) {
  TextReader reader(in, file_name);
  Reading r{reader, {}, {}, {}, {}};
  if (!reader.next_line() || reader.tokens()[0] != "$MeshFormat")
    reader.fail("not a gmsh file (the first line must be '$MeshFormat')");
  r.next("the format line");
  const std::string version(reader.tokens()[0]);
  if (reader.tokens().size() < 3) reader.fail("the format line is 'version file-type data-size'");
  if (reader.integer(1, "file type") != 0)
    reader.fail("binary .msh is not supported: save it as ASCII (gmsh: -format msh41 with Mesh.Binary = 0)");
  const bool v2 = version.rfind("2.", 0) == 0, v4 = version == "4.1";
  if (!v2 && !v4) reader.fail("unsupported .msh version " + version + " (supported: 2.2 and 4.1, ASCII)");
  r.expect_end("$EndMeshFormat");
  bool have_nodes = false, have_elements = false;
  while (reader.next_line()) {
    const std::string section(reader.tokens()[0]);
    if (section == "$Nodes") {
      if (have_nodes) reader.fail("a second $Nodes section");
      v2 ? nodes_22(r) : nodes_41(r);
      have_nodes = true;
    } else if (section == "$Elements") {
      if (have_elements) reader.fail("a second $Elements section");
      v2 ? elements_22(r) : elements_41(r);
      have_elements = true;
    } else if (!section.empty() && section[0] == '$') {
      r.skip_section(section);
    } else {
      reader.fail("expected a section ('$Nodes', '$Elements', ...), found '" + section + "'");
    }
  }
  if (!have_nodes) throw InputError(file_name, 0, "no $Nodes section");
  if (r.tet_lines.empty()) throw InputError(file_name, 0, "no tetrahedra (element type 4)");
  std::vector<int> corners;
  corners.reserve(r.tet_tags.size());
  for (std::size_t k = 0; k < r.tet_tags.size(); ++k) {
    const auto it = r.node_index.find(r.tet_tags[k]);
    if (it == r.node_index.end())
      throw InputError(file_name, r.tet_lines[k / 4],
                       "tetrahedron uses node " + std::to_string(r.tet_tags[k]) + ", which $Nodes does not define");
    corners.push_back(it->second);
  }
  TetMesh mesh;
  mesh.V = rows_to_matrix<double, 3>(r.coords);
  mesh.T = rows_to_matrix<int, 4>(corners);
  mesh.index_base = 0;
  return mesh;
}

}  // namespace akvf
