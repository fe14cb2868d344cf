#pragma once
// A chart whose flip-free map lies over itself (its boundary wraps onto
// itself) cut into pieces that do not: each piece a disk whose triangles'
// interiors are disjoint in UV, so that the map of each piece is injective
// as it is. The map, and so every triangle's distortion, is unchanged.
#include <Eigen/Core>
#include <vector>

namespace akvf {

// A refinement of face_chart (num_charts charts of the cut mesh F, UV one
// row per vertex): every chart in which two triangles overlap is cut into
// pieces grown across shared edges, breadth first from its lowest-numbered
// face not yet placed; a face joins the piece when it overlaps none of the
// piece's triangles and the piece stays a disk (it shares one edge with the
// piece and its third vertex is new, or two edges). Charts without overlap
// keep their number; pieces are numbered after them. Returns the number of
// charts and pieces.
int overlap_free_pieces(const Eigen::MatrixXi& F, const Eigen::MatrixXd& UV, const std::vector<int>& face_chart,
                        int num_charts, std::vector<int>* pieces);

}  // namespace akvf
