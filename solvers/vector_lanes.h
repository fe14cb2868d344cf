#pragma once
// Four doubles as one value (the vector extension of GCC and Clang), for
// the dense kernels of the supernodal factorization and solves: a function
// marked target_clones (dense_block_kernels.cpp, supernodal_block_solve.cpp)
// compiles it to SSE2 pairs for any x86-64 and to one AVX2 register for
// x86-64-v3.
namespace akvf {

typedef double Lanes __attribute__((vector_size(32)));

// Four doubles in memory at any double's address: packed (unaligned moves)
// and may alias the doubles, as the intrinsics' unaligned loads are written.
// Reached by reference, `lanes_at(p).value`, because a 32-byte vector
// passed or returned by value would have another ABI in the two clones.
struct [[gnu::packed, gnu::may_alias]] LanesInMemory {
  Lanes value;
};

[[gnu::always_inline]] inline const LanesInMemory& lanes_at(const double* p) {
  return *reinterpret_cast<const LanesInMemory*>(p);
}
[[gnu::always_inline]] inline LanesInMemory& lanes_at(double* p) { return *reinterpret_cast<LanesInMemory*>(p); }

// The four lanes' sum, in a fixed order.
[[gnu::always_inline]] inline double lane_sum(const Lanes& v) { return (v[0] + v[2]) + (v[1] + v[3]); }

}  // namespace akvf
