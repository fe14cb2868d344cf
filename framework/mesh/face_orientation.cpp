#include "framework/mesh/face_orientation.h"

#include <algorithm>
#include <array>
#include <utility>

#include "akvf/mesh.h"
#include "framework/mesh/mesh_topology.h"

namespace akvf {

namespace {

// The walk of consistent_orientation(); with `cuts`, a face reached both
// ways records the edge it was reached across and the walk goes on,
// otherwise it returns false.
bool orient(const Eigen::MatrixXi& F, std::vector<char>* flip, std::vector<std::pair<int, int>>* cuts) {
  const int nf = static_cast<int>(F.rows());
  const int nv = nf == 0 ? 0 : F.maxCoeff() + 1;
  // Per face, the faces across its edges and whether they run the edge the
  // same way (an edge of two faces).
  const std::vector<std::array<int, 3>> across = faces_across_edges(F, nv);
  struct Neighbour {
    int face;
    bool same;                 // runs the shared edge the same way
    std::pair<int, int> edge;  // (smaller, larger) end
  };
  std::vector<std::vector<Neighbour>> neighbours(nf);
  for (int f = 0; f < nf; ++f)
    for (int k = 0; k < 3; ++k)
      if (const int g = across[f][k]; g >= 0) {
        const int u = F(f, k), v = F(f, (k + 1) % 3);
        bool same = false;
        for (int j = 0; j < 3; ++j) same = same || (F(g, j) == u && F(g, (j + 1) % 3) == v);
        neighbours[f].push_back({g, same, {std::min(u, v), std::max(u, v)}});
      }
  // A walk over each piece, each neighbour flipped or not to agree with the
  // face it is reached from; one reached both ways has no agreeing choice.
  std::vector<int> turn(nf, -1);
  std::vector<int> piece;
  for (int start = 0; start < nf; ++start) {
    if (turn[start] >= 0) continue;
    turn[start] = 0;
    piece.assign(1, start);
    for (std::size_t i = 0; i < piece.size(); ++i) {
      const int f = piece[i];
      for (const Neighbour& n : neighbours[f]) {
        const int wanted = turn[f] ^ static_cast<int>(n.same);
        if (turn[n.face] < 0) {
          turn[n.face] = wanted;
          piece.push_back(n.face);
        } else if (turn[n.face] != wanted) {
          if (!cuts) return false;
          cuts->push_back(n.edge);
        }
      }
    }
    // The piece keeps the winding most of its faces have.
    const auto turned = std::count_if(piece.begin(), piece.end(), [&](int f) { return turn[f] == 1; });
    if (2 * static_cast<std::size_t>(turned) > piece.size())
      for (int f : piece) turn[f] ^= 1;
  }
  if (cuts) {
    // Each disagreeing edge is met from both of its faces.
    std::sort(cuts->begin(), cuts->end());
    cuts->erase(std::unique(cuts->begin(), cuts->end()), cuts->end());
  }
  flip->assign(nf, 0);
  for (int f = 0; f < nf; ++f) (*flip)[f] = static_cast<char>(turn[f]);
  return true;
}

}  // namespace

bool consistent_orientation(const Eigen::MatrixXi& F, std::vector<char>* flip) { return orient(F, flip, nullptr); }

void orientation_with_cuts(const Eigen::MatrixXi& F, std::vector<char>* flip, std::vector<std::pair<int, int>>* cuts) {
  cuts->clear();
  orient(F, flip, cuts);
}

std::vector<int> reverse_faces(const std::vector<char>& flip, Eigen::MatrixXi* F) {
  std::vector<int> reversed;
  for (int f = 0; f < F->rows(); ++f)
    if (flip[f]) {
      std::swap((*F)(f, 1), (*F)(f, 2));
      reversed.push_back(f);
    }
  return reversed;
}

std::string reorientation_description(const std::vector<int>& reversed, const std::vector<int>& input_face,
                                      const std::string& name, int index_base) {
  constexpr std::size_t kListed = 5;
  std::string faces;
  for (std::size_t i = 0; i < std::min(reversed.size(), kListed); ++i)
    faces += (i > 0 ? ", " : "") + file_number(input_face.empty() ? reversed[i] : input_face[reversed[i]], index_base);
  const std::size_t count = reversed.size();
  return name + ": repaired: reversed " + std::to_string(count) + (count == 1 ? " face" : " faces") +
         " wound against their neighbours (" + faces + (count > kListed ? ", ..." : "") + ")" +
         numbering_note(index_base) +
         "; their UV triangles run the other way in the file's winding (--repair none refuses such input)";
}

std::string orientation_cut_description(const std::vector<std::pair<int, int>>& cuts, int copies, std::size_t reversed,
                                        const std::string& name, int index_base) {
  constexpr std::size_t kListed = 5;
  std::string edges;
  for (std::size_t i = 0; i < std::min(cuts.size(), kListed); ++i)
    edges += std::string(i > 0 ? ", (" : "(") + file_number(cuts[i].first, index_base) + ", " +
             file_number(cuts[i].second, index_base) + ")";
  const std::size_t count = cuts.size();
  return name + ": repaired: the surface is non-orientable (like a Moebius strip or a Klein bottle); cut along " +
         std::to_string(count) + (count == 1 ? " edge (" : " edges (") + edges + (count > kListed ? ", ...)" : ")") +
         " where no winding of the faces agrees, " + std::to_string(copies) +
         (copies == 1 ? " vertex copy" : " vertex copies") + " added, " + std::to_string(reversed) +
         (reversed == 1 ? " face" : " faces") + " reversed" + numbering_note(index_base) +
         "; the UV is per corner along the cut (--repair none refuses such input)";
}

}  // namespace akvf
