// libFuzzer target: the OBJ triangle-mesh reader, then disk validation of
// whatever it accepts (the path `akvf param mesh.obj` takes).
#include <sstream>

#include "framework/mesh_io.h"
#include "framework/mesh_validation.h"
#include "tests/fuzz/fuzz_text_input.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return akvf::fuzz::run_on_text(data, size, [](const std::string& text) {
    std::istringstream in(text);
    const akvf::TriMesh mesh = akvf::read_obj(in, "fuzz.obj");
    akvf::prepare_disk_mesh(mesh, "fuzz.obj");
  });
}
