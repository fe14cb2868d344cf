#include "framework/optimization/boundary_contact.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "framework/mesh/box_pairs.h"
#include "framework/optimization/flip_free_step.h"

namespace akvf {

namespace {
using Vec2 = Eigen::Vector2d;
constexpr double kUnbounded = std::numeric_limits<double>::infinity();

double cross(const Vec2& a, const Vec2& b) { return a.x() * b.y() - a.y() * b.x(); }
Vec2 point(const Eigen::VectorXd& x, int v) { return x.segment<2>(2 * v); }

Box2 bounds(std::initializer_list<Vec2> points, double margin) {
  Box2 box{kUnbounded, kUnbounded, -kUnbounded, -kUnbounded};
  for (const Vec2& p : points) {
    box.min_x = std::min(box.min_x, p.x() - margin);
    box.min_y = std::min(box.min_y, p.y() - margin);
    box.max_x = std::max(box.max_x, p.x() + margin);
    box.max_y = std::max(box.max_y, p.y() + margin);
  }
  return box;
}

// The first t in (0, horizon] at which p(t) lies on the segment a(t) b(t),
// every point moving linearly; +infinity if none.
double vertex_edge_contact(const Vec2& p, const Vec2& dp, const Vec2& a, const Vec2& da, const Vec2& b, const Vec2& db,
                           double horizon) {
  const Vec2 u = a - p, du = da - dp, w = b - p, dw = db - dp;
  // cross(u + t du, w + t dw) = 0: the three points are collinear ...
  double a2 = cross(du, dw), a1 = cross(u, dw) + cross(du, w), a0 = cross(u, w);
  bool collinear_throughout = a2 == 0 && a1 == 0 && a0 == 0;
  // ... and p lies between a and b: (u . w)(t) <= 0. If they stay collinear,
  // the contact is the first time that holds.
  if (collinear_throughout) {
    a2 = du.dot(dw);
    a1 = u.dot(dw) + du.dot(w);
    a0 = u.dot(w);
  }
  double roots[2];
  const int n = positive_roots(a2, a1, a0, roots);
  for (int k = 0; k < n && roots[k] <= horizon; ++k) {
    if (collinear_throughout) return roots[k];
    const double t = roots[k];
    if ((u + t * du).dot(w + t * dw) <= 0) return t;
  }
  return kUnbounded;
}

// The parameter s in [0, 1] of the point (1 - s) a + s b of the segment a b
// closest to p (2D map or 3D rest positions).
template <class Vec>
double closest_parameter(const Vec& p, const Vec& a, const Vec& b) {
  const Vec edge = b - a;
  const double length2 = edge.squaredNorm();
  return length2 > 0 ? std::clamp((p - a).dot(edge) / length2, 0.0, 1.0) : 0.0;
}

// p minus its closest point on the segment a b, and that point's parameter s.
Vec2 offset_from_segment(const Vec2& p, const Vec2& a, const Vec2& b, double* s) {
  *s = closest_parameter(p, a, b);
  return p - (a + *s * (b - a));
}

// 2 pi - theta, theta the angle from u counter-clockwise to v in [0, 2 pi):
// an angle term's q for u = next - corner, v = previous - corner.
double angle_gap(const Vec2& u, const Vec2& v) {
  double theta = std::atan2(cross(u, v), u.dot(v));
  if (theta < 0) theta += 2 * M_PI;
  return 2 * M_PI - theta;
}

bool segments_meet(const Vec2& a1, const Vec2& b1, const Vec2& a2, const Vec2& b2) {
  const double o1 = cross(b1 - a1, a2 - a1), o2 = cross(b1 - a1, b2 - a1);
  const double o3 = cross(b2 - a2, a1 - a2), o4 = cross(b2 - a2, b1 - a2);
  if (o1 == 0 && o2 == 0) {  // collinear: do the projections on the segment's line overlap?
    const Vec2 e = b1 - a1;
    const double s1 = e.dot(a2 - a1), s2 = e.dot(b2 - a1), length2 = e.squaredNorm();
    return std::max(s1, s2) >= 0 && std::min(s1, s2) <= length2;
  }
  return o1 * o2 <= 0 && o3 * o4 <= 0;
}
}  // namespace

BoundaryContact::BoundaryContact(const std::vector<std::vector<int>>& loops, const Eigen::MatrixXd& rest,
                                 const Eigen::VectorXd& rest_angle, const Eigen::MatrixXi& faces)
    : rest_(rest), neighbours_(rest.rows()) {
  std::vector<char> on_boundary(rest.rows(), 0);
  for (const auto& loop : loops)
    for (int v : loop) on_boundary[v] = 1;
  for (int f = 0; f < faces.rows(); ++f)
    for (int k = 0; k < 3; ++k)
      if (on_boundary[faces(f, k)])
        for (int j = 1; j < 3; ++j) neighbours_[faces(f, k)].push_back(faces(f, (k + j) % 3));
  for (std::vector<int>& list : neighbours_) {
    std::sort(list.begin(), list.end());
    list.erase(std::unique(list.begin(), list.end()), list.end());
  }
  constexpr double kAngleReach = M_PI / 4, kSmallestAngleReach = M_PI / 64;
  for (int k = 0; k < static_cast<int>(loops.size()); ++k) {
    const std::vector<int>& loop = loops[k];
    const int n = static_cast<int>(loop.size());
    for (int i = 0; i < n; ++i) {
      const int v = loop[i], next = loop[(i + 1) % n], previous = loop[(i + n - 1) % n];
      const double length = (rest.row(next) - rest.row(v)).norm(), before = (rest.row(v) - rest.row(previous)).norm();
      edges_.push_back({v, next, k, length});
      const double mean = 0.5 * (length + before);
      const double reach = std::clamp(0.5 * (2 * M_PI - rest_angle[v]), kSmallestAngleReach, kAngleReach);
      corners_.push_back({v, previous, next, k, reach, mean * mean});
    }
  }
}

double BoundaryContact::first_contact_step(const Eigen::VectorXd& x, const Eigen::VectorXd& d, double horizon) const {
  if (!(horizon > 0) || !std::isfinite(horizon) || edges_.empty()) return kUnbounded;
  // The sweep over [0, horizon] in slices along which the boundary vertices
  // move about a boundary edge's length (root mean square): a box swept
  // over the whole horizon can cover most of the chart (a fifth of all
  // vertex-edge pairs on hilbert_b), a slice's covers the vertex's
  // neighbourhood. The slices are visited in order and the search ends at
  // the first contact; each pair is solved once, over all of [0, horizon]
  // left, in the first slice where its boxes meet, so the result is the
  // unsliced sweep's.
  double motion = 0, length = 0;
  for (const Edge& e : edges_) {
    motion += point(d, e.a).squaredNorm();
    length += (point(x, e.b) - point(x, e.a)).norm();
  }
  motion = std::sqrt(motion / static_cast<double>(edges_.size()));
  length /= static_cast<double>(edges_.size());
  constexpr int kMostSlices = 64;
  const double wanted = length > 0 ? std::ceil(horizon * motion / length) : 1;
  const int slices = std::isfinite(wanted) ? static_cast<int>(std::clamp(wanted, 1.0, double(kMostSlices))) : 1;
  std::vector<Box2> swept_corners(corners_.size()), swept_edges(edges_.size());
  std::vector<Box2> earlier_corners, earlier_edges;  // the slice before's
  double step = kUnbounded;
  for (int k = 0; k < slices; ++k) {
    const double t0 = horizon * k / slices, t1 = k + 1 == slices ? horizon : horizon * (k + 1) / slices;
    if (t0 > step) break;
    if (k > 0) {
      earlier_corners.swap(swept_corners);
      earlier_edges.swap(swept_edges);
      swept_corners.resize(corners_.size());
      swept_edges.resize(edges_.size());
    }
    for (size_t i = 0; i < corners_.size(); ++i) {
      const int v = corners_[i].vertex;
      swept_corners[i] = bounds({point(x, v) + t0 * point(d, v), point(x, v) + t1 * point(d, v)}, 0);
    }
    for (size_t j = 0; j < edges_.size(); ++j) {
      const Edge& e = edges_[j];
      swept_edges[j] = bounds({point(x, e.a) + t0 * point(d, e.a), point(x, e.b) + t0 * point(d, e.b),
                               point(x, e.a) + t1 * point(d, e.a), point(x, e.b) + t1 * point(d, e.b)},
                              0);
    }
    for_each_overlapping_pair(
        swept_corners, swept_edges,
        [&](int i, int j) {
          const Corner& c = corners_[i];
          const Edge& e = edges_[j];
          if (c.loop != e.loop || c.vertex == e.a || c.vertex == e.b) return;
          // A pair whose boxes met in the slice before was solved there, over
          // the whole interval left.
          if (k > 0 && earlier_corners[i].overlaps(earlier_edges[j])) return;
          const double t = vertex_edge_contact(point(x, c.vertex), point(d, c.vertex), point(x, e.a), point(d, e.a),
                                               point(x, e.b), point(d, e.b), std::min(horizon, step));
          step = std::min(step, t);
        },
        PairOrder::kGrid);  // a minimum: any order gives it
  }
  return step;
}

// A vertex within this fraction of an edge's length from it at rest lies on
// it: the two sides of a seam (positions equal to rounding).
constexpr double kSeamTolerance = 1e-3;

double BoundaryContact::rest_distance(int p, int a, int b) const {
  const Eigen::Vector3d P = rest_.row(p).transpose(), A = rest_.row(a).transpose(), B = rest_.row(b).transpose();
  const double s = closest_parameter(P, A, B);
  return (P - (A + s * (B - A))).norm();
}

template <class Visit>
void BoundaryContact::for_each_term(const Eigen::VectorXd& x, double reach_factor, const Visit& visit) const {
  // Vertex-edge terms.
  std::vector<Box2> corner_points(corners_.size()), reach_boxes(edges_.size());
  for (size_t i = 0; i < corners_.size(); ++i) corner_points[i] = bounds({point(x, corners_[i].vertex)}, 0);
  for (size_t j = 0; j < edges_.size(); ++j)
    reach_boxes[j] = bounds({point(x, edges_[j].a), point(x, edges_[j].b)}, 0.5 * reach_factor * edges_[j].rest_length);
  for_each_overlapping_pair(corner_points, reach_boxes, [&](int i, int j) {
    const Corner& c = corners_[i];
    const Edge& e = edges_[j];
    if (c.loop != e.loop || c.vertex == e.a || c.vertex == e.b) return;
    const std::vector<int>& joined = neighbours_[c.vertex];
    if (std::binary_search(joined.begin(), joined.end(), e.a) || std::binary_search(joined.begin(), joined.end(), e.b))
      return;
    const Vec2 p = point(x, c.vertex), a = point(x, e.a), b = point(x, e.b);
    double s;
    const Vec2 r = offset_from_segment(p, a, b, &s);
    const double distance = r.norm();
    if (!(distance < 0.5 * reach_factor * e.rest_length)) return;
    // Half the rest distance, where the isometric map would put them; a
    // vertex that lies on the edge at rest (a seam's two sides, cut apart)
    // is as far as the edge is long.
    const double apart = rest_distance(c.vertex, e.a, e.b);
    const double reach =
        0.5 * (apart > kSeamTolerance * e.rest_length ? std::min(e.rest_length, apart) : e.rest_length);
    if (!(distance < reach_factor * reach)) return;
    // d dist / dp = n, and the edge's ends share -n by s (zero at contact).
    const Vec2 n = distance > 0 ? Vec2(r / distance) : Vec2::Zero();
    visit(Term{{{c.vertex, e.a, e.b}, {n, -(1 - s) * n, -s * n}, 0, 0, false}, distance, reach * e.rest_length, reach});
  });
  // Angle terms: theta from c -> next counter-clockwise to c -> previous,
  // in [0, 2 pi); d theta / d next = -u^perp / |u|^2, d theta / d previous =
  // v^perp / |v|^2 (perp: turned by +90 degrees) and c takes minus their sum.
  for (const Corner& c : corners_) {
    const Vec2 u = point(x, c.next) - point(x, c.vertex), v = point(x, c.previous) - point(x, c.vertex);
    const double gap = angle_gap(u, v);
    if (!(gap < reach_factor * c.reach)) continue;
    const double uu = u.squaredNorm(), vv = v.squaredNorm();
    if (!(uu > 0 && vv > 0)) continue;
    // q = 2 pi - theta: its gradient is minus theta's.
    const Vec2 d_next(-u.y() / uu, u.x() / uu), d_previous(v.y() / vv, -v.x() / vv);
    visit(Term{{{c.next, c.previous, c.vertex}, {d_next, d_previous, -(d_next + d_previous)}, 0, 0, true},
               gap,
               c.weight,
               c.reach});
  }
}

double BoundaryContact::barrier(const Eigen::VectorXd& x, Eigen::VectorXd* gradient) const {
  double value = 0;
  for_each_term(x, 1, [&](const Term& term) {
    if (!(term.q > 0) || !std::isfinite(value)) {
      value = kUnbounded;
      return;
    }
    const double excess = term.reach / term.q - 1;
    value += term.weight * excess * excess;
    if (gradient) {
      // d/dq of w (eps / q - 1)^2.
      const double slope = -2 * term.weight * excess * term.reach / (term.q * term.q);
      for (int k = 0; k < 3; ++k)
        gradient->segment<2>(2 * term.derivative.vertex[k]) += slope * term.derivative.gradient[k];
    }
  });
  return value;
}

std::vector<BoundaryContact::ActiveTerm> BoundaryContact::active_terms(const Eigen::VectorXd& x) const {
  std::vector<ActiveTerm> terms;
  for_each_term(x, 1, [&](const Term& term) {
    if (!(term.q > 0)) return;
    // d^2/dq^2 of w (eps / q - 1)^2 = (2 w eps / q^3)(3 eps / q - 2), > 0 for q < eps.
    const double q3 = term.q * term.q * term.q;
    ActiveTerm active = term.derivative;
    active.curvature = 2 * term.weight * term.reach / q3 * (3 * term.reach / term.q - 2);
    active.slope = -2 * term.weight * (term.reach / term.q - 1) * term.reach / (term.q * term.q);
    active.argument = term.q;
    active.reach = term.reach;
    terms.push_back(active);
  });
  return terms;
}

std::vector<std::array<int, 3>> BoundaryContact::terms_within(const Eigen::VectorXd& x, double reach_factor) const {
  std::vector<std::array<int, 3>> found;
  for_each_term(x, reach_factor, [&](const Term& term) {
    const int* v = term.derivative.vertex;
    found.push_back({v[0], v[1], v[2]});
  });
  return found;
}

namespace {

using Matrix6 = Eigen::Matrix<double, 6, 6>;
// The quarter turn R: R v = v^perp, and cross(e, w) = w^T R e.
const Eigen::Matrix2d kQuarterTurn = (Eigen::Matrix2d() << 0, -1, 1, 0).finished();

// Adds m to the (i, j) block of H and m^T to the (j, i) one (i != j), or m to (i, i).
void add_block(int i, int j, const Eigen::Matrix2d& m, Matrix6* H) {
  H->block<2, 2>(2 * i, 2 * j) += m;
  if (i != j) H->block<2, 2>(2 * j, 2 * i) += m.transpose();
}

// d^2 dist(p, segment a b) / d(p, a, b)^2. Inside the segment the distance
// is |f| / L with f = cross(b - a, p - a) = (p - a)^T R (b - a), bilinear
// (its Hessian: R in the (p, b) block, -R in (p, a) and (a, b)), and
// L = |b - a| (its Hessian: (I - t t^T) / L in (a, a) and (b, b), minus that
// in (a, b), t = (b - a) / L); at an end it is |p - a| (or |p - b|), whose
// Hessian is (I - n n^T) / q in (p, p) and (a, a), minus that in (p, a).
Matrix6 distance_hessian(const Eigen::Vector2d& p, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  Matrix6 H = Matrix6::Zero();
  const double s = closest_parameter(p, a, b);
  if (!(s > 0 && s < 1)) {
    const int end = s == 1 ? 2 : 1;
    const Eigen::Vector2d r = p - (end == 1 ? a : b);
    const double q = r.norm();
    if (!(q > 0)) return H;
    const Eigen::Vector2d n = r / q;
    const Eigen::Matrix2d P = (Eigen::Matrix2d::Identity() - n * n.transpose()) / q;
    add_block(0, 0, P, &H);
    add_block(end, end, P, &H);
    add_block(0, end, -P, &H);
    return H;
  }
  const Eigen::Vector2d e = b - a, w = p - a;
  const double L = e.norm(), f = w.dot(kQuarterTurn * e);
  const double sign = f >= 0 ? 1.0 : -1.0;
  // Gradients over (p, a, b).
  Eigen::Matrix<double, 6, 1> df, dL;
  df << kQuarterTurn * e, -kQuarterTurn * e + kQuarterTurn * w, -(kQuarterTurn * w);
  const Eigen::Vector2d t = e / L;
  dL << Eigen::Vector2d::Zero(), -t, t;
  Matrix6 d2f = Matrix6::Zero(), d2L = Matrix6::Zero();
  add_block(0, 2, kQuarterTurn, &d2f);
  add_block(0, 1, -kQuarterTurn, &d2f);
  add_block(1, 2, -kQuarterTurn, &d2f);
  const Eigen::Matrix2d P = (Eigen::Matrix2d::Identity() - t * t.transpose()) / L;
  add_block(1, 1, P, &d2L);
  add_block(2, 2, P, &d2L);
  add_block(1, 2, -P, &d2L);
  // d^2 (f / L) = d2f / L - (df dL^T + dL df^T) / L^2 + f (2 dL dL^T / L^3 - d2L / L^2).
  H = d2f / L - (df * dL.transpose() + dL * df.transpose()) / (L * L) +
      f * (2 * dL * dL.transpose() / (L * L * L) - d2L / (L * L));
  return sign * H;
}

// The Hessian of atan2(y, x) at u = (x, y): [2xy, y^2 - x^2; y^2 - x^2, -2xy] / |u|^4.
Eigen::Matrix2d direction_angle_hessian(const Eigen::Vector2d& u) {
  const double r4 = u.squaredNorm() * u.squaredNorm();
  Eigen::Matrix2d H;
  H << 2 * u.x() * u.y(), u.y() * u.y() - u.x() * u.x(), u.y() * u.y() - u.x() * u.x(), -2 * u.x() * u.y();
  return H / r4;
}

// d^2 q / d(next, previous, c)^2 for q = 2 pi - theta, theta the angle of
// v = previous - c less that of u = next - c.
Matrix6 angle_hessian(const Eigen::Vector2d& next, const Eigen::Vector2d& previous, const Eigen::Vector2d& c) {
  const Eigen::Matrix2d Hu = direction_angle_hessian(next - c), Hv = -direction_angle_hessian(previous - c);
  Matrix6 H = Matrix6::Zero();
  add_block(0, 0, Hu, &H);
  add_block(1, 1, Hv, &H);
  add_block(2, 2, Hu + Hv, &H);
  add_block(0, 2, -Hu, &H);
  add_block(1, 2, -Hv, &H);
  return H;
}

}  // namespace

Eigen::Matrix<double, 6, 6> BoundaryContact::hessian(const ActiveTerm& term, const Eigen::VectorXd& x) {
  const Vec2 p0 = point(x, term.vertex[0]), p1 = point(x, term.vertex[1]), p2 = point(x, term.vertex[2]);
  Eigen::Matrix<double, 6, 1> dq;
  for (int k = 0; k < 3; ++k) dq.segment<2>(2 * k) = term.gradient[k];
  const Matrix6 d2q = term.angle ? angle_hessian(p0, p1, p2) : distance_hessian(p0, p1, p2);
  return term.curvature * dq * dq.transpose() + term.slope * d2q;
}

double BoundaryContact::argument_at(const ActiveTerm& term, const Eigen::VectorXd& x) {
  const Vec2 p0 = point(x, term.vertex[0]), p1 = point(x, term.vertex[1]), p2 = point(x, term.vertex[2]);
  if (term.angle) return angle_gap(p0 - p2, p1 - p2);
  double s;
  return offset_from_segment(p0, p1, p2, &s).norm();
}

std::vector<std::array<int, 4>> BoundaryContact::crossings(const Eigen::VectorXd& x) const {
  std::vector<Box2> boxes(edges_.size());
  for (size_t j = 0; j < edges_.size(); ++j) boxes[j] = bounds({point(x, edges_[j].a), point(x, edges_[j].b)}, 0);
  std::vector<std::array<int, 4>> found;
  for_each_overlapping_pair(boxes, boxes, [&](int i, int j) {
    const Edge& e = edges_[i];
    const Edge& f = edges_[j];
    if (j <= i || e.loop != f.loop || e.a == f.a || e.a == f.b || e.b == f.a || e.b == f.b) return;
    if (segments_meet(point(x, e.a), point(x, e.b), point(x, f.a), point(x, f.b)))
      found.push_back({e.a, e.b, f.a, f.b});
  });
  return found;
}

}  // namespace akvf
