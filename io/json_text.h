#pragma once
// JSON documents read from files (manifests, run summaries), with errors
// that name the file and line.
#include <nlohmann/json.hpp>
#include <string>

namespace akvf {

// Parses `text` (read from file_name; a leading UTF-8 byte-order mark is
// skipped). InputError naming the file and line for invalid JSON or a number
// beyond double's range, naming the file for a key given twice in one object
// or nesting deeper than 256 levels.
nlohmann::ordered_json parse_json_text(const std::string& text, const std::string& file_name);

// The same for a file: read, then parsed (InputError if it cannot be read).
nlohmann::ordered_json read_json_file(const std::string& path);

}  // namespace akvf
