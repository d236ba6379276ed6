#pragma once
// Small text helpers shared by the spectral CSV reader and writer.
#include <array>
#include <charconv>
#include <string>
#include <string_view>

namespace impasto::data::detail {

// s without leading and trailing blanks (spaces, tabs, carriage returns).
inline std::string_view trim(std::string_view s) {
  const auto first = s.find_first_not_of(" \t\r");
  if (first == std::string_view::npos) return {};
  const auto last = s.find_last_not_of(" \t\r");
  return s.substr(first, last - first + 1);
}

// The shortest decimal text that reads back as the same double.
inline std::string format_number(double value) {
  std::array<char, 32> buffer{};
  const auto result = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value);
  return std::string(buffer.data(), result.ptr);
}

}  // namespace impasto::data::detail
