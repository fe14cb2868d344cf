// libFuzzer target: the OBJ-like tet reader (`v x y z`, `f a b c d`, SLIM's data), then tet validation.
#include "akvf/tet_mesh_io.h"
#include "tests/fuzz/fuzz_mesh_reader.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return akvf::fuzz::fuzz_tet_reader(
      data, size,
      [](std::istream& in, const std::string& file_name) {
        akvf::Warnings warnings;  // the unknown-statement path too
        return akvf::read_tet_obj(in, file_name, &warnings);
      },
      "fuzz.obj");
}
