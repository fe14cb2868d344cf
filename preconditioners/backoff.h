#pragma once
// Exponential backoff for an attempt that may fail (a reuse of the last
// factor, an exact Hessian that may not be positive definite): after a
// failure the next 1, 2, 4, ... chances to try are skipped, the count
// doubling with each failure since the last success, and a success resets it.

namespace akvf {

class Backoff {
 public:
  // Whether this chance is skipped; a skipped chance is used up.
  bool skip() {
    if (wait_ == 0) return false;
    --wait_;
    return true;
  }
  // The attempt failed: skip the next `next` chances, and twice as many
  // after the next failure.
  void failed() {
    wait_ = next_;
    next_ *= 2;
  }
  // The attempt served: the next failure skips one chance.
  void succeeded() { next_ = 1; }
  // Skips the next `chances` chances, the count for a failure unchanged.
  void skip_next(int chances) { wait_ = chances; }

 private:
  int wait_ = 0;  // chances still to skip
  int next_ = 1;  // chances the next failure skips
};

}  // namespace akvf
