#include "solvers/fill_reducing_ordering.h"

#include <cholmod.h>

#include <tbb/parallel_invoke.h>

#include "akvf/error.h"

namespace akvf {

namespace {

// Whether to compute METIS's nested dissection besides AMD. On large meshes
// it needs far fewer flops (horse_b subdivided to 2.55 M unknowns: 69
// GFlop instead of 159, a factor with 195 M entries instead of 259 M), but
// its analysis costs about 0.7 us per nonzero of the block graph on this
// machine (horse_b: 79 ms against AMD's 19 ms), more than a factorization of
// the small meshes, where AMD's ordering is as good or better (horse_b: 110
// MFlop with AMD, 130 with METIS). So it is tried when one factorization
// with AMD's ordering, at about 1e10 flop/s, would take longer than the
// analysis: AMD's flops per block-graph nonzero above 0.7e-6 x 1e10 = 7000.
// (`amd_flops` are the expanded matrix's: block_size^3 times the graph's.)
// CHOLMOD's own rule tries METIS only above 500 flops per factor nonzero,
// a rule for scalar matrices that the block graph, with b^3 / b^2 = b times
// fewer flops per nonzero than the matrix factored, stays below.
bool use_metis(double amd_flops, double graph_nonzeros) { return amd_flops > 7000 * graph_nonzeros; }

// Whether to start METIS's ordering before AMD's result decides whether it
// is needed (use_metis), on the core that AMD's ordering leaves idle. A
// needless METIS run delays the analysis by METIS's time minus AMD's (about
// 4x AMD's on the meshes measured); a needed one saves AMD's (horse_b x64:
// 1.3 s of 8.5 s, METIS 7 s). So it pays only where METIS is almost always
// needed: on large meshes. AMD's fill on a mesh-like (planar) graph grows
// faster than nested dissection's O(n log n) (Lipton, Rose and Tarjan), so
// its flops per nonzero, which use_metis compares, grow with the mesh; every
// mesh measured here from 1.8e5 vertices on (camelhead and horse_b
// subdivided, up to 5.1e6 vertices) needed METIS, the largest paper mesh
// (horse_b, 2e4 vertices) does not. The first power of two above the
// paper's meshes by a margin: 2^17 blocks. Either way the ordering kept is
// the one use_metis chooses: only the timing depends on this guess.
// (Two METIS orderings must not run at once, e.g. of the two halves left by
// a top separator: METIS draws from libc's rand(), one state for the
// process, so concurrent calls interleave their draws and the ordering, and
// with it the factor's rounding, changes from run to run: horse_b x16's
// factor had 39.92 M, 39.99 M and 39.93 M entries in three such runs.)
bool start_metis_early(int blocks) { return blocks >= (1 << 17); }

// CHOLMOD's analysis of the graph with `method` (CHOLMOD_AMD, CHOLMOD_METIS,
// or CHOLMOD_GIVEN with `given`), postordered: the permutation and its
// factor's nonzeros and flops. Its own cholmod_common: two may run at the
// same time. Simplicial: the supernodes of the graph's factor are not used.
BlockOrdering block_ordering(const UpperVertexGraph& graph, int method, const std::vector<int>* given,
                             std::string name) {
  struct Workspace {
    cholmod_common common;
    Workspace() { cholmod_start(&common); }
    ~Workspace() { cholmod_finish(&common); }
  } w;
  cholmod_common& common = w.common;
  common.print = 0;
  common.nmethods = 1;
  common.method[0].ordering = method;
  common.postorder = 1;
  common.supernodal = CHOLMOD_SIMPLICIAL;
  // CHOLMOD reads the pattern only (const_cast: its structs are not const).
  const int blocks = graph.num_vertices();
  cholmod_sparse A{};
  A.nrow = A.ncol = static_cast<size_t>(blocks);
  A.nzmax = graph.row.size();
  A.p = const_cast<int*>(graph.column_start.data());
  A.i = const_cast<int*>(graph.row.data());
  A.stype = 1;
  A.itype = CHOLMOD_INT;
  A.xtype = CHOLMOD_PATTERN;
  A.dtype = CHOLMOD_DOUBLE;
  A.sorted = 1;
  A.packed = 1;
  cholmod_factor* ordering =
      cholmod_analyze_p(&A, given ? const_cast<int*>(given->data()) : nullptr, nullptr, 0, &common);
  if (common.status < CHOLMOD_OK || !ordering)
    throw NumericalError("CHOLMOD ordering failed (status " + std::to_string(common.status) + ")");
  const int* perm = static_cast<const int*>(ordering->Perm);
  BlockOrdering result{std::vector<int>(perm, perm + blocks), std::move(name), true};
  result.factor_nonzeros = common.method[0].lnz;
  result.factor_flops = common.method[0].fl;
  cholmod_free_factor(&ordering, &common);
  return result;
}

}  // namespace

BlockOrdering fill_reducing_ordering(const UpperVertexGraph& graph, int block_size, bool always_try_metis) {
  const int blocks = graph.num_vertices();
  const double expanded = static_cast<double>(block_size) * block_size * block_size;
  BlockOrdering amd, metis;
  const auto order_by_amd = [&] { amd = block_ordering(graph, CHOLMOD_AMD, nullptr, "amd"); };
  const auto order_by_metis = [&] { metis = block_ordering(graph, CHOLMOD_METIS, nullptr, "metis"); };
  const auto metis_wanted = [&] {
    return always_try_metis || use_metis(expanded * amd.factor_flops, static_cast<double>(graph.row.size()));
  };
  if (!always_try_metis && start_metis_early(blocks)) {
    tbb::parallel_invoke(order_by_amd, order_by_metis);
  } else {
    order_by_amd();
    if (metis_wanted()) order_by_metis();
  }
  if (metis_wanted() && metis.factor_flops < amd.factor_flops) return metis;  // metis_wanted(): METIS ran
  return amd;
}

BlockOrdering postordered(const UpperVertexGraph& graph, const BlockOrdering& order) {
  if (static_cast<int>(order.permutation.size()) != graph.num_vertices())
    throw NumericalError("postordered: the order has " + std::to_string(order.permutation.size()) +
                         " blocks, the graph " + std::to_string(graph.num_vertices()));
  return block_ordering(graph, CHOLMOD_GIVEN, &order.permutation, order.method);
}

double expanded_flops_per_entry(const BlockOrdering& ordering, int block_size) {
  // A column of c blocks in the blocks' factor gives b columns of b c - j
  // entries, j = 0 .. b - 1; CHOLMOD counts the sums of the columns' entries
  // and of their squares.
  if (!(ordering.factor_nonzeros > 0)) return 0;
  const double b = block_size, blocks = static_cast<double>(ordering.permutation.size());
  const double nonzeros = b * b * ordering.factor_nonzeros - blocks * b * (b - 1) / 2;
  const double flops = b * b * b * ordering.factor_flops - b * b * (b - 1) * ordering.factor_nonzeros +
                       blocks * (b - 1) * b * (2 * b - 1) / 6;
  return flops / nonzeros;
}

std::vector<int> restricted_order(const BlockOrdering& ordering, const std::vector<int>& subset) {
  std::vector<int> index(ordering.permutation.size(), -1);
  for (std::size_t i = 0; i < subset.size(); ++i) {
    if (subset[i] < 0 || subset[i] >= static_cast<int>(index.size()) || index[subset[i]] >= 0)
      throw NumericalError("restricted_order: the subset lists block " + std::to_string(subset[i]) +
                           " twice or outside the ordering's " + std::to_string(index.size()));
    index[subset[i]] = static_cast<int>(i);
  }
  std::vector<int> order;
  order.reserve(subset.size());
  for (int block : ordering.permutation)
    if (index[block] >= 0) order.push_back(index[block]);
  return order;
}

}  // namespace akvf
