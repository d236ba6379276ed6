#pragma once
// Text helpers for the line-based file readers.
#include <string>
#include <string_view>

namespace impasto::util {

// `text` without leading and trailing blanks (spaces, tabs, carriage returns: a CRLF file's
// lines read as an LF file's). A view into `text`.
std::string_view trim(std::string_view text);

// The value of the first "key = value" line of `text` whose key is `key` (both trimmed;
// empty lines, lines starting with '#' and lines without '=' skipped), or "" when none is.
std::string key_value_field(std::string_view text, std::string_view key);

}  // namespace impasto::util
