#pragma once
// Text helpers for the line-based file readers.
#include <string_view>

namespace impasto::util {

// `text` without leading and trailing blanks (spaces, tabs, carriage returns: a CRLF file's
// lines read as an LF file's). A view into `text`.
std::string_view trim(std::string_view text);

}  // namespace impasto::util
