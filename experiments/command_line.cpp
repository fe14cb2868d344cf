#include "experiments/command_line.h"

#include <limits>
#include <sstream>

#include "framework/error.h"
#include "framework/text_reader.h"

namespace akvf {

CommandLine::CommandLine(std::string usage, std::vector<OptionSpec> specs)
    : usage_(std::move(usage)), specs_(std::move(specs)) {}

const OptionSpec* CommandLine::find(const std::string& name) const {
  for (const auto& spec : specs_)
    if (spec.name == name) return &spec;
  return nullptr;
}

void CommandLine::parse(const std::vector<std::string>& args) {
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& arg = args[i];
    if (arg.rfind("--", 0) != 0 || arg.size() == 2) {
      positional_.push_back(arg);
      continue;
    }
    std::string name = arg.substr(2), value;
    const auto equals = name.find('=');
    const bool inline_value = equals != std::string::npos;
    if (inline_value) {
      value = name.substr(equals + 1);
      name = name.substr(0, equals);
    }
    const OptionSpec* spec = find(name);
    if (!spec) throw OptionsError("unknown option --" + name + " (see --help)");
    if (spec->value_name.empty()) {
      if (inline_value) throw OptionsError("option --" + name + " takes no value");
    } else if (!inline_value) {
      if (i + 1 >= args.size()) throw OptionsError("option --" + name + " needs a value " + spec->value_name);
      value = args[++i];
    }
    values_[name] = value;
  }
}

std::string CommandLine::text(const std::string& name, const std::string& fallback) const {
  const auto it = values_.find(name);
  return it == values_.end() ? fallback : it->second;
}

double CommandLine::real(const std::string& name, double fallback) const {
  const auto it = values_.find(name);
  if (it == values_.end()) return fallback;
  double value = 0;
  if (!parse_real(it->second, &value))
    throw OptionsError("option --" + name + ": '" + it->second + "' is not a finite number");
  return value;
}

int CommandLine::integer(const std::string& name, int fallback) const {
  const auto it = values_.find(name);
  if (it == values_.end()) return fallback;
  long long value = 0;
  if (!parse_integer(it->second, &value) || value < std::numeric_limits<int>::min() ||
      value > std::numeric_limits<int>::max())
    throw OptionsError("option --" + name + ": '" + it->second + "' is not an integer");
  return static_cast<int>(value);
}

std::string CommandLine::help() const {
  std::ostringstream out;
  out << "usage: " << usage_ << "\n\noptions:\n";
  for (const auto& spec : specs_) {
    std::string left = "  --" + spec.name + (spec.value_name.empty() ? "" : " " + spec.value_name);
    if (left.size() < 26)
      left.resize(26, ' ');
    else
      left += "\n" + std::string(26, ' ');
    out << left << spec.help << '\n';
  }
  return out.str();
}

}  // namespace akvf
