#pragma once
// Thread settings for the native libraries under CHOLMOD, and huge pages for
// malloc, applied by re-executing the program once with them in its
// environment.
//
// Why: Debian 12's CHOLMOD is compiled to open an OpenMP region with 4
// threads for every supernode, and OpenBLAS's workers spin-wait with
// sched_yield between calls. On a 2-core machine the numeric factorization
// of K then spends most of its time in futex and sched_yield calls.
// Both libraries read their thread limits only when
// they are loaded, before main() runs, so the only way for the program to
// set them is its own environment at start-up: OMP_THREAD_LIMIT=1 and
// OPENBLAS_NUM_THREADS=1 (TBB keeps all cores for assembly).
//
// glibc reads GLIBC_TUNABLES at start-up too: glibc.malloc.hugetlb=1 has
// malloc advise its large blocks for transparent huge pages, so a run takes
// a page fault per 2 MiB instead of per 4 KiB of its arrays (horse_b, 40 000
// triangles: 12 800 faults in a run, 5 600 with it; a fault costs about
// 12 us on a paravirtualized VM: docs/notes/2026-11-30-page-faults.md).
//
// Values the user has set are kept; AKVF_NATIVE_RUNTIME=keep skips all of
// this.
#include <string>

namespace akvf {

// GLIBC_TUNABLES's value (nullptr: unset) with glibc.malloc.hugetlb=1
// appended, or unchanged where it already names that tunable.
std::string tunables_with_huge_page_malloc(const char* tunables);

// Call first thing in main(). Returns only if no re-execution was needed or
// it failed (then the program runs with the libraries' defaults).
void configure_native_runtime(char** argv);

}  // namespace akvf
