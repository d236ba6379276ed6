#pragma once
// An enum's spellings, written once in a table that the parser, the command line's choices,
// the messages and the docs all read: one spelling of each choice.
#include <array>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace impasto::util {

template <typename Enum>
struct EnumName {
  Enum value;
  std::string_view name;
};

template <typename Enum, std::size_t N>
using EnumNames = std::array<EnumName<Enum>, N>;

// The names in table order, e.g. for CLI::IsMember.
template <typename Enum, std::size_t N>
std::vector<std::string> names_of(const EnumNames<Enum, N>& names) {
  std::vector<std::string> out;
  for (const auto& entry : names) out.emplace_back(entry.name);
  return out;
}

// "a, b or c".
template <typename Enum, std::size_t N>
std::string names_text(const EnumNames<Enum, N>& names) {
  std::string text;
  for (std::size_t i = 0; i < N; ++i) {
    if (i > 0) text += i + 1 == N ? " or " : ", ";
    text += names[i].name;
  }
  return text;
}

// The value named `text`; throws std::runtime_error "unknown WHAT 'TEXT' (expected a, b or c)".
template <typename Enum, std::size_t N>
Enum parse_name(const EnumNames<Enum, N>& names, std::string_view text, std::string_view what) {
  for (const auto& entry : names) {
    if (entry.name == text) return entry.value;
  }
  throw std::runtime_error("unknown " + std::string(what) + " '" + std::string(text) +
                           "' (expected " + names_text(names) + ")");
}

// The name of `value`; throws std::logic_error for a value the table lacks.
template <typename Enum, std::size_t N>
std::string_view name_of(const EnumNames<Enum, N>& names, Enum value) {
  for (const auto& entry : names) {
    if (entry.value == value) return entry.name;
  }
  throw std::logic_error("a value without a name in its enum's table");
}

}  // namespace impasto::util
