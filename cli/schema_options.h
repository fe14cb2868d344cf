#pragma once
// The command line's side of the options schema (akvf/internal/option_schema.h):
// the flags and their --help lines, and the API options read from a parsed
// command line and checked, with messages that name the flag.
#include <string>
#include <vector>

#include "akvf/error.h"
#include "akvf/internal/option_schema.h"
#include "cli/command_line.h"

namespace akvf {

// One OptionSpec per field: --flag VALUE, help with the default.
template <class Options>
std::vector<OptionSpec> schema_option_specs(const std::vector<OptionField<Options>>& fields,
                                            const Options& defaults = {}) {
  std::vector<OptionSpec> specs;
  for (const auto& field : fields) {
    std::string help = field.help;
    if (field.kind != OptionKind::kSwitch) {
      const std::string value = field.format(defaults);
      help += " (default " + (value == "inf" ? std::string("none") : value) + ")";
    }
    specs.push_back({field.flag, field.value_name, help});
  }
  return specs;
}

// The options given on the command line over `defaults`, every field
// checked: OptionsError "option --exponent must be > 0, found -1", or
// "option --max-iters: 'x' is not an integer".
template <class Options>
Options schema_options_from(const CommandLine& cl, const std::vector<OptionField<Options>>& fields,
                            Options options = {}) {
  for (const auto& field : fields) {
    if (!cl.has(field.flag)) continue;
    try {
      field.parse(options, field.kind == OptionKind::kSwitch ? "true" : cl.text(field.flag, ""));
    } catch (const OptionsError& e) {
      throw OptionsError("option --" + field.flag + ": " + e.what());
    }
  }
  check_all(fields, options, [](const auto& field) { return "option --" + field.flag; });
  return options;
}

}  // namespace akvf
