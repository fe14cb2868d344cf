#pragma once
// Energies, preconditioners and line searches of one's own, compiled in C++
// and registered into the module's registries at run time:
// akvf.load_extension("libmine.so"). The module holds akvf's libraries; an
// extension is a shared library built against the headers alone
// (akvf::headers, no copy of the libraries, so there is one set of
// registries) that defines
//   extern "C" void akvf_register_extension();
// and registers its parts there (akvf/extend.h). Its references to the
// library resolve to the module's: the module is made global first.
#include <string>

namespace akvf::python {

// Loads the extension (once per path) and calls its registration function.
// InputError naming the file when it cannot be loaded, lacks the function or
// its registration throws; OptionsError naming it when a registration is
// refused (a name already taken).
void load_extension(const std::string& path);

}  // namespace akvf::python
