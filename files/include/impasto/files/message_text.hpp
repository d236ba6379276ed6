#pragma once
// File content quoted in a message: cut to a readable length, control characters escaped, so
// a 60 MB CSV cell or escape codes in a pigment name never reach the terminal whole.
#include <cstdint>
#include <string>
#include <string_view>

namespace impasto::files {

inline constexpr std::size_t kQuotedChars = 100;

// 'text' in single quotes; bytes below 0x20 and 0x7f as \n, \t, \r or \xNN; a backslash as
// \\; longer text cut after max_chars with "... (N bytes)" after the closing quote.
std::string excerpt(std::string_view text, std::size_t max_chars = kQuotedChars);

// Text for a terminal or a list that holds one name a line: control characters escaped as
// in excerpt (an escape code in a pigment or file name cannot reach the terminal), except the
// line breaks and tabs a message itself is made of when keep_lines; not quoted, not cut.
std::string terminal_text(std::string_view text, bool keep_lines = false);

// "512 bytes", "3.1 MB", "2.0 GB": sizes in messages.
std::string describe_bytes(std::uint64_t bytes);

}  // namespace impasto::files
