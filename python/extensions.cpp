#include "python/extensions.h"

#include <dlfcn.h>

#include <exception>
#include <filesystem>
#include <set>

#include "akvf/error.h"

namespace akvf::python {

namespace {

// This module's own file, made global so that libraries loaded later find
// akvf's symbols in it (Python loads extension modules RTLD_LOCAL).
void make_module_global() {
  Dl_info self{};
  if (!dladdr(reinterpret_cast<void*>(&make_module_global), &self) || !self.dli_fname)
    throw InputError("cannot locate the akvf module's own file to load extensions");
  if (!dlopen(self.dli_fname, RTLD_NOW | RTLD_NOLOAD | RTLD_GLOBAL))
    throw InputError(std::string("cannot make the akvf module global: ") + dlerror());
}

}  // namespace

void load_extension(const std::string& path) {
  static std::set<std::string> loaded;
  std::error_code error;
  const std::string canonical = std::filesystem::canonical(path, error).string();
  if (error) throw InputError(path + ": cannot load extension: " + error.message());
  if (loaded.count(canonical)) return;
  make_module_global();
  // Never closed: the registered factories live in it.
  void* library = dlopen(canonical.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (!library) throw InputError(path + ": cannot load extension: " + dlerror());
  using Register = void (*)();
  const auto register_parts = reinterpret_cast<Register>(dlsym(library, "akvf_register_extension"));
  if (!register_parts)
    throw InputError(path + ": not an akvf extension (no extern \"C\" void akvf_register_extension())");
  // What a registration throws becomes an akvf error naming the file (a
  // foreign type would reach Python as a bare RuntimeError).
  try {
    register_parts();
  } catch (const OptionsError& e) {
    throw OptionsError(path + ": the extension's registration failed: " + e.what());
  } catch (const std::exception& e) {
    throw InputError(path + ": the extension's registration failed: " + e.what());
  } catch (...) {
    throw InputError(path + ": the extension's registration failed with an exception that is not a std::exception");
  }
  loaded.insert(canonical);
}

}  // namespace akvf::python
