#include "framework/process/physical_memory.h"

#include <unistd.h>

namespace akvf {

double physical_memory_bytes() {
  return static_cast<double>(sysconf(_SC_PHYS_PAGES)) * static_cast<double>(sysconf(_SC_PAGE_SIZE));
}

}  // namespace akvf
