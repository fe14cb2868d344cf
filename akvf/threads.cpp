#include "akvf/threads.h"

#include <dlfcn.h>
#include <tbb/global_control.h>

namespace akvf {

struct ThreadLimit::Impl {
  std::unique_ptr<tbb::global_control> control;
};

ThreadLimit::ThreadLimit(int n) : impl_(std::make_unique<Impl>()) {
  if (n <= 0) return;
  impl_->control = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism, n);
  // OpenBLAS is reached through Debian's libblas alternative, so look its
  // setter up at run time rather than linking OpenBLAS by name; with another
  // BLAS the call is simply skipped.
  using SetThreads = void (*)(int);
  if (auto set = reinterpret_cast<SetThreads>(dlsym(RTLD_DEFAULT, "openblas_set_num_threads"))) set(n);
}

ThreadLimit::~ThreadLimit() = default;

}  // namespace akvf
