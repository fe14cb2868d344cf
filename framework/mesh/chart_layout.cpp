#include "framework/mesh/chart_layout.h"

#include "framework/mesh/plane_geometry.h"
#include "framework/mesh/raster_packing.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numeric>

namespace akvf {

namespace {

// Vertex lists of the charts, each in increasing order.
std::vector<std::vector<int>> chart_vertices(const Eigen::MatrixXi& F, const std::vector<int>& face_chart,
                                             int num_charts, int num_vertices) {
  std::vector<int> chart_of(num_vertices, -1);
  for (int f = 0; f < F.rows(); ++f)
    for (int k = 0; k < 3; ++k) chart_of[F(f, k)] = face_chart[f];
  std::vector<std::vector<int>> vertices(num_charts);
  for (int v = 0; v < num_vertices; ++v)
    if (chart_of[v] >= 0) vertices[chart_of[v]].push_back(v);
  return vertices;
}

// The extent of `hull` turned by `angle`.
Eigen::Vector2d turned_size(const std::vector<Eigen::Vector2d>& hull, double angle) {
  const Eigen::Rotation2Dd turn(angle);
  Eigen::Vector2d lo = turn * hull[0], hi = lo;
  for (const Eigen::Vector2d& p : hull) {
    lo = lo.cwiseMin(turn * p);
    hi = hi.cwiseMax(turn * p);
  }
  return hi - lo;
}

// The angle that turns a hull to its smallest bounding rectangle, which has
// a side on the hull (Freeman and Shapira 1975), lying flat.
double flat_box_angle(const std::vector<Eigen::Vector2d>& hull) {
  double best_area = std::numeric_limits<double>::infinity(), best_angle = 0;
  for (std::size_t i = 0; i < hull.size(); ++i) {
    const Eigen::Vector2d edge = hull[(i + 1) % hull.size()] - hull[i];
    if (edge.squaredNorm() == 0) continue;
    const double angle = -std::atan2(edge.y(), edge.x());
    const Eigen::Vector2d size = turned_size(hull, angle);
    if (size.prod() < best_area) {
      best_area = size.prod();
      best_angle = size.y() > size.x() ? angle + M_PI / 2 : angle;
    }
  }
  return best_angle;
}

// The angle that turns a hull to its smallest bounding square: the larger
// extent is minimal where a hull side lies flat or where width and height
// cross, so 1024 angles of a quarter turn, then the best one refined by
// golden sections, find it to rounding.
double square_angle(const std::vector<Eigen::Vector2d>& hull) {
  if (hull.empty()) return 0;  // the chart's points coincide
  const auto side = [&](double angle) { return turned_size(hull, angle).maxCoeff(); };
  const int samples = 1024;
  const double step = M_PI / 2 / samples;
  int best = 0;
  for (int i = 1; i < samples; ++i)
    if (side(i * step) < side(best * step)) best = i;
  double a = (best - 1) * step, b = (best + 1) * step;
  const double golden = (std::sqrt(5.0) - 1) / 2;
  for (int i = 0; i < 40; ++i) {
    const double c = b - golden * (b - a), d = a + golden * (b - a);
    if (side(c) < side(d))
      b = d;
    else
      a = c;
  }
  return side(0.5 * (a + b)) < side(best * step) ? 0.5 * (a + b) : best * step;
}

}  // namespace

Eigen::MatrixXd tutte_embedding_charts(const TriMesh& mesh, const std::vector<std::vector<int>>& boundary_loops,
                                       const std::vector<int>& face_chart, TutteWeights weights, Warnings* warnings,
                                       const SpdSolver& solver) {
  const int charts = static_cast<int>(boundary_loops.size());
  if (charts == 1) return tutte_embedding(mesh, boundary_loops[0], weights, warnings, solver);
  const std::vector<std::vector<int>> vertices = chart_vertices(mesh.F, face_chart, charts, mesh.num_vertices());
  std::vector<std::vector<int>> faces(charts);
  for (int f = 0; f < mesh.num_faces(); ++f) faces[face_chart[f]].push_back(f);
  Eigen::MatrixXd UV = Eigen::MatrixXd::Zero(mesh.num_vertices(), 2);
  std::vector<int> local(mesh.num_vertices(), -1);
  for (int c = 0; c < charts; ++c) {
    TriMesh chart;
    chart.V.resize(static_cast<Eigen::Index>(vertices[c].size()), 3);
    for (std::size_t i = 0; i < vertices[c].size(); ++i) {
      local[vertices[c][i]] = static_cast<int>(i);
      chart.V.row(i) = mesh.V.row(vertices[c][i]);
    }
    chart.F.resize(static_cast<Eigen::Index>(faces[c].size()), 3);
    for (std::size_t row = 0; row < faces[c].size(); ++row)
      chart.F.row(row) = mesh.F.row(faces[c][row]).unaryExpr([&](int v) { return local[v]; });
    std::vector<int> loop(boundary_loops[c].size());
    std::transform(boundary_loops[c].begin(), boundary_loops[c].end(), loop.begin(), [&](int v) { return local[v]; });
    // The solver sees the whole mesh's vertices (an ordering may be of those).
    const SpdSolver chart_solver = !solver ? SpdSolver{}
                                           : [&](const Eigen::SparseMatrix<double>& A, const Eigen::MatrixXd& B,
                                                 const std::vector<int>& chart_vertices, Eigen::MatrixXd* X) {
                                               std::vector<int> mesh_vertices(chart_vertices.size());
                                               for (std::size_t i = 0; i < chart_vertices.size(); ++i)
                                                 mesh_vertices[i] = vertices[c][chart_vertices[i]];
                                               return solver(A, B, mesh_vertices, X);
                                             };
    const Eigen::MatrixXd chart_uv = tutte_embedding(chart, loop, weights, warnings, chart_solver);
    for (std::size_t i = 0; i < vertices[c].size(); ++i) UV.row(vertices[c][i]) = chart_uv.row(i);
  }
  pack_charts(mesh.F, face_chart, charts, &UV);
  return UV;
}

void pack_charts(const Eigen::MatrixXi& F, const std::vector<int>& face_chart, int num_charts, Eigen::MatrixXd* UV,
                 bool rotate_to_boxes, double gutter, PackingGrid grid, double min_coverage) {
  if (num_charts < 1 || (num_charts == 1 && !rotate_to_boxes)) return;
  const std::vector<std::vector<int>> vertices =
      chart_vertices(F, face_chart, num_charts, static_cast<int>(UV->rows()));
  // With rotate_to_boxes, each chart is turned to its smallest bounding
  // rectangle, lying flat, for the rows (one chart: to its smallest bounding
  // square). The raster gets two sets of turns of the charts as given:
  // every chart flat, or every chart in its square, each then by any number
  // of quarter turns (a half turn lets wedges interlock); below
  // min_coverage on the fine grid, each set by any number of eighth turns.
  const Eigen::MatrixXd given = *UV;
  std::array<std::vector<std::vector<double>>, 4> turns;
  for (auto& chart_turns : turns) chart_turns.resize(num_charts);
  if (rotate_to_boxes)
    for (int c = 0; c < num_charts; ++c) {
      std::vector<Eigen::Vector2d> points;
      for (int v : vertices[c]) points.push_back(UV->row(v).transpose());
      const std::vector<Eigen::Vector2d> hull = convex_hull(points);
      const double flat = flat_box_angle(hull), square = square_angle(hull);
      for (int quarter = 0; quarter < 4; ++quarter) {
        turns[0][c].push_back(flat + quarter * M_PI / 2);
        turns[1][c].push_back(square + quarter * M_PI / 2);
      }
      for (int eighth = 0; eighth < 8; ++eighth) {
        turns[2][c].push_back(flat + eighth * M_PI / 4);
        turns[3][c].push_back(square + eighth * M_PI / 4);
      }
      const Eigen::Matrix2d turn = Eigen::Rotation2Dd(num_charts == 1 ? square : flat).toRotationMatrix();
      for (int v : vertices[c]) UV->row(v) = (turn * UV->row(v).transpose()).transpose();
    }
  if (num_charts == 1) return;
  std::vector<Eigen::RowVector2d> low(num_charts), size(num_charts);
  double box_area = 0;
  for (int c = 0; c < num_charts; ++c) {
    Eigen::RowVector2d lo = UV->row(vertices[c].front()), hi = lo;
    for (int v : vertices[c]) {
      lo = lo.cwiseMin(UV->row(v));
      hi = hi.cwiseMax(UV->row(v));
    }
    low[c] = lo;
    size[c] = hi - lo;
    box_area += size[c].x() * size[c].y();
  }
  double widest = 0, total_width = 0;
  for (int c = 0; c < num_charts; ++c) {
    widest = std::max(widest, size[c].x());
    total_width += size[c].x();
  }
  std::vector<int> order(num_charts);
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return size[a].y() > size[b].y(); });
  // Rows of at most row_width with `gap` between boxes: each chart's lower
  // corner (or, without `corners`, only the side of the square around them).
  const auto rows = [&](double row_width, double gap, std::vector<Eigen::RowVector2d>* corners) {
    double x = 0, y = 0, row_height = 0, width = 0;
    for (int c : order) {
      if (x > 0 && x + size[c].x() > row_width) {  // start a new row above
        x = 0;
        y += row_height + gap;
        row_height = 0;
      }
      if (corners) (*corners)[c] = Eigen::RowVector2d(x, y);
      width = std::max(width, x + size[c].x());
      x += size[c].x() + gap;
      row_height = std::max(row_height, size[c].y());
    }
    return std::max(width, y + row_height);
  };
  std::vector<std::vector<int>> chart_faces(num_charts);
  for (int f = 0; f < F.rows(); ++f) chart_faces[face_chart[f]].push_back(f);
  // The gutter is a share of the square's side, which the gap itself
  // widens: a layout is redone with gaps from its last side, 1 % over,
  // until they hold (they approach that fixed point geometrically; one
  // round for the small gutters of real textures; the square is at least
  // sqrt(box_area)). layout(least_gap, &kept) returns the side of its
  // square and the least distance it keeps between charts.
  const auto holding_gutter = [&](const auto& layout) {
    double kept = 0;
    double side = layout(gutter * std::sqrt(box_area), &kept);
    for (int round = 0; round < 16 && kept < gutter * side; ++round) side = layout(1.01 * gutter * side, &kept);
    return side;
  };
  // Boxes in rows, the gutter apart (a start map's: also 2 % of the
  // square), the row width that fits the smallest square among 32 from one
  // chart to all per row.
  std::vector<Eigen::RowVector2d> corner(num_charts);
  double side = holding_gutter([&](double least_gap, double* kept) {
    const double gap = rotate_to_boxes ? least_gap : std::max(0.02 * std::sqrt(box_area), least_gap);
    double row_width = std::max(std::sqrt(box_area), widest);
    if (rotate_to_boxes) {
      const double last = total_width + num_charts * gap;
      double best = rows(row_width, gap, nullptr);
      for (int i = 0; i <= 32; ++i) {
        const double candidate = widest * std::pow(std::max(last / widest, 1.0), i / 32.0);
        if (const double trial = rows(candidate, gap, nullptr); trial < best) {
          best = trial;
          row_width = candidate;
        }
      }
    }
    *kept = gap;
    return rows(row_width, gap, &corner);
  });
  // Charts that interlock, when they fit a smaller square so. The eighth
  // turns only where the quarter turns leave the square emptier than asked
  // (thin sectors, as a cone's spikes unrolled, fan out only by finer
  // turns): they triple the work of the finest layout.
  std::vector<ChartPlacement> placement;
  bool interlocked = false;
  const double area = map_area(F, given);
  if (rotate_to_boxes)
    for (std::size_t set = 0; set < turns.size(); ++set) {
      if (set >= 2 && (grid != PackingGrid::kFine || area >= min_coverage * side * side)) break;
      const auto& chart_turns = turns[set];
      std::vector<ChartPlacement> trial;
      const double raster_side = holding_gutter([&](double least_gap, double* kept) {
        return raster_pack(F, chart_faces, given, chart_turns, least_gap, &trial, kept, grid);
      });
      if (raster_side < side) {
        interlocked = true;
        placement = std::move(trial);
        side = raster_side;
      }
    }
  if (interlocked) {
    *UV = given;
    apply_placement(F, chart_faces, placement, UV);
    return;
  }
  for (int c = 0; c < num_charts; ++c)
    for (int v : vertices[c]) UV->row(v) += corner[c] - low[c];
}

double square_coverage(const Eigen::MatrixXi& F, const Eigen::MatrixXd& UV) {
  if (F.rows() == 0) return 0;
  Eigen::RowVector2d lo = UV.row(F(0, 0)), hi = lo;
  double area = 0;
  for (int f = 0; f < F.rows(); ++f) {
    for (int k = 0; k < 3; ++k) {
      lo = lo.cwiseMin(UV.row(F(f, k)));
      hi = hi.cwiseMax(UV.row(F(f, k)));
    }
    area += triangle_area(F, UV, f);
  }
  const double side = (hi - lo).maxCoeff();
  return side > 0 ? area / (side * side) : 0;
}

}  // namespace akvf
