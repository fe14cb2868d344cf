// libFuzzer target: the MEDIT .mesh tet reader, then tet validation (the path of `akvf deform mesh.mesh`).
#include "akvf/tet_mesh_io.h"
#include "tests/fuzz/fuzz_mesh_reader.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return akvf::fuzz::fuzz_tet_reader(data, size, akvf::read_medit, "fuzz.mesh");
}
