#include "cli/command_line.h"

#include <cmath>
#include <limits>
#include <sstream>

#include "akvf/error.h"
#include "io/text_reader.h"

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
    std::string arg = args[i];
    // The usual one-letter aliases, where the command has the long option.
    if (arg == "-h" && find("help")) arg = "--help";
    if (arg == "-q" && find("quiet")) arg = "--quiet";
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
  double real_value = 0;
  const bool is_integer = parse_integer(it->second, &value);
  if (!is_integer && parse_real(it->second, &real_value) && real_value == std::floor(real_value))
    throw OptionsError("option --" + name + ": " + it->second + " is out of range (at most " +
                       std::to_string(std::numeric_limits<int>::max()) + ")");
  if (!is_integer) throw OptionsError("option --" + name + ": '" + it->second + "' is not an integer");
  if (value < std::numeric_limits<int>::min() || value > std::numeric_limits<int>::max())
    throw OptionsError("option --" + name + ": " + it->second + " is out of range (" +
                       std::to_string(std::numeric_limits<int>::min()) + " to " +
                       std::to_string(std::numeric_limits<int>::max()) + ")");
  return static_cast<int>(value);
}

int CommandLine::thread_count() const {
  const int n = integer("threads", 0);
  if (n < 0) throw OptionsError("option --threads must be >= 0 (0 = all cores), found " + std::to_string(n));
  return n;
}

namespace {

// `text` in lines of at most `width` characters (words are not split), the
// lines after the first indented by `indent` spaces.
std::string wrapped(const std::string& text, std::size_t indent, std::size_t width) {
  std::istringstream words(text);
  std::string out, line, word;
  while (words >> word) {
    if (!line.empty() && indent + line.size() + 1 + word.size() > width) {
      out += line + "\n" + std::string(indent, ' ');
      line.clear();
    }
    line += (line.empty() ? "" : " ") + word;
  }
  return out + line;
}

}  // namespace

std::string CommandLine::help() const {
  std::ostringstream out;
  out << "usage: " << usage_ << "\n\noptions:\n";
  for (const auto& spec : specs_) {
    std::string left = "  --" + spec.name + (spec.value_name.empty() ? "" : " " + spec.value_name);
    if (left.size() < 26)
      left.resize(26, ' ');
    else
      left += "\n" + std::string(26, ' ');
    out << left << wrapped(spec.help, 26, 100) << '\n';
  }
  return out.str();
}

}  // namespace akvf
