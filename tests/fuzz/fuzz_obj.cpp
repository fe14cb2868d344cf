// libFuzzer target: the OBJ triangle-mesh reader, then disk validation (the path of `akvf param mesh.obj`).
#include "akvf/mesh_io.h"
#include "tests/fuzz/fuzz_mesh_reader.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return akvf::fuzz::fuzz_triangle_reader(
      data, size,
      [](std::istream& in, const std::string& file_name) {
        akvf::Warnings warnings;  // the unknown-statement and triangulation paths too
        akvf::ObjPassthrough passthrough;
        return akvf::read_obj(in, file_name, &warnings, nullptr, &passthrough);
      },
      "fuzz.obj");
}
