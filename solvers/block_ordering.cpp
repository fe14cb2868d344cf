#include "solvers/block_ordering.h"

#include <cholmod.h>
#include <tbb/parallel_invoke.h>

#include <string>
#include <utility>

#include "framework/process/error.h"

namespace akvf {

namespace {

struct Common {
  cholmod_common common;
  Common() {
    cholmod_start(&common);
    common.print = 0;
  }
  ~Common() { cholmod_finish(&common); }
  Common(const Common&) = delete;
  Common& operator=(const Common&) = delete;
};

void check(const cholmod_common& common, const char* what) {
  if (common.status < CHOLMOD_OK)
    throw NumericalError(std::string("CHOLMOD ") + what + " failed (status " + std::to_string(common.status) + ")");
}

// CHOLMOD's analysis of A with the ordering `method`, or the `given`
// permutation (CHOLMOD_GIVEN), postordered.
std::vector<int> analyzed_ordering(cholmod_sparse* A, int method, int* given, double* flops) {
  Common w;
  cholmod_common& common = w.common;
  common.nmethods = 1;
  common.method[0].ordering = method;
  common.postorder = 1;
  cholmod_factor* ordering = cholmod_analyze_p(A, given, nullptr, 0, &common);
  check(common, "symbolic analysis");
  const int* perm = static_cast<const int*>(ordering->Perm);
  std::vector<int> permutation(perm, perm + A->nrow);
  *flops = common.method[0].fl;
  cholmod_free_factor(&ordering, &common);
  return permutation;
}

// The subgraph of A (upper triangle with its diagonal, sorted columns)
// induced by the nodes of `part`, numbered as in `part`.
struct Subgraph {
  std::vector<int> column_start{0}, row;
  cholmod_sparse view(int n) {
    cholmod_sparse S{};
    S.nrow = S.ncol = static_cast<size_t>(n);
    S.nzmax = static_cast<size_t>(column_start.back());
    S.p = column_start.data();
    S.i = row.data();
    S.stype = 1;
    S.itype = CHOLMOD_INT;
    S.xtype = CHOLMOD_PATTERN;
    S.dtype = CHOLMOD_DOUBLE;
    S.sorted = 1;
    S.packed = 1;
    return S;
  }
};

Subgraph induced_subgraph(const cholmod_sparse& A, const std::vector<int>& part, const std::vector<int>& local) {
  const int* start = static_cast<const int*>(A.p);
  const int* rows = static_cast<const int*>(A.i);
  Subgraph g;
  for (int node : part) {
    // Rows stay sorted: `local` numbers a part's nodes in increasing order.
    for (int k = start[node]; k < start[node + 1]; ++k)
      if (local[rows[k]] >= 0 && rows[k] <= node) g.row.push_back(local[rows[k]]);
    g.column_start.push_back(static_cast<int>(g.row.size()));
  }
  return g;
}

// METIS's nested dissection of one half, in the half's numbering.
std::vector<int> metis_order(Subgraph g, int n) {
  std::vector<int> perm(static_cast<size_t>(n));
  if (n == 0) return perm;
  Common w;
  cholmod_sparse S = g.view(n);
  cholmod_metis(&S, nullptr, 0, 0, perm.data(), &w.common);
  check(w.common, "METIS ordering");
  return perm;
}

}  // namespace

std::vector<int> block_ordering(cholmod_sparse* A, int method, double* flops) {
  return analyzed_ordering(A, method, nullptr, flops);
}

std::vector<int> nested_dissection_two_cores(cholmod_sparse* A, double* flops, const std::function<void()>& also) {
  const int n = static_cast<int>(A->nrow);
  std::vector<int> part[3];  // each side's nodes in increasing order; part[2] the separator
  std::vector<int> order[2];
  const auto dissect = [&] {
    std::vector<int> side(static_cast<size_t>(n)), local(static_cast<size_t>(n));
    {
      Common w;
      cholmod_bisect(A, nullptr, 0, 1, side.data(), &w.common);
      check(w.common, "METIS vertex separator");
    }
    for (int node = 0; node < n; ++node) {
      local[node] = static_cast<int>(part[side[node]].size());
      part[side[node]].push_back(node);
    }
    const auto order_half = [&](int h) {
      std::vector<int> in_half(static_cast<size_t>(n), -1);
      for (int node : part[h]) in_half[node] = local[node];
      order[h] = metis_order(induced_subgraph(*A, part[h], in_half), static_cast<int>(part[h].size()));
    };
    tbb::parallel_invoke([&] { order_half(0); }, [&] { order_half(1); });
  };
  // `also` (AMD's ordering) on the second core while the first finds the
  // separator; whichever core is free first takes the second half.
  if (also)
    tbb::parallel_invoke(also, dissect);
  else
    dissect();
  // The first half, the second, the separator last (as METIS numbers them).
  std::vector<int> permutation;
  permutation.reserve(static_cast<size_t>(n));
  for (int h = 0; h < 2; ++h)
    for (int k : order[h]) permutation.push_back(part[h][k]);
  permutation.insert(permutation.end(), part[2].begin(), part[2].end());
  return analyzed_ordering(A, CHOLMOD_GIVEN, permutation.data(), flops);
}

}  // namespace akvf
