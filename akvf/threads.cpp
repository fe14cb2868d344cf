#include "akvf/threads.h"

#include <dlfcn.h>
#include <tbb/global_control.h>

#include <mutex>

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

namespace {

// The native settings are process-wide and the same for every run, so runs
// side by side share them: the first ThreadLimit alive sets them, the last
// one restores them (a run ending must not hand its neighbour a
// multi-threaded BLAS in the middle of a factorization).
std::mutex native_mutex;
int native_users = 0;
int saved_openblas_threads = -1;  // to restore; -1 = not changed
int saved_omp_dynamic = -1;

void acquire_native_settings() {
  const std::lock_guard<std::mutex> lock(native_mutex);
  if (native_users++ > 0) return;
  // Measured on horse_b through the API: 0.90-1.10 s
  // with the libraries' defaults, 0.74 s with OPENBLAS_NUM_THREADS=1 and
  // OMP_THREAD_LIMIT=1 in the environment, about the same with these
  // in-process settings.
  const auto get_blas = lookup<GetInt>("openblas_get_num_threads");
  const auto set_blas = lookup<SetInt>("openblas_set_num_threads");
  saved_openblas_threads = -1;
  if (get_blas && set_blas) {
    saved_openblas_threads = get_blas();
    set_blas(1);
  }
  const auto get_dynamic = lookup<GetInt>("omp_get_dynamic");
  const auto set_dynamic = lookup<SetInt>("omp_set_dynamic");
  saved_omp_dynamic = -1;
  if (get_dynamic && set_dynamic) {
    saved_omp_dynamic = get_dynamic();
    set_dynamic(1);
  }
}

void release_native_settings() {
  const std::lock_guard<std::mutex> lock(native_mutex);
  if (--native_users > 0) return;
  if (saved_openblas_threads > 0)
    if (const auto set_blas = lookup<SetInt>("openblas_set_num_threads")) set_blas(saved_openblas_threads);
  if (saved_omp_dynamic >= 0)
    if (const auto set_dynamic = lookup<SetInt>("omp_set_dynamic")) set_dynamic(saved_omp_dynamic);
}

}  // namespace

struct ThreadLimit::Impl {
  std::unique_ptr<tbb::global_control> control;
};

ThreadLimit::ThreadLimit(int n) : impl_(std::make_unique<Impl>()) {
  if (n > 0) impl_->control = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism, n);
  acquire_native_settings();
}

ThreadLimit::~ThreadLimit() { release_native_settings(); }

}  // namespace akvf
