#pragma once
// Global injectivity of a 2D map, after Smith & Schaefer 2015 ("Bijective
// parameterization with free boundaries"): a locally injective map of a
// disk is injective exactly when its boundary does not cross itself, so a
// descent that keeps every triangle positive (the flip-free bound of §5.3)
// and never lets a boundary vertex reach a boundary edge keeps the map
// bijective onto its image. This file holds the three pieces that need:
//   - the first contact step along a direction (continuous collision
//     detection of boundary vertices against boundary edges), which bounds
//     the line search as the flip-free step does;
//   - a barrier that grows without bound as a vertex nears an edge, so the
//     minimum lies in the interior of the injective maps and the descent
//     converges there instead of stalling against the contact bound;
//   - a count of crossing boundary edges, to measure a map.
// Vertices and edges are compared only within one boundary loop (one chart):
// charts are packed apart after the optimization.
//
// Variables: x in R^{2|V|}, interleaved (u_0, v_0, u_1, ...).
#include <Eigen/Core>
#include <array>
#include <vector>

namespace akvf {

class BoundaryContact {
 public:
  //   loops        the boundary loops (vertex indices in order, the chart to
  //                their left), one per chart
  //   rest         #V by 3: the rest positions, in the optimizer's units
  //   rest_angle   #V: the angle sum of each vertex's triangles at rest (the
  //                inner angle an isometric map gives a boundary vertex)
  //   faces        #F by 3: the mesh's triangles
  // The barrier's reach and weight are set from the rest shape (below), so
  // that it stays zero on an isometric map, a seam's two sides apart.
  BoundaryContact(const std::vector<std::vector<int>>& loops, const Eigen::MatrixXd& rest,
                  const Eigen::VectorXd& rest_angle, const Eigen::MatrixXi& faces);

  // The smallest t in (0, horizon] at which a boundary vertex lies on a
  // boundary edge of its loop that it is not an end of, for x + t d;
  // +infinity if there is none. Each vertex-edge pair meets when
  // cross(a - p, b - p), a quadratic in t, vanishes with p between a and b.
  double first_contact_step(const Eigen::VectorXd& x, const Eigen::VectorXd& d, double horizon) const;

  // E_B(x), Smith & Schaefer's boundary barrier, a sum of terms
  //   w (eps / q - 1)^2  where q < eps (0 elsewhere; C^1, +infinity at q = 0)
  // of two kinds:
  //   - a vertex p and an edge e of its loop, p joined by no mesh edge to
  //     an end of e (such a p reaches e only through a collapsed triangle or
  //     a fold at that end, which the flip-free step and the angle terms
  //     guard): q = dist(p, e) in the map, eps half
  //     the smaller of e's rest length and the rest distance of p from e
  //     (e's rest length where p lies on e at rest, a seam's two sides),
  //     w = eps * e's rest length (the area of the strip the term guards, so
  //     that E_B is measured like the area-weighted distortion);
  //   - every boundary vertex c: q = 2 pi - theta, theta the angle inside
  //     the chart at c (from c -> next to c -> previous, counter-clockwise),
  //     eps = min(pi / 4, half of 2 pi minus c's rest angle, at least
  //     pi / 64), w = the squared mean rest length of c's two boundary
  //     edges. This guards the folds a vertex-edge term cannot: a boundary
  //     vertex whose inner angle nears 2 pi, its neighbour reaching its other
  //     edge (the pair the first kind leaves out, since at the other end,
  //     theta near 0, it is a sharp but valid corner).
  // Measured against the rest shape, each term is zero on an isometric map,
  // but for a seam's two sides, which it holds apart.
  // Adds dE_B/dx to *gradient when given (sized 2|V|).
  double barrier(const Eigen::VectorXd& x, Eigen::VectorXd* gradient) const;

  // One term b(q) of the barrier within its reach at x: its argument q
  // depends on three vertices, dq/dx being gradient[k] at vertex[k]. Its
  // Hessian is b''(q) (dq/dx)(dq/dx)^T + b'(q) d^2q/dx^2, with
  // curvature = b''(q) > 0 and slope = b'(q) < 0; the first part alone is
  // its Gauss-Newton curvature (positive semi-definite).
  struct ActiveTerm {
    int vertex[3];
    Eigen::Vector2d gradient[3];
    double curvature;
    double slope;
    bool angle;  // an angle term (vertex: next, previous, the corner), else vertex-edge (the vertex, a, b)
    double argument = 0;  // q at x
    double reach = 0;     // eps: the term is zero where q >= eps
  };
  // The terms of barrier() that are not zero, in its order.
  std::vector<ActiveTerm> active_terms(const Eigen::VectorXd& x) const;
  // The vertices of the terms that lie within reach_factor times their
  // reach at x (those of active_terms for 1), in active_terms' order.
  std::vector<std::array<int, 3>> terms_within(const Eigen::VectorXd& x, double reach_factor) const;
  // The term's whole Hessian at x, on the coordinates of its three vertices
  // in their order (2 each).
  static Eigen::Matrix<double, 6, 6> hessian(const ActiveTerm& term, const Eigen::VectorXd& x);
  // The term's argument q with its vertices at x (another map than the one
  // it was found at): the angle's gap to 2 pi, or the vertex's distance
  // from the edge.
  static double argument_at(const ActiveTerm& term, const Eigen::VectorXd& x);

  // The pairs of edges of one loop, neither following the other, that meet:
  // their vertices (a, b, c, d) for edges a -> b and c -> d.
  std::vector<std::array<int, 4>> crossings(const Eigen::VectorXd& x) const;
  int count_crossings(const Eigen::VectorXd& x) const { return static_cast<int>(crossings(x).size()); }

 private:
  struct Edge {
    int a, b;  // vertex indices, a -> b along the loop
    int loop;
    double rest_length;
  };
  struct Corner {
    int vertex, previous, next;  // along the loop
    int loop;
    double reach, weight;  // eps and w of its angle term
  };
  // Calls visit(term) for every term of the barrier within reach_factor
  // times its reach, with q, its gradient, w and eps, in a fixed order.
  struct Term {
    ActiveTerm derivative;
    double q, weight, reach;
  };
  double rest_distance(int p, int a, int b) const;
  template <class Visit>
  void for_each_term(const Eigen::VectorXd& x, double reach_factor, const Visit& visit) const;

  Eigen::MatrixXd rest_;
  std::vector<std::vector<int>> neighbours_;  // sorted mesh neighbours of each vertex (boundary ones only)
  std::vector<Edge> edges_;
  std::vector<Corner> corners_;
};

}  // namespace akvf
