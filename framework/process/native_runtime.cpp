#include "framework/process/native_runtime.h"

#include <unistd.h>

#include <cstdlib>
#include <initializer_list>

namespace akvf {

std::string tunables_with_huge_page_malloc(const char* tunables) {
  constexpr const char* kHugePageMalloc = "glibc.malloc.hugetlb";
  const std::string current = tunables ? tunables : "";
  if (current.find(kHugePageMalloc) != std::string::npos) return current;
  return (current.empty() ? current : current + ":") + kHugePageMalloc + "=1";
}

void configure_native_runtime(char** argv) {
  if (std::getenv("AKVF_NATIVE_RUNTIME")) return;  // already re-executed, or the user opted out
  bool changed = false;
  for (const char* name : {"OMP_THREAD_LIMIT", "OPENBLAS_NUM_THREADS"}) {
    if (!std::getenv(name)) {
      setenv(name, "1", 1);
      changed = true;
    }
  }
  const char* tunables = std::getenv("GLIBC_TUNABLES");
  const std::string wanted = tunables_with_huge_page_malloc(tunables);
  if (wanted != (tunables ? tunables : "")) {
    setenv("GLIBC_TUNABLES", wanted.c_str(), 1);
    changed = true;
  }
  setenv("AKVF_NATIVE_RUNTIME", "configured", 1);
  if (changed) execv("/proc/self/exe", argv);
}

}  // namespace akvf
