#pragma once
// Text helpers for the line-based file readers.
#include <string>
#include <string_view>

namespace impasto::util {

// `text` without leading and trailing blanks (spaces, tabs, carriage returns: a CRLF file's
// lines read as an LF file's). A view into `text`.
std::string_view trim(std::string_view text);

// ASCII letters in lower case, every other byte as it is (file extensions, names compared
// without regard to case).
std::string ascii_lowercase(std::string_view text);
// The same text but for the case of its ASCII letters.
bool equal_ignoring_case(std::string_view a, std::string_view b);

// A number as printf's %g writes it with `digits` significant digits ("0.5", "1e+06").
std::string number_text(double value, int digits = 6);

// The value of the first "key = value" line of `text` whose key is `key` (both trimmed;
// empty lines, lines starting with '#' and lines without '=' skipped), or "" when none is.
std::string key_value_field(std::string_view text, std::string_view key);

// A name of any bytes on one line: its control characters (below 0x20, and 0x7f) and '%'
// written as %XX (two upper-case hex digits), every other byte as it is.
std::string line_encoded(std::string_view name);
// The name back from line_encoded's line. A '%' not followed by two hex digits stands for
// itself (a hand-edited or torn line decodes to what it says, and never throws).
std::string line_decoded(std::string_view line);

}  // namespace impasto::util
