#include "io/text_reader.h"

#include <charconv>
#include <cmath>

#include "akvf/error.h"

namespace akvf {

TextReader::TextReader(std::istream& in, std::string file_name, long lines_already_read, bool continue_lines)
    : in_(in), file_name_(std::move(file_name)), line_number_(lines_already_read), continue_lines_(continue_lines) {
  if (lines_already_read == 0) skip_utf8_bom(in_);
}

void skip_utf8_bom(std::istream& in) {
  static constexpr unsigned char kBom[3] = {0xEF, 0xBB, 0xBF};
  for (int i = 0; i < 3; ++i) {
    if (in.peek() != kBom[i]) {
      // Not a mark: put back what was taken (at most two bytes).
      for (int k = 0; k < i; ++k) in.unget();
      return;
    }
    in.get();
  }
}

bool TextReader::next_line() {
  line_number_ += pending_lines_;  // the continuation lines of the last statement
  pending_lines_ = 0;
  while (std::getline(in_, line_)) {
    ++line_number_;
    long joined = 0;  // continuation lines read into this one
    for (std::string more; continue_lines_;) {
      const std::size_t end = line_.find_last_not_of(" \t\r");
      if (end == std::string::npos || line_[end] != '\\' || !std::getline(in_, more)) break;
      line_.resize(end);
      line_ += ' ' + more;
      ++joined;
    }
    tokens_.clear();
    std::string_view rest(line_);
    if (auto hash = rest.find('#'); hash != std::string_view::npos) rest = rest.substr(0, hash);
    std::size_t pos = 0;
    while (pos < rest.size()) {
      while (pos < rest.size() && std::isspace(static_cast<unsigned char>(rest[pos]))) ++pos;
      std::size_t end = pos;
      while (end < rest.size() && !std::isspace(static_cast<unsigned char>(rest[end]))) ++end;
      if (end > pos) tokens_.push_back(rest.substr(pos, end - pos));
      pos = end;
    }
    if (!tokens_.empty()) {
      pending_lines_ = joined;
      return true;
    }
    line_number_ += joined;
  }
  if (in_.bad()) throw InputError(file_name_, line_number_, "read error");
  return false;
}

void TextReader::fail(const std::string& problem) const { throw InputError(file_name_, line_number_, problem); }

double TextReader::real(std::size_t i, const char* what) const {
  if (i >= tokens_.size()) fail(std::string("missing ") + what);
  double value = 0;
  if (!parse_real(tokens_[i], &value))
    fail(std::string(what) + " '" + std::string(tokens_[i]) + "' is not a finite number");
  return value;
}

long long TextReader::integer(std::size_t i, const char* what) const {
  if (i >= tokens_.size()) fail(std::string("missing ") + what);
  long long value = 0;
  if (!parse_integer(tokens_[i], &value))
    fail(std::string(what) + " '" + std::string(tokens_[i]) + "' is not an integer");
  return value;
}

bool parse_real(std::string_view token, double* value) {
  const char* first = token.data();
  const char* last = first + token.size();
  if (first != last && *first == '+') ++first;  // from_chars rejects a leading '+'
  auto [ptr, ec] = std::from_chars(first, last, *value);
  return ec == std::errc() && ptr == last && std::isfinite(*value);
}

bool parse_integer(std::string_view token, long long* value) {
  const char* first = token.data();
  const char* last = first + token.size();
  if (first != last && *first == '+') ++first;
  auto [ptr, ec] = std::from_chars(first, last, *value);
  return ec == std::errc() && ptr == last;
}

}  // namespace akvf
