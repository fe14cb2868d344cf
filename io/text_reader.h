#pragma once
// Line-by-line tokenizer shared by the mesh readers: strips '#' comments,
// splits on white space, and parses numbers with errors that name the file
// and line.
#include <istream>
#include <string>
#include <string_view>
#include <vector>

namespace akvf {

class TextReader {
 public:
  // lines_already_read: lines of `in` consumed before, for the line numbers;
  // when 0, a leading UTF-8 byte-order mark is skipped. continue_lines: a
  // line ending in '\\' goes on on the next line (OBJ); messages name the
  // line where the statement starts.
  TextReader(std::istream& in, std::string file_name, long lines_already_read = 0, bool continue_lines = false);

  // Advances to the next line that has at least one token. Returns false at
  // the end of the input.
  bool next_line();

  const std::vector<std::string_view>& tokens() const { return tokens_; }
  long line_number() const { return line_number_; }
  // The current line as read (comment and trailing '\r' included).
  const std::string& line() const { return line_; }
  const std::string& file_name() const { return file_name_; }

  // Parsers for token i of the current line; they throw InputError naming
  // the line and the offending text.
  double real(std::size_t i, const char* what) const;
  long long integer(std::size_t i, const char* what) const;

  [[noreturn]] void fail(const std::string& problem) const;

 private:
  std::istream& in_;
  std::string file_name_;
  std::string line_;
  std::vector<std::string_view> tokens_;
  long line_number_ = 0;
  bool continue_lines_ = false;
  long pending_lines_ = 0;  // continuation lines of the current statement, counted at the next
};

// Consumes a UTF-8 byte-order mark at the current position of `in`, if there
// is one (editors on Windows write it; it is not part of the first token).
void skip_utf8_bom(std::istream& in);

// Parses a whole token as a finite double / integer; returns false otherwise.
bool parse_real(std::string_view token, double* value);
bool parse_integer(std::string_view token, long long* value);

}  // namespace akvf
