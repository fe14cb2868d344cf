#pragma once
// A small command-line parser: `--name value` and `--flag` options plus
// positional arguments, with generated --help text. `-h` and `-q` stand for
// --help and --quiet where a command has them. Unknown options and bad values
// throw OptionsError naming the option.
#include <map>
#include <string>
#include <vector>

namespace akvf {

struct OptionSpec {
  std::string name;        // without the leading dashes
  std::string value_name;  // empty for a flag
  std::string help;
};

class CommandLine {
 public:
  CommandLine(std::string usage, std::vector<OptionSpec> specs);

  void parse(const std::vector<std::string>& args);

  bool has(const std::string& name) const { return values_.count(name) > 0; }
  std::string text(const std::string& name, const std::string& fallback) const;
  double real(const std::string& name, double fallback) const;
  int integer(const std::string& name, int fallback) const;
  // --threads N: 0 (the default) = all cores; negative is an error.
  int thread_count() const;
  const std::vector<std::string>& positional() const { return positional_; }

  std::string help() const;

 private:
  const OptionSpec* find(const std::string& name) const;

  std::string usage_;
  std::vector<OptionSpec> specs_;
  std::map<std::string, std::string> values_;
  std::vector<std::string> positional_;
};

}  // namespace akvf
