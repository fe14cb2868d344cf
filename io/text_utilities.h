#pragma once
// Small text helpers the report writers share.
#include <string>

namespace akvf {

// &, < and > as XML entities (SVG text).
std::string xml_escape(const std::string& text);

// "1 face", "2 faces", "1 vertex": n and the noun, plural unless n is 1
// (the plural adds an s unless given).
std::string count_of(long long n, const std::string& singular, const std::string& plural = "");

// The whole file as a string; InputError naming the file if it cannot be opened.
std::string read_text_file(const std::string& path);

}  // namespace akvf
