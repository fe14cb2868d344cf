// libFuzzer target: the PLY reader (ASCII and binary), then disk validation (the path of `akvf param mesh.ply`).
#include "io/ply_reader.h"
#include "tests/fuzz/fuzz_mesh_reader.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return akvf::fuzz::fuzz_triangle_reader(
      data, size,
      [](std::istream& in, const std::string& name) {
        Eigen::MatrixXd uv, corner_uv;
        akvf::Warnings warnings;
        return akvf::read_ply(in, name, &uv, &corner_uv, &warnings);
      },
      "fuzz.ply");
}
