// libFuzzer target: the .tet reader (`#num of vertex: N` headers), then tet validation.
#include "akvf/tet_mesh_io.h"
#include "tests/fuzz/fuzz_mesh_reader.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return akvf::fuzz::fuzz_tet_reader(data, size, akvf::read_tet_file, "fuzz.tet");
}
