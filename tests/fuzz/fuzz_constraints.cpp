// libFuzzer target: the positional-constraints reader (`index x y z` rows)
// for a mesh of 100 vertices, the count the seed corpus is written for.
#include <sstream>

#include "io/constraints_io.h"
#include "tests/fuzz/fuzz_text_input.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return akvf::fuzz::run_on_text(data, size, [](const std::string& text) {
    std::istringstream in(text);
    akvf::read_constraints(in, "fuzz.txt", 100);
  });
}
