#include "io/json_text.h"

#include <algorithm>
#include <vector>

#include "akvf/error.h"
#include "io/text_utilities.h"

namespace akvf {

namespace {

// Deeper than any manifest or summary, far shallower than a thread's stack.
constexpr int kMaxDepth = 256;

int line_of_offset(const std::string& text, std::size_t offset) {
  return 1 + static_cast<int>(std::count(text.begin(), text.begin() + std::min(offset, text.size()), '\n'));
}

}  // namespace

nlohmann::ordered_json parse_json_text(const std::string& text_as_read, const std::string& file_name) {
  using Json = nlohmann::ordered_json;
  const std::string text = text_as_read.rfind("\xEF\xBB\xBF", 0) == 0 ? text_as_read.substr(3) : text_as_read;
  // Keys seen in each open object, to refuse a key given twice (parsers
  // differ on which one wins); nesting beyond kMaxDepth is refused before it
  // can exhaust the stack.
  std::vector<std::vector<std::string>> keys;
  const Json::parser_callback_t check = [&](int depth, Json::parse_event_t event, Json& parsed) {
    if (depth > kMaxDepth)
      throw InputError(file_name + ": JSON nested deeper than " + std::to_string(kMaxDepth) + " levels");
    if (event == Json::parse_event_t::object_start) keys.emplace_back();
    if (event == Json::parse_event_t::object_end && !keys.empty()) keys.pop_back();
    if (event == Json::parse_event_t::key && !keys.empty()) {
      const std::string key = parsed.get<std::string>();
      if (std::find(keys.back().begin(), keys.back().end(), key) != keys.back().end())
        throw InputError(file_name + ": key \"" + key + "\" appears twice in one object (name each key once)");
      keys.back().push_back(key);
    }
    return true;
  };
  try {
    return Json::parse(text, check);
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
