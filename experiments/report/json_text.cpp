#include "experiments/report/json_text.h"

#include <algorithm>

#include "experiments/report/text_utilities.h"
#include "framework/process/error.h"

namespace akvf {

namespace {

int line_of_offset(const std::string& text, std::size_t offset) {
  return 1 + static_cast<int>(std::count(text.begin(), text.begin() + std::min(offset, text.size()), '\n'));
}

}  // namespace

nlohmann::ordered_json parse_json_text(const std::string& text_as_read, const std::string& file_name) {
  using Json = nlohmann::ordered_json;
  const std::string text = text_as_read.rfind("\xEF\xBB\xBF", 0) == 0 ? text_as_read.substr(3) : text_as_read;
  try {
    return Json::parse(text);
  } catch (const Json::parse_error& e) {
    // e.byte is 1-based, pointing at the first character that did not fit.
    throw InputError(file_name, line_of_offset(text, e.byte == 0 ? 0 : e.byte - 1),
                     std::string("invalid JSON: ") + e.what());
  } catch (const Json::out_of_range& e) {
    // A number beyond double's range (found by fuzzing): nlohmann names the
    // literal but not its place, so the line is that of its first occurrence.
    const std::string what = e.what();
    const auto open = what.find('\''), close = what.rfind('\'');
    const std::string literal = open < close ? what.substr(open + 1, close - open - 1) : "";
    const std::size_t at = literal.empty() ? std::string::npos : text.find(literal);
    const std::string problem = "invalid JSON: number " + literal + " is out of range";
    if (at == std::string::npos) throw InputError(file_name + ": " + problem);
    throw InputError(file_name, line_of_offset(text, at), problem);
  }
}

nlohmann::ordered_json read_json_file(const std::string& path) { return parse_json_text(read_text_file(path), path); }

}  // namespace akvf
