#include "framework/process/native_runtime.h"

#include <unistd.h>

#include <cstdlib>
#include <initializer_list>

namespace akvf {

void configure_native_runtime(char** argv) {
  if (std::getenv("AKVF_NATIVE_RUNTIME")) return;  // already re-executed, or the user opted out
  bool changed = false;
  for (const char* name : {"OMP_THREAD_LIMIT", "OPENBLAS_NUM_THREADS"}) {
    if (!std::getenv(name)) {
      setenv(name, "1", 1);
      changed = true;
    }
  }
  setenv("AKVF_NATIVE_RUNTIME", "configured", 1);
  if (changed) execv("/proc/self/exe", argv);
}

}  // namespace akvf
