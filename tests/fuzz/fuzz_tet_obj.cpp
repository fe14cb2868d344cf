// libFuzzer target: the OBJ-like tet reader (`v x y z`, `f a b c d`, SLIM's
// data format), then tet validation of whatever it accepts.
#include <sstream>

#include "framework/tet_mesh_io.h"
#include "framework/tet_validation.h"
#include "tests/fuzz/fuzz_text_input.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return akvf::fuzz::run_on_text(data, size, [](const std::string& text) {
    std::istringstream in(text);
    const akvf::TetMesh mesh = akvf::read_tet_obj(in, "fuzz.obj");
    akvf::Warnings warnings;
    akvf::prepare_tet_mesh(mesh, "fuzz.obj", &warnings);
  });
}
