#pragma once
// Small text helpers shared by the spectral CSV reader and writer.
#include <array>
#include <charconv>
#include <string>
#include <string_view>

#include "impasto/util/text.hpp"

namespace impasto::data::detail {

using util::trim;

// The shortest decimal text that reads back as the same double.
inline std::string format_number(double value) {
  std::array<char, 32> buffer{};
  const auto result = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value);
  return std::string(buffer.data(), result.ptr);
}

}  // namespace impasto::data::detail
