#include "impasto/files/message_text.hpp"

#include <cstdio>

namespace impasto::files {

namespace {

// Appends c, a control character or a backslash escaped (\n, \t, \r, \\, \xNN).
void append_escaped(std::string& out, unsigned char c) {
  if (c == '\n') {
    out += "\\n";
  } else if (c == '\t') {
    out += "\\t";
  } else if (c == '\r') {
    out += "\\r";
  } else if (c == '\\') {
    out += "\\\\";
  } else if (c < 0x20 || c == 0x7f) {
    char hex[8];
    std::snprintf(hex, sizeof hex, "\\x%02x", c);
    out += hex;
  } else {
    out += static_cast<char>(c);
  }
}

}  // namespace

std::string excerpt(std::string_view text, std::size_t max_chars) {
  std::string out = "'";
  const std::size_t shown = std::min(text.size(), max_chars);
  for (std::size_t i = 0; i < shown; ++i) append_escaped(out, static_cast<unsigned char>(text[i]));
  out += "'";
  if (shown < text.size()) out += "... (" + std::to_string(text.size()) + " bytes)";
  return out;
}

std::string terminal_text(std::string_view text, bool keep_lines) {
  std::string out;
  out.reserve(text.size());
  for (const char ch : text) {
    const auto c = static_cast<unsigned char>(ch);
    if (c == '\\' || (keep_lines && (c == '\n' || c == '\t')) || (c >= 0x20 && c != 0x7f))
      out += ch;
    else
      append_escaped(out, c);
  }
  return out;
}

std::string describe_bytes(std::uint64_t bytes) {
  char text[48];
  if (bytes < 10000)
    std::snprintf(text, sizeof text, "%llu bytes", static_cast<unsigned long long>(bytes));
  else if (bytes < 10'000'000)
    std::snprintf(text, sizeof text, "%.1f kB", static_cast<double>(bytes) / 1e3);
  else if (bytes < 10'000'000'000ull)
    std::snprintf(text, sizeof text, "%.1f MB", static_cast<double>(bytes) / 1e6);
  else
    std::snprintf(text, sizeof text, "%.1f GB", static_cast<double>(bytes) / 1e9);
  return text;
}

}  // namespace impasto::files
