#pragma once
// Faces wound the other way than their neighbours (akvf param --repair
// auto): each connected piece (faces joined across edges of exactly two
// faces) keeps the winding most of its faces have, and the others are
// reversed (libigl's bfs_orient makes a piece agree with its first face
// instead; either way the whole surface agrees).
#include <Eigen/Core>
#include <string>
#include <utility>
#include <vector>

namespace akvf {

// The winding each face needs to agree with its neighbours across every
// edge (F edge-manifold: no edge of three or more faces): flip[f] = 1 to
// reverse face f, the fewest in each piece. Returns false, flip unset, when no choice agrees (a Moebius strip,
// a Klein bottle: the surface is not orientable).
bool consistent_orientation(const Eigen::MatrixXi& F, std::vector<char>* flip);

// For a surface that is not orientable: the same walk, but where a face is
// reached both ways the edge between the two is recorded in `cuts` (as
// (smaller, larger) vertex pairs, ascending) instead of failing. Across
// every other edge the windings then agree, so the surface opened along
// `cuts` is orientable (a Moebius strip's cut runs across it once).
void orientation_with_cuts(const Eigen::MatrixXi& F, std::vector<char>* flip, std::vector<std::pair<int, int>>* cuts);

// Reverses (swaps the second and third corners of) the faces of F that
// `flip` (consistent_orientation's) marks; returns them, ascending.
std::vector<int> reverse_faces(const std::vector<char>& flip, Eigen::MatrixXi* F);

// The cut of a surface that is not orientable, in words, for a warning:
// `cuts` as input vertex pairs (numbered in the text as the file numbers
// them), the vertex copies it added and the faces reversed.
std::string orientation_cut_description(const std::vector<std::pair<int, int>>& cuts, int copies, std::size_t reversed,
                                        const std::string& name, int index_base);

// The reversal in words, for a warning: the first few faces numbered as the
// file numbers them (face f is input face input_face[f]; empty: f itself).
std::string reorientation_description(const std::vector<int>& reversed, const std::vector<int>& input_face,
                                      const std::string& name, int index_base);

}  // namespace akvf
