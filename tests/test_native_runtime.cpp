// The programs' start-up environment (framework/process/native_runtime.h).
#include <doctest/doctest.h>

#include <cstdlib>
#include <string>

#include "framework/process/native_runtime.h"

TEST_CASE("the programs ask glibc's malloc for huge pages and keep the user's tunables") {
  CHECK(akvf::tunables_with_huge_page_malloc(nullptr) == "glibc.malloc.hugetlb=1");
  CHECK(akvf::tunables_with_huge_page_malloc("") == "glibc.malloc.hugetlb=1");
  CHECK(akvf::tunables_with_huge_page_malloc("glibc.malloc.arena_max=2") ==
        "glibc.malloc.arena_max=2:glibc.malloc.hugetlb=1");
  CHECK(akvf::tunables_with_huge_page_malloc("glibc.malloc.hugetlb=0") == "glibc.malloc.hugetlb=0");
  // This binary ran configure_native_runtime() first: unless the user opted
  // out (AKVF_NATIVE_RUNTIME=keep), it now runs with the tunable.
  const char* runtime = std::getenv("AKVF_NATIVE_RUNTIME");
  if (runtime && std::string(runtime) == "configured") {
    const char* tunables = std::getenv("GLIBC_TUNABLES");
    REQUIRE(tunables != nullptr);
    CHECK(std::string(tunables).find("glibc.malloc.hugetlb") != std::string::npos);
  }
}
