#include "framework/mesh/vertex_graph.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>

namespace akvf {

UpperVertexGraph upper_vertex_graph(const Eigen::MatrixXi& elements, int num_vertices) {
  const int ne = static_cast<int>(elements.rows()), N = static_cast<int>(elements.cols());
  const auto for_each_pair = [&](int e, auto&& visit) {  // visit(u, v) for u <= v, with repeats
    for (int j = 0; j < N; ++j)
      for (int i = 0; i < N; ++i)
        if (elements(e, i) < elements(e, j) || i == j) visit(elements(e, i), elements(e, j));
  };
  // Every pair of every element, counted and listed under its larger vertex.
  std::vector<long> listed_start(num_vertices + 1, 0);
  for (int e = 0; e < ne; ++e) for_each_pair(e, [&](int, int v) { ++listed_start[v + 1]; });
  for (int v = 0; v < num_vertices; ++v) listed_start[v + 1] += listed_start[v];
  std::vector<int> listed(listed_start[num_vertices]);
  {
    std::vector<long> fill(listed_start.begin(), listed_start.end() - 1);
    for (int e = 0; e < ne; ++e) for_each_pair(e, [&](int u, int v) { listed[fill[v]++] = u; });
  }
  // Each list sorted and its repeats dropped (v itself sorts last), then
  // the lists packed.
  std::vector<int> distinct(num_vertices, 0);
  tbb::parallel_for(tbb::blocked_range<int>(0, num_vertices, 4096), [&](const tbb::blocked_range<int>& range) {
    for (int v = range.begin(); v != range.end(); ++v) {
      const auto begin = listed.begin() + listed_start[v], end = listed.begin() + listed_start[v + 1];
      std::sort(begin, end);
      distinct[v] = static_cast<int>(std::unique(begin, end) - begin);
    }
  });
  UpperVertexGraph graph;
  graph.column_start.assign(num_vertices + 1, 0);
  for (int v = 0; v < num_vertices; ++v) graph.column_start[v + 1] = graph.column_start[v] + distinct[v];
  graph.row.resize(graph.column_start[num_vertices]);
  tbb::parallel_for(tbb::blocked_range<int>(0, num_vertices, 4096), [&](const tbb::blocked_range<int>& range) {
    for (int v = range.begin(); v != range.end(); ++v)
      std::copy_n(listed.begin() + listed_start[v], distinct[v], graph.row.begin() + graph.column_start[v]);
  });
  return graph;
}

}  // namespace akvf
