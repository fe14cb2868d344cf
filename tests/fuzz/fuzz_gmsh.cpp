// libFuzzer target: the gmsh .msh reader (2.2 and 4.1 ASCII), then tet validation (the path of `akvf deform mesh.msh`).
#include "io/gmsh_reader.h"
#include "tests/fuzz/fuzz_mesh_reader.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return akvf::fuzz::fuzz_tet_reader(data, size, akvf::read_gmsh, "fuzz.msh");
}
