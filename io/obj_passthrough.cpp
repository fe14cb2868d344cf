#include "akvf/obj_passthrough.h"

#include <filesystem>
#include <fstream>

#include "io/text_reader.h"

namespace akvf {

namespace fs = std::filesystem;

namespace {

// MTL statements whose last token names an image file.
bool names_texture_map(std::string_view statement) {
  return statement.substr(0, 4) == "map_" || statement == "bump" || statement == "disp" || statement == "decal" ||
         statement == "refl" || statement == "norm";
}

}  // namespace

std::vector<std::string> material_files(const std::string& obj_path, const ObjPassthrough& source) {
  std::vector<std::string> files;
  const fs::path folder = fs::path(obj_path).parent_path();
  for (const std::string& name : source.material_libraries) {
    const fs::path library = folder / name;
    files.push_back(library.string());
    std::ifstream in(library, std::ios::binary);
    if (!in) continue;  // a missing library names nothing further
    TextReader reader(in, library.string());
    try {
      while (reader.next_line())
        if (names_texture_map(reader.tokens()[0]) && reader.tokens().size() > 1)
          files.push_back((library.parent_path() / std::string(reader.tokens().back())).string());
    } catch (const std::exception&) {
      // A library that cannot be read to its end names what was read so far.
    }
  }
  return files;
}

}  // namespace akvf
