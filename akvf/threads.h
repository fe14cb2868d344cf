#pragma once
// Limits the worker threads of TBB (assembly) and OpenBLAS (CHOLMOD's dense
// kernels) for the lifetime of the returned object.
#include <memory>

namespace akvf {

class ThreadLimit {
 public:
  // n <= 0 keeps the libraries' defaults (all cores).
  explicit ThreadLimit(int n);
  ~ThreadLimit();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace akvf
