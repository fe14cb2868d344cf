#include "akvf/threads.h"

#include <dlfcn.h>
#include <tbb/global_control.h>

namespace akvf {

namespace {

// OpenBLAS and libgomp are reached through CHOLMOD (and Debian's libblas
// alternative), so their setters are looked up at run time rather than
// linked by name; with another BLAS or no OpenMP the calls are skipped.
template <class Function>
Function lookup(const char* name) {
  return reinterpret_cast<Function>(dlsym(RTLD_DEFAULT, name));
}

using GetInt = int (*)();
using SetInt = void (*)(int);

}  // namespace

struct ThreadLimit::Impl {
  std::unique_ptr<tbb::global_control> control;
  int openblas_threads = -1;  // to restore; -1 = not changed
  int omp_dynamic = -1;
};

ThreadLimit::ThreadLimit(int n) : impl_(std::make_unique<Impl>()) {
  if (n > 0) impl_->control = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism, n);
  // Measured on horse_b through the API (docs/performance.md): 0.90-1.10 s
  // with the libraries' defaults, 0.74 s with OPENBLAS_NUM_THREADS=1 and
  // OMP_THREAD_LIMIT=1 in the environment, about the same with these
  // in-process settings.
  const auto get_blas = lookup<GetInt>("openblas_get_num_threads");
  const auto set_blas = lookup<SetInt>("openblas_set_num_threads");
  if (get_blas && set_blas) {
    impl_->openblas_threads = get_blas();
    set_blas(1);
  }
  const auto get_dynamic = lookup<GetInt>("omp_get_dynamic");
  const auto set_dynamic = lookup<SetInt>("omp_set_dynamic");
  if (get_dynamic && set_dynamic) {
    impl_->omp_dynamic = get_dynamic();
    set_dynamic(1);
  }
}

ThreadLimit::~ThreadLimit() {
  if (impl_->openblas_threads > 0)
    if (const auto set_blas = lookup<SetInt>("openblas_set_num_threads")) set_blas(impl_->openblas_threads);
  if (impl_->omp_dynamic >= 0)
    if (const auto set_dynamic = lookup<SetInt>("omp_set_dynamic")) set_dynamic(impl_->omp_dynamic);
}

}  // namespace akvf
