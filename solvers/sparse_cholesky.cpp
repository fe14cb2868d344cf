#include "solvers/sparse_cholesky.h"

#include <cholmod.h>

#include <algorithm>
#include <cstring>
#include <memory>
#include <tuple>
#include <type_traits>
#include <utility>
#include <vector>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "akvf/error.h"
#include "framework/process/huge_page_array.h"
#include "solvers/fill_reducing_ordering.h"
#include "solvers/supernodal_factorization.h"
#include "solvers/supernodal_solve.h"

namespace akvf {

// How the matrix reaches CHOLMOD. Given the upper triangle of A and a
// fill-reducing permutation P (found once by cholmod_analyze), we keep the
// lower triangle of P A P^T ourselves, in the compressed form CHOLMOD's
// supernodal factorization reads directly when the ordering is natural
// (stype < 0). cholmod_factorize on A with a permutation would instead build a
// permuted transpose, with its allocations, at every call; here CHOLMOD's
// factorizations get the values gathered through a fixed index map, and our
// supernodal factorization reads them through the map from A's own values
// (no copy: at 10 M triangles the lower triangle's values are 0.6 GB).
//
// The pattern part (permutation, lower triangle's indices, index map) is
// immutable after the analysis and shared by copies of it (copy_analysis:
// the cache of symbolic_analysis_cache.h, kept by the API's repeated solves),
// so an analysis kept for later costs no values (at 10 M triangles the
// lower triangle's indices are 0.9 GB).
struct PermutedPattern {
  std::vector<int> permutation;  // row a of P A P^T is row permutation[a] of A
  std::vector<int> lower_column_start, lower_row;
  std::vector<int> source;  // entry p of the lower triangle is nonzero source[p] of the upper input
};

namespace {

using Long = SuiteSparse_long;

// CHOLMOD's entry points for one integer width: cholmod_* (int) and
// cholmod_l_* (SuiteSparse_long).
template <class Index>
struct Cholmod;
#define AKVF_CHOLMOD_API(INDEX, PREFIX, ITYPE)                      \
  template <>                                                       \
  struct Cholmod<INDEX> {                                           \
    static constexpr int itype = ITYPE;                             \
    static constexpr auto start = &PREFIX##start;                   \
    static constexpr auto finish = &PREFIX##finish;                 \
    static constexpr auto analyze = &PREFIX##analyze;               \
    static constexpr auto factorize = &PREFIX##factorize;           \
    static constexpr auto copy_factor = &PREFIX##copy_factor;       \
    static constexpr auto free_factor = &PREFIX##free_factor;       \
    static constexpr auto allocate_dense = &PREFIX##allocate_dense; \
    static constexpr auto free_dense = &PREFIX##free_dense;         \
    static constexpr auto solve2 = &PREFIX##solve2;                 \
  };
AKVF_CHOLMOD_API(int, cholmod_, CHOLMOD_INT)
AKVF_CHOLMOD_API(Long, cholmod_l_, CHOLMOD_LONG)
#undef AKVF_CHOLMOD_API

void check_status(const cholmod_common& common, const char* what) {
  if (common.status < CHOLMOD_OK)
    throw NumericalError(std::string("CHOLMOD ") + what + " failed (status " + std::to_string(common.status) + ")");
}

template <class Index>
cholmod_sparse sparse_view(Index n, Index* column_start, Index* row, double* value, int stype) {
  cholmod_sparse A{};
  A.nrow = A.ncol = static_cast<size_t>(n);
  A.nzmax = static_cast<size_t>(column_start[n]);
  A.p = column_start;
  A.i = row;
  A.x = value;
  A.stype = stype;
  A.itype = Cholmod<Index>::itype;
  A.xtype = value ? CHOLMOD_REAL : CHOLMOD_PATTERN;
  A.dtype = CHOLMOD_DOUBLE;
  A.sorted = 1;
  A.packed = 1;
  return A;
}

}  // namespace

// The numeric side, for one integer width: CHOLMOD's analysis of the
// permuted lower triangle in its natural order, its factor, and the solves.
class PermutedFactor {
 public:
  virtual ~PermutedFactor() = default;
  // Symbolic analysis; false if the factor is too large for this integer
  // width (CHOLMOD_TOO_LARGE), any other failure throws. expected_flops_per_entry:
  // the factor's flops over its nonzeros as the blocks' factor predicts them
  // (0: unknown); it only decides which analysis is tried first.
  virtual bool analyze(const std::shared_ptr<const PermutedPattern>& pattern, double expected_flops_per_entry) = 0;
  // A new object holding a copy of this (analyzed, unfactored) analysis.
  virtual std::unique_ptr<PermutedFactor> copy_analysis() const = 0;
  // upper_values: the upper input's nonzeros (PermutedPattern::source
  // maps them to the lower triangle). A supernodal factor is computed by
  // SupernodalFactorization (every thread) unless `by_cholmod`.
  virtual void factorize(const double* upper_values, bool by_cholmod) = 0;
  // z = (L L^T)^-1 z in the permuted numbering.
  virtual void solve(double* z) = 0;
  // SparseCholesky::round_factor_to_single (a supernodal factor only).
  virtual void round_to_single() = 0;
  virtual bool single() const = 0;
  virtual bool supernodal() const = 0;
  virtual bool factored() const = 0;
  // SupernodalFactorization::critical_path_share, SupernodalSolve::top_share.
  virtual double factor_critical_path_share() = 0;
  virtual double solve_top_share(int threads) = 0;
  virtual int index_bits() const = 0;
  virtual double bytes() const = 0;
  double nonzeros = 0, flops = 0;  // of the factor, from the analysis
};

namespace {

// Our analysis (CholmodFactor's `cholmod_defaults` false) differs from
// CHOLMOD's where CHOLMOD would factor simplicially: below 40 flops per
// factor entry (its supernodal switch; hilbert_b's K has 21) it computes
// L D L^T column by column on one core, because there the supernodes are too
// small to pay for their overhead. There we analyze supernodal instead, with
// CHOLMOD's own limits for merging supernodes, and factor with
// SupernodalFactorization on every thread. Measured with `akvf_benchmarks
// --benchmark_filter='^(NumericFactorization|Solve)/'` on one core:
// hilbert_b 11.1 ms simplicial (CHOLMOD's), 3.3 ms here; merging up to
// twice as many columns stored 36 % more of L
// (explicit zeros) and was 8 % slower on one core, the same on two
// (docs/notes/2026-11-30-rounding-batch.md).

template <class Index>
class CholmodFactor final : public PermutedFactor {
  using Api = Cholmod<Index>;

 public:
  // cholmod_defaults: CHOLMOD's analysis as it is (the unit of
  // akvf_speed's table); otherwise ours (above).
  explicit CholmodFactor(bool cholmod_defaults) : ours_(!cholmod_defaults) {
    Api::start(&common_);
    common_.print = 0;  // errors are reported through exceptions, not stderr
    // The matrix comes permuted and postordered (SparseCholesky::analyze).
    common_.nmethods = 1;
    common_.method[0].ordering = CHOLMOD_NATURAL;
    common_.postorder = 0;
  }
  ~CholmodFactor() override {
    Api::free_factor(&factor_, &common_);
    Api::free_dense(&rhs_, &common_);
    Api::free_dense(&solution_, &common_);
    Api::free_dense(&workspace_y_, &common_);
    Api::free_dense(&workspace_e_, &common_);
    Api::finish(&common_);
  }

  bool analyze(const std::shared_ptr<const PermutedPattern>& pattern, double expected_flops_per_entry) override {
    set_pattern(pattern);
    cholmod_sparse B = lower(nullptr);
    // Where the matrix is expected below CHOLMOD's supernodal switch, our
    // analysis for it comes first, and it stays when CHOLMOD's counts, which
    // the supernodal settings do not change, confirm it: one analysis
    // instead of two. Otherwise, or if they do not, CHOLMOD's choice first.
    if (ours_ && expected_flops_per_entry > 0 && expected_flops_per_entry < common_.supernodal_switch) {
      if (!analyze_supernodal(&B)) return false;
      if (!(common_.lnz > 0 && common_.fl / common_.lnz >= common_.supernodal_switch)) return counted();
      common_.supernodal = CHOLMOD_AUTO;
    }
    if (!analyze_lower(&B)) return false;
    if (ours_ && !factor_->is_super && !analyze_supernodal(&B)) return false;
    return counted();
  }

  std::unique_ptr<PermutedFactor> copy_analysis() const override {
    auto copy = std::make_unique<CholmodFactor<Index>>(!ours_);
    copy->pattern_ = pattern_;
    copy->column_start_ = column_start_;
    copy->row_ = row_;
    copy->factor_ = Api::copy_factor(factor_, &copy->common_);
    check_status(copy->common_, "copy of a symbolic analysis");
    copy->nonzeros = nonzeros;
    copy->flops = flops;
    return copy;
  }

  void factorize(const double* upper_values, bool by_cholmod) override {
    own_factored_ = false;
    single_ = false;
    const std::vector<int>& source = pattern_->source;
    if (factor_->is_super && !by_cholmod) {
      // Not value-initialized: each supernode's block is set when it is
      // built, so the pages are first touched by the core that builds it;
      // on huge pages where the system gives them (huge_page_array.h).
      if (!factor_values_) factor_values_ = allocate_huge_page_doubles(factor_->xsize);
      const LowerTriangle A{static_cast<int>(factor_->n), pattern_->lower_column_start.data(),
                            pattern_->lower_row.data(), upper_values, source.data()};
      parallel_factorization().factorize(A, factor_values_.get());
      own_factored_ = true;
      return;
    }
    lower_value_.resize(source.size());  // allocated at the first factorization
    for (std::size_t p = 0; p < source.size(); ++p) lower_value_[p] = upper_values[source[p]];
    cholmod_sparse B = lower(lower_value_.data());
    Api::factorize(&B, factor_, &common_);
    if (common_.status == CHOLMOD_NOT_POSDEF)
      throw NotPositiveDefinite("matrix is not positive definite (CHOLMOD stopped at column " +
                                std::to_string(factor_->minor) + ")");
    // CHOLMOD's simplicial factorization (small matrices) is L D L^T, which
    // goes on through negative pivots and reports only zero ones: a matrix
    // that is not positive definite must not pass there either.
    if (!factor_->is_super && !factor_->is_ll) {
      const Index* column_start = static_cast<const Index*>(factor_->p);
      const double* value = static_cast<const double*>(factor_->x);
      for (size_t j = 0; j < factor_->n; ++j)
        if (!(value[column_start[j]] > 0))  // D(j, j) leads column j
          throw NotPositiveDefinite("matrix is not positive definite (pivot " + std::to_string(j) + " of L D L^T is " +
                                    std::to_string(value[column_start[j]]) + ")");
    }
    check_status(common_, "numeric factorization");
  }

  void solve(double* z) override {
    if (factor_->is_super) {
      if (single_)
        supernodal_solve().solve(reinterpret_cast<const SingleEntry*>(values()), z);
      else
        supernodal_solve().solve(static_cast<const double*>(values()), z);
      return;
    }
    const size_t n = factor_->n;
    if (!rhs_) rhs_ = Api::allocate_dense(n, 1, n, CHOLMOD_REAL, &common_);
    std::copy(z, z + n, static_cast<double*>(rhs_->x));
    if (!Api::solve2(CHOLMOD_A, factor_, rhs_, nullptr, &solution_, nullptr, &workspace_y_, &workspace_e_, &common_))
      check_status(common_, "solve");
    const double* x = static_cast<const double*>(solution_->x);
    std::copy(x, x + n, z);
  }

  void round_to_single() override {
    if (!factor_->is_super || single_) return;
    double* value = values();
    SingleEntry* single = reinterpret_cast<SingleEntry*>(value);
    // In place, front to back: entry i's float lands in the bytes of double
    // i / 2, already read. The first stretch in order, then stretches
    // [begin, 2 begin), each in parallel: their floats land below begin.
    const auto round = [&](std::size_t begin, std::size_t end) {
      for (std::size_t i = begin; i < end; ++i) single[i].value = static_cast<float>(value[i]);
    };
    const std::size_t n = factor_->xsize, first = std::min<std::size_t>(n, 1 << 16);
    round(0, first);
    for (std::size_t begin = first; begin < n; begin *= 2)
      tbb::parallel_for(tbb::blocked_range<std::size_t>(begin, std::min(n, 2 * begin), 1 << 14),
                        [&](const tbb::blocked_range<std::size_t>& r) { round(r.begin(), r.end()); });
    single_ = true;
  }
  bool single() const override { return single_; }

  bool supernodal() const override { return factor_->is_super; }
  bool factored() const override { return own_factored_ || factor_->xtype != CHOLMOD_PATTERN; }
  double factor_critical_path_share() override {
    return factor_->is_super ? parallel_factorization().critical_path_share() : 1.0;
  }
  double solve_top_share(int threads) override {
    return factor_->is_super ? supernodal_solve().top_share(std::max(2, threads)) : 1.0;
  }
  int index_bits() const override { return 8 * static_cast<int>(sizeof(Index)); }
  // A supernodal factor stores its supernodes' dense blocks (xsize values,
  // zeros of the relaxed amalgamation included) and ssize row indices; a
  // simplicial one a value and a row index per entry.
  double bytes() const override {
    if (factor_->is_super)
      return 8.0 * static_cast<double>(factor_->xsize) + sizeof(Index) * static_cast<double>(factor_->ssize);
    return (8.0 + sizeof(Index)) * nonzeros;
  }

 private:
  // The pattern's indices as CHOLMOD's integers: the int arrays themselves,
  // or 64-bit copies (shared by copies of the analysis).
  void set_pattern(const std::shared_ptr<const PermutedPattern>& pattern) {
    pattern_ = pattern;
    if constexpr (!std::is_same_v<Index, int>) {
      column_start_ =
          std::make_shared<std::vector<Index>>(pattern->lower_column_start.begin(), pattern->lower_column_start.end());
      row_ = std::make_shared<std::vector<Index>>(pattern->lower_row.begin(), pattern->lower_row.end());
    }
  }

  // CHOLMOD reads the indices only (const_cast: its structs are not const).
  cholmod_sparse lower(double* values) const {
    const Index n = static_cast<Index>(pattern_->permutation.size());
    if constexpr (std::is_same_v<Index, int>)
      return sparse_view<Index>(n, const_cast<int*>(pattern_->lower_column_start.data()),
                                const_cast<int*>(pattern_->lower_row.data()), values, -1);
    else
      return sparse_view<Index>(n, column_start_->data(), row_->data(), values, -1);
  }

  // The factor's supernodal structure, and our triangular solves
  // (solvers/supernodal_solve.h) and numeric factorization
  // (solvers/supernodal_factorization.h) on it, set up at first use.
  SupernodalStructure<Index> structure() const {
    return {static_cast<Index>(factor_->nsuper), static_cast<const Index*>(factor_->super),
            static_cast<const Index*>(factor_->pi), static_cast<const Index*>(factor_->px),
            static_cast<const Index*>(factor_->s)};
  }
  SupernodalSolve<Index>& supernodal_solve() {
    if (!supernodal_solver_) supernodal_solver_ = std::make_unique<SupernodalSolve<Index>>(structure());
    return *supernodal_solver_;
  }
  SupernodalFactorization<Index>& parallel_factorization() {
    if (!parallel_factorization_)
      parallel_factorization_ = std::make_unique<SupernodalFactorization<Index>>(structure());
    return *parallel_factorization_;
  }

  // CHOLMOD's analysis of the permuted lower triangle B with the settings in
  // common_ (replacing any earlier one); false if too large for Index.
  bool analyze_lower(cholmod_sparse* B) {
    Api::free_factor(&factor_, &common_);
    factor_ = Api::analyze(B, &common_);
    if (common_.status == CHOLMOD_TOO_LARGE) return false;
    check_status(common_, "symbolic analysis of the permuted matrix");
    return true;
  }

  // Ours below the supernodal switch: supernodal.
  bool analyze_supernodal(cholmod_sparse* B) {
    common_.supernodal = CHOLMOD_SUPERNODAL;
    return analyze_lower(B);
  }

  // The analyzed factor's nonzeros and flops, as CHOLMOD counted them.
  bool counted() {
    nonzeros = common_.lnz;
    flops = common_.fl;
    return true;
  }

  cholmod_common common_;
  bool ours_;  // our analysis settings rather than CHOLMOD's (above)
  cholmod_factor* factor_ = nullptr;
  std::shared_ptr<const PermutedPattern> pattern_;
  std::shared_ptr<std::vector<Index>> column_start_, row_;  // 64-bit copies (long only)
  cholmod_dense* rhs_ = nullptr;
  cholmod_dense* solution_ = nullptr;
  cholmod_dense* workspace_y_ = nullptr;
  cholmod_dense* workspace_e_ = nullptr;
  std::unique_ptr<SupernodalSolve<Index>> supernodal_solver_;
  std::unique_ptr<SupernodalFactorization<Index>> parallel_factorization_;
  HugePageDoubles factor_values_;    // L by SupernodalFactorization (factor_->xsize entries)
  std::vector<double> lower_value_;  // the lower triangle's values, for CHOLMOD's factorizations
  bool own_factored_ = false;
  bool single_ = false;  // L's values rounded to single precision in place (round_to_single)
  double* values() { return own_factored_ ? factor_values_.get() : static_cast<double*>(factor_->x); }
};

}  // namespace

struct SparseCholesky::Impl {
  std::shared_ptr<const PermutedPattern> pattern;
  std::unique_ptr<PermutedFactor> factor;
  std::vector<double> permuted_rhs;
  bool wide_indices = false;       // tests: 64-bit indices from the start
  bool by_cholmod = false;         // tests, benchmarks: CHOLMOD's own numeric factorization
  bool cholmod_defaults = false;   // benchmarks: and CHOLMOD's own analysis settings
  bool always_try_metis = false;   // tests: METIS's ordering besides AMD's at any size
  std::string ordering;            // of the last analysis: "amd" or "metis"

  // The upper-triangular pattern of the graph whose nodes are the blocks of
  // block_size consecutive unknowns (block size 1: the pattern of `upper`).
  static UpperVertexGraph block_graph(const Eigen::SparseMatrix<double>& upper, int block_size) {
    const int blocks = static_cast<int>(upper.rows()) / block_size;
    const int* start = upper.outerIndexPtr();
    const int* rows = upper.innerIndexPtr();
    UpperVertexGraph graph;
    std::vector<int>& column_start = graph.column_start;
    std::vector<int>& row = graph.row;
    column_start.assign(1, 0);
    std::vector<int> last_seen(blocks, -1);
    for (int J = 0; J < blocks; ++J) {
      const std::size_t first = row.size();
      for (int j = J * block_size; j < (J + 1) * block_size; ++j)
        for (int k = start[j]; k < start[j + 1]; ++k) {
          const int I = rows[k] / block_size;
          if (I <= J && last_seen[I] != J) {
            last_seen[I] = J;
            row.push_back(I);
          }
        }
      std::sort(row.begin() + static_cast<std::ptrdiff_t>(first), row.end());
      column_start.push_back(static_cast<int>(row.size()));
    }
    return graph;
  }

  // The rest of analyze() once the blocks' ordering is known: its expansion
  // to the unknowns, the permuted lower triangle, CHOLMOD's analysis of it.
  void analyze_in_order(const Eigen::SparseMatrix<double>& upper, int block_size, const BlockOrdering& block_ordering);

  // The lower triangle of P A P^T from the pattern of `upper`.
  static std::shared_ptr<const PermutedPattern> permuted_lower(const Eigen::SparseMatrix<double>& upper,
                                                               std::vector<int> permutation) {
    const int n = static_cast<int>(upper.rows());
    auto built = std::make_shared<PermutedPattern>();
    std::vector<int>& lower_column_start = built->lower_column_start;
    std::vector<int>& lower_row = built->lower_row;
    std::vector<int>& source = built->source;
    std::vector<int> inverse(n);
    for (int a = 0; a < n; ++a) inverse[permutation[a]] = a;
    const int* start = upper.outerIndexPtr();
    const int* rows = upper.innerIndexPtr();
    // Entry k of `upper` (row rows[k], column j) lands in column
    // min(inverse[rows[k]], inverse[j]) of the lower triangle, at row max.
    // Counted per column, scattered to its column (one pass each), then
    // each column's entries sorted by row, columns in parallel (a column
    // holds the few neighbours of one unknown).
    lower_column_start.assign(n + 1, 0);
    for (int j = 0; j < n; ++j)
      for (int k = start[j]; k < start[j + 1]; ++k) ++lower_column_start[std::min(inverse[rows[k]], inverse[j]) + 1];
    for (int j = 0; j < n; ++j) lower_column_start[j + 1] += lower_column_start[j];
    lower_row.resize(upper.nonZeros());
    source.resize(upper.nonZeros());
    std::vector<int> next(lower_column_start.begin(), lower_column_start.end() - 1);
    for (int j = 0; j < n; ++j)
      for (int k = start[j]; k < start[j + 1]; ++k) {
        const int a = inverse[rows[k]], b = inverse[j];
        const int p = next[std::min(a, b)]++;
        lower_row[p] = std::max(a, b);
        source[p] = k;
      }
    tbb::parallel_for(tbb::blocked_range<int>(0, n), [&](const tbb::blocked_range<int>& columns) {
      std::vector<std::pair<int, int>> column;
      for (int j = columns.begin(); j < columns.end(); ++j) {
        const int first = lower_column_start[j], end = lower_column_start[j + 1];
        column.clear();
        for (int p = first; p < end; ++p) column.emplace_back(lower_row[p], source[p]);
        std::sort(column.begin(), column.end());  // rows are distinct within a column
        for (int p = first; p < end; ++p) std::tie(lower_row[p], source[p]) = column[p - first];
      }
    });
    built->permutation = std::move(permutation);
    return built;
  }
};

std::string cholmod_version() {
  return std::to_string(CHOLMOD_MAIN_VERSION) + "." + std::to_string(CHOLMOD_SUB_VERSION) + "." +
         std::to_string(CHOLMOD_SUBSUB_VERSION);
}

SparseCholesky::SparseCholesky() : impl_(std::make_unique<Impl>()) {}
SparseCholesky::~SparseCholesky() = default;

bool SparseCholesky::analyzed() const { return impl_->factor != nullptr; }

bool SparseCholesky::supernodal() const { return analyzed() && impl_->factor->supernodal(); }

double SparseCholesky::factor_nonzeros() const { return analyzed() ? impl_->factor->nonzeros : 0; }

double SparseCholesky::factor_flops() const { return analyzed() ? impl_->factor->flops : 0; }

double SparseCholesky::factor_critical_path_share() {
  return analyzed() ? impl_->factor->factor_critical_path_share() : 1.0;
}

double SparseCholesky::solve_top_share(int threads) {
  return analyzed() ? impl_->factor->solve_top_share(threads) : 1.0;
}

double SparseCholesky::factor_bytes() const { return analyzed() ? impl_->factor->bytes() : 0; }

void SparseCholesky::clear() {
  impl_->factor.reset();
  impl_->pattern.reset();
}

void SparseCholesky::take_over(SparseCholesky* other) {
  std::swap(impl_, other->impl_);
  other->clear();
}

int SparseCholesky::index_bits() const { return analyzed() ? impl_->factor->index_bits() : 0; }

void SparseCholesky::use_64_bit_indices(bool on) { impl_->wide_indices = on; }

std::string SparseCholesky::ordering() const { return analyzed() ? impl_->ordering : ""; }

void SparseCholesky::always_try_metis(bool on) { impl_->always_try_metis = on; }

void SparseCholesky::use_cholmod_factorization(bool on) { impl_->by_cholmod = on; }


void SparseCholesky::use_cholmod_alone(bool on) {
  impl_->by_cholmod = on;
  impl_->cholmod_defaults = on;
}

namespace {

void check_analyzable(const Eigen::SparseMatrix<double>& upper, int block_size) {
  if (!upper.isCompressed() || upper.rows() != upper.cols())
    throw NumericalError("SparseCholesky: matrix must be square and compressed");
  if (block_size < 1 || upper.rows() % block_size != 0)
    throw NumericalError("SparseCholesky: block size must divide the matrix size");
}

}  // namespace

void SparseCholesky::analyze(const Eigen::SparseMatrix<double>& upper, int block_size, const BlockOrdering* order) {
  check_analyzable(upper, block_size);
  Impl& m = *impl_;
  m.factor.reset();
  const int blocks = static_cast<int>(upper.rows()) / block_size;
  if (order && static_cast<int>(order->permutation.size()) != blocks)
    throw NumericalError("SparseCholesky: the given ordering has " + std::to_string(order->permutation.size()) +
                         " blocks, the matrix " + std::to_string(blocks));

  // 1. The fill-reducing ordering, found on the graph of the blocks
  //    (vertices) and expanded to their unknowns (analyze_in_order): the same
  //    elimination order as on the scalar graph, at a fraction of the
  //    analysis time (solvers/fill_reducing_ordering.h). A given one is
  //    postordered on that graph unless it already is.
  if (order && order->postordered)
    m.analyze_in_order(upper, block_size, *order);
  else if (order)
    m.analyze_in_order(upper, block_size, postordered(Impl::block_graph(upper, block_size), *order));
  else
    m.analyze_in_order(upper, block_size,
                       fill_reducing_ordering(Impl::block_graph(upper, block_size), block_size, m.always_try_metis));
}

void SparseCholesky::Impl::analyze_in_order(const Eigen::SparseMatrix<double>& upper, int block_size,
                                            const BlockOrdering& block_ordering) {
  const int n = static_cast<int>(upper.rows());
  const int blocks = n / block_size;
  ordering = block_ordering.method;
  std::vector<int> permutation(n);
  for (int a = 0; a < blocks; ++a)
    for (int c = 0; c < block_size; ++c)
      permutation[a * block_size + c] = block_ordering.permutation[a] * block_size + c;

  // 2. The permuted matrix, analyzed again in its natural order (the
  //    postorder is already part of the permutation), with CHOLMOD's int
  //    indices while the factor's entries fit them and its 64-bit ones
  //    (cholmod_l_*) from 2^31 entries on (the same arithmetic: same bits).
  pattern = permuted_lower(upper, std::move(permutation));
  const double expected = expanded_flops_per_entry(block_ordering, block_size);
  if (!wide_indices) {
    factor = std::make_unique<CholmodFactor<int>>(cholmod_defaults);
    if (factor->analyze(pattern, expected)) return;
  }
  factor = std::make_unique<CholmodFactor<Long>>(cholmod_defaults);
  if (!factor->analyze(pattern, expected))
    throw NumericalError("CHOLMOD symbolic analysis failed: the factor is too large even for 64-bit indices");
}

void SparseCholesky::copy_analysis(const SparseCholesky& other) {
  const Impl& from = *other.impl_;
  if (!other.analyzed() || from.factor->factored())
    throw NumericalError("SparseCholesky::copy_analysis: the source must be analyzed and not factored");
  Impl& m = *impl_;
  m.factor = from.factor->copy_analysis();
  m.pattern = from.pattern;
  m.ordering = from.ordering;
}

void SparseCholesky::factorize(const Eigen::SparseMatrix<double>& upper) {
  if (!analyzed()) analyze(upper);
  Impl& m = *impl_;
  if (static_cast<std::size_t>(upper.nonZeros()) != m.pattern->source.size())
    throw NumericalError("SparseCholesky: the sparsity pattern changed since analyze()");
  m.factor->factorize(upper.valuePtr(), m.by_cholmod);
}

bool solve_positive_definite(const Eigen::SparseMatrix<double>& A, const Eigen::MatrixXd& B, Eigen::MatrixXd* X,
                             const BlockOrdering* order) {
  Eigen::SparseMatrix<double> upper = A.triangularView<Eigen::Upper>();
  upper.makeCompressed();
  SparseCholesky cholesky;
  cholesky.analyze(upper, 1, order);
  try {
    cholesky.factorize(upper);
  } catch (const NotPositiveDefinite&) {
    return false;
  }
  X->resize(B.rows(), B.cols());
  Eigen::VectorXd x;
  for (Eigen::Index c = 0; c < B.cols(); ++c) {
    cholesky.solve(B.col(c), &x);
    X->col(c) = x;
  }
  return true;
}

void SparseCholesky::round_factor_to_single() {
  if (!analyzed() || !impl_->factor->factored())
    throw NumericalError("SparseCholesky::round_factor_to_single called before factorize");
  impl_->factor->round_to_single();
}

bool SparseCholesky::factor_is_single() const { return analyzed() && impl_->factor->single(); }

void SparseCholesky::solve(const Eigen::VectorXd& b, Eigen::VectorXd* x) {
  if (!analyzed() || !impl_->factor->factored()) throw NumericalError("SparseCholesky::solve called before factorize");
  Impl& m = *impl_;
  const auto n = static_cast<size_t>(b.size());
  const std::vector<int>& permutation = m.pattern->permutation;
  if (n != permutation.size()) throw NumericalError("SparseCholesky::solve: right-hand side has the wrong size");
  m.permuted_rhs.resize(n);
  for (size_t a = 0; a < n; ++a) m.permuted_rhs[a] = b[permutation[a]];  // c = P b
  m.factor->solve(m.permuted_rhs.data());
  x->resize(b.size());
  for (size_t a = 0; a < n; ++a) (*x)[permutation[a]] = m.permuted_rhs[a];  // x = P^T z
}

}  // namespace akvf
