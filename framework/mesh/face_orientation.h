#pragma once
// Faces wound the other way than their neighbours (akvf param --repair
// auto): each connected piece (faces joined across edges of exactly two
// faces) keeps the winding most of its faces have, and the others are
// reversed (libigl's bfs_orient makes a piece agree with its first face
// instead; either way the whole surface agrees).
#include <Eigen/Core>
#include <string>
#include <vector>

namespace akvf {

// The winding each face needs to agree with its neighbours across every
// edge (F edge-manifold: no edge of three or more faces): flip[f] = 1 to
// reverse face f, the fewest in each piece. Returns false, flip unset, when no choice agrees (a Moebius strip,
// a Klein bottle: the surface is not orientable).
bool consistent_orientation(const Eigen::MatrixXi& F, std::vector<char>* flip);

// Reverses (swaps the second and third corners of) the faces of F that
// `flip` (consistent_orientation's) marks; returns them, ascending.
std::vector<int> reverse_faces(const std::vector<char>& flip, Eigen::MatrixXi* F);

// The reversal in words, for a warning: the first few faces numbered as the
// file numbers them (face f is input face input_face[f]; empty: f itself).
std::string reorientation_description(const std::vector<int>& reversed, const std::vector<int>& input_face,
                                      const std::string& name, int index_base);

}  // namespace akvf
