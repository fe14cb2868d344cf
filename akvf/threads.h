#pragma once
// The threads of a run, for the lifetime of the object: TBB (assembly, line
// search) limited to n, and the native libraries under CHOLMOD set in-process
// to what their environment variables give the `akvf` program
// (docs/design.md, "Native runtime"): OpenBLAS single-threaded, and OpenMP's
// dynamic adjustment on, so that Debian's CHOLMOD does not start a 4-thread
// team per supernode on a 2-core machine. Both are restored when the last
// ThreadLimit alive ends, so runs side by side in one process keep them.
#include <memory>

namespace akvf {

class ThreadLimit {
 public:
  // n <= 0 keeps TBB's default (all cores).
  explicit ThreadLimit(int n);
  ~ThreadLimit();
  ThreadLimit(const ThreadLimit&) = delete;
  ThreadLimit& operator=(const ThreadLimit&) = delete;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace akvf
