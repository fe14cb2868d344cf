#pragma once
// One description of every option of a problem: its key (the field of
// ParameterizeOptions / DeformOptions, the manifest key, the Python keyword),
// its command-line flag, help text, how it is read from text and written
// back, its range check, the problems it applies to and whether it restarts
// the initial map. The command line (flags and --help), the
// experiment manifests, the API's is_valid(), Parameterizer::set_options'
// rule for recomputing the initial map, the Python keywords and the options
// reference (docs/options.md, `akvf list --options`) are all driven by it, so
// a new option is one entry here.
#include <functional>
#include <string>
#include <vector>

#include "akvf/deform.h"
#include "akvf/error.h"
#include "akvf/parameterize.h"

namespace akvf {

enum class OptionKind {
  kText,     // a name or word
  kNumber,   // a finite real number (or "inf" for a time limit)
  kInteger,  // an int
  kSwitch,   // a flag without value on the command line; true/false elsewhere
};

// The problems an option applies to.
enum class OptionScope {
  kParam,   // akvf param, ParameterizeOptions
  kDeform,  // akvf deform, DeformOptions
  kBoth,    // both, with the same meaning (one definition: add_common_fields)
};

template <class Options>
struct OptionField {
  std::string key;         // "grad_tol"
  std::string flag;        // "grad-tol" (used as --grad-tol)
  std::string value_name;  // "X" on the command line ("" for a switch)
  OptionKind kind;
  std::string help;
  // Reads the text of a value into the field (OptionsError naming the key
  // when it is not of the kind); for a switch "true" or "false".
  std::function<void(Options&, const std::string&)> parse;
  // The field as text (for records and the reference's defaults).
  std::function<std::string(const Options&)> format;
  // Range or name check of the field's value: OptionsError "NAME must be
  // > 0, found -1" for a range (NAME is how the caller names the option,
  // "" for none), or the registry's "unknown energy 'x' (valid: ...)".
  std::function<void(const Options&, const std::string& name)> check;
  // Changing it recomputes the initial map of a Parameterizer
  // (Parameterizer::set_options compares these fields only).
  bool recomputes_start = false;
  OptionScope scope = OptionScope::kBoth;
};

const std::vector<OptionField<ParameterizeOptions>>& parameterize_option_fields();
const std::vector<OptionField<DeformOptions>>& deform_option_fields();

// Runs every field's check (the one place of each range check); a range
// error names the option as name_of(field) does.
template <class Options, class NameOf>
void check_all(const std::vector<OptionField<Options>>& fields, const Options& options, NameOf name_of) {
  for (const auto& field : fields) field.check(options, name_of(field));
}

// Sets the field `key` of *options from its text, as the command line and
// the manifests read it (the field's OptionsError for bad text).
template <class Options>
void set_option_text(const std::vector<OptionField<Options>>& fields, const std::string& key, const std::string& text,
                     Options* options) {
  for (const auto& field : fields)
    if (field.key == key) return field.parse(*options, text);
  throw OptionsError("unknown option '" + key + "'");
}

// The options reference in Markdown, one table per problem (docs/options.md).
std::string options_reference_markdown();

}  // namespace akvf
