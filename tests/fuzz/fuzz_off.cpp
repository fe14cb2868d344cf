// libFuzzer target: the OFF triangle-mesh reader, then disk validation (the path of `akvf param mesh.off`).
#include "akvf/mesh_io.h"
#include "tests/fuzz/fuzz_mesh_reader.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return akvf::fuzz::fuzz_triangle_reader(
      data, size,
      [](std::istream& in, const std::string& file_name) {
        akvf::Warnings warnings;  // the triangulation path too
        return akvf::read_off(in, file_name, &warnings);
      },
      "fuzz.off");
}
