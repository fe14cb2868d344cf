#include "framework/mesh/face_orientation.h"

#include <algorithm>
#include <array>
#include <utility>

#include "akvf/mesh.h"
#include "framework/mesh/mesh_topology.h"

namespace akvf {

bool consistent_orientation(const Eigen::MatrixXi& F, std::vector<char>* flip) {
  const int nf = static_cast<int>(F.rows());
  const int nv = nf == 0 ? 0 : F.maxCoeff() + 1;
  // Per face, the faces across its edges and whether they run the edge the
  // same way (an edge of two faces).
  const std::vector<std::array<int, 3>> across = faces_across_edges(F, nv);
  std::vector<std::vector<std::pair<int, bool>>> neighbours(nf);  // (face, same direction)
  for (int f = 0; f < nf; ++f)
    for (int k = 0; k < 3; ++k)
      if (const int g = across[f][k]; g >= 0) {
        const int u = F(f, k), v = F(f, (k + 1) % 3);
        bool same = false;
        for (int j = 0; j < 3; ++j) same = same || (F(g, j) == u && F(g, (j + 1) % 3) == v);
        neighbours[f].push_back({g, same});
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
      for (const auto& [g, same] : neighbours[f]) {
        const int wanted = turn[f] ^ static_cast<int>(same);
        if (turn[g] < 0) {
          turn[g] = wanted;
          piece.push_back(g);
        } else if (turn[g] != wanted) {
          return false;
        }
      }
    }
    // The piece keeps the winding most of its faces have.
    const auto turned = std::count_if(piece.begin(), piece.end(), [&](int f) { return turn[f] == 1; });
    if (2 * static_cast<std::size_t>(turned) > piece.size())
      for (int f : piece) turn[f] ^= 1;
  }
  flip->assign(nf, 0);
  for (int f = 0; f < nf; ++f) (*flip)[f] = static_cast<char>(turn[f]);
  return true;
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

}  // namespace akvf
