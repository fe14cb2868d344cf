#pragma once
// Small text helpers the report writers share.
#include <string>

namespace akvf {

// &, < and > as XML entities (SVG text).
std::string xml_escape(const std::string& text);

// The whole file as a string; InputError naming the file if it cannot be opened.
std::string read_text_file(const std::string& path);

}  // namespace akvf
