#pragma once
// The version of akvf. CMakeLists.txt reads it from here, so this is the one
// place it is written; `akvf --version`, the installed package's version
// file and the Python module's __version__ all come from it.
#define AKVF_VERSION_MAJOR 0
#define AKVF_VERSION_MINOR 2
#define AKVF_VERSION_PATCH 0

namespace akvf {

inline constexpr const char* kVersion = "0.2.0";

}  // namespace akvf
