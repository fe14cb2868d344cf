#pragma once
// Four doubles as one value (the vector extension of GCC and Clang), for
// the dense kernels of the supernodal factorization and solves
// (dense_block_kernels.cpp, supernodal_block_solve.cpp). A kernel marked
// AKVF_FOR_EACH_X86_LEVEL is compiled for any x86-64 (the vector as SSE2
// pairs) and for x86-64-v3 (one AVX2 register, FMA), and the loader picks
// the version the processor runs; on other processors it is compiled once.
#if defined(__x86_64__)
#define AKVF_FOR_EACH_X86_LEVEL [[gnu::target_clones("arch=x86-64-v3", "default")]]
#else
#define AKVF_FOR_EACH_X86_LEVEL
#endif

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

// Four floats in memory at any float's address, likewise (widened to Lanes
// by __builtin_convertvector).
typedef float FloatLanes __attribute__((vector_size(16)));
struct [[gnu::packed, gnu::may_alias]] FloatLanesInMemory {
  FloatLanes value;
};
[[gnu::always_inline]] inline const FloatLanesInMemory& floats_at(const float* p) {
  return *reinterpret_cast<const FloatLanesInMemory*>(p);
}

// The four lanes' sum, in a fixed order.
[[gnu::always_inline]] inline double lane_sum(const Lanes& v) { return (v[0] + v[2]) + (v[1] + v[3]); }

}  // namespace akvf
