#pragma once
// Thread settings for the native libraries under CHOLMOD, applied by
// re-executing the program once with them in its environment.
//
// Why: Debian 12's CHOLMOD is compiled to open an OpenMP region with 4
// threads for every supernode, and OpenBLAS's workers spin-wait with
// sched_yield between calls. On a 2-core machine the numeric factorization
// of K then spends most of its time in futex and sched_yield calls.
// Both libraries read their thread limits only when
// they are loaded, before main() runs, so the only way for the program to
// set them is its own environment at start-up: OMP_THREAD_LIMIT=1 and
// OPENBLAS_NUM_THREADS=1 (TBB keeps all cores for assembly). Values the
// user has set are kept; AKVF_NATIVE_RUNTIME=keep skips all of this.
namespace akvf {

// Call first thing in main(). Returns only if no re-execution was needed or
// it failed (then the program runs with the libraries' defaults).
void configure_native_runtime(char** argv);

}  // namespace akvf
