#pragma once
// Fuzz bodies for the mesh readers: read the text as a file named
// `file_name`, then validate what the reader accepts as the program would
// (disk validation with the repair of `akvf param`, tet validation for
// `akvf deform`).
#include <sstream>

#include "framework/mesh/mesh_validation.h"
#include "framework/mesh/tet_validation.h"
#include "tests/fuzz/fuzz_text_input.h"

namespace akvf::fuzz {

// read: TriMesh(std::istream&, const std::string& file_name)
template <class Reader>
int fuzz_triangle_reader(const std::uint8_t* data, std::size_t size, Reader read, const char* file_name) {
  return run_on_text(data, size, [&](const std::string& text) {
    std::istringstream in(text);
    prepare_disk_mesh(read(in, file_name), file_name, false, true);
  });
}

// read: TetMesh(std::istream&, const std::string& file_name)
template <class Reader>
int fuzz_tet_reader(const std::uint8_t* data, std::size_t size, Reader read, const char* file_name) {
  return run_on_text(data, size, [&](const std::string& text) {
    std::istringstream in(text);
    Warnings warnings;
    prepare_tet_mesh(read(in, file_name), file_name, &warnings);
  });
}

}  // namespace akvf::fuzz
