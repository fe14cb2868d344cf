// libFuzzer target: the OBJ triangle-mesh reader, then disk validation (the path of `akvf param mesh.obj`).
#include "framework/mesh_io.h"
#include "tests/fuzz/fuzz_mesh_reader.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return akvf::fuzz::fuzz_triangle_reader(data, size, akvf::read_obj, "fuzz.obj");
}
