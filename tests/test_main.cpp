#define DOCTEST_CONFIG_IMPLEMENT
#include <doctest/doctest.h>

#include "framework/process/native_runtime.h"

// The tests run with the same native thread settings as the akvf program.
int main(int argc, char** argv) {
  akvf::configure_native_runtime(argv);
  doctest::Context context(argc, argv);
  return context.run();
}
