// libFuzzer target: the STL reader (ASCII and binary, welding), then disk validation (the path of `akvf param
// mesh.stl`).
#include "io/stl_reader.h"
#include "tests/fuzz/fuzz_mesh_reader.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return akvf::fuzz::fuzz_triangle_reader(data, size, akvf::read_stl, "fuzz.stl");
}
