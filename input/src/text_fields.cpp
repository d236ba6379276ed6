#include "text_fields.hpp"

#include <impasto/files/message_text.hpp>

#include <array>
#include <charconv>
#include <cmath>
#include <limits>

namespace impasto::input::detail {

namespace {

bool is_blank(char c) {
  return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f';
}

// Field text shown in messages, shortened and escaped so a binary file cannot flood the
// terminal (files::excerpt; a field is short, so 40 characters).
std::string shown(std::string_view text) {
  return files::excerpt(text, 40);
}

template <typename Number>
Number parse_floating(std::string_view text, const LineContext& where, const std::string& field) {
  Number value{};
  // from_chars rejects a leading '+', which other programs write.
  std::string_view digits = text;
  if (!digits.empty() && digits.front() == '+') digits.remove_prefix(1);
  const auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
  if (digits.empty() || error == std::errc::invalid_argument ||
      end != digits.data() + digits.size()) {
    where.fail(field, "expected a number, found " + shown(text));
  }
  if (error == std::errc::result_out_of_range) where.fail(field, shown(text) + " is out of range");
  if (!std::isfinite(value)) where.fail(field, shown(text) + " is not a finite number");
  return value;
}

}  // namespace

std::vector<std::string_view> split_fields(std::string_view line, const LineContext& where) {
  std::vector<std::string_view> fields;
  std::size_t i = 0;
  while (i < line.size()) {
    if (is_blank(line[i])) {
      ++i;
      continue;
    }
    if (line[i] == '#') break;
    const std::size_t start = i;
    if (line[i] == '"') {
      const std::size_t close = line.find('"', i + 1);
      if (close == std::string_view::npos) where.fail("", "unterminated quoted name");
      i = close + 1;
      if (i < line.size() && !is_blank(line[i]) && line[i] != '#') {
        where.fail("", "missing blank after quoted name");
      }
    } else {
      while (i < line.size() && !is_blank(line[i]) && line[i] != '#') ++i;
    }
    fields.push_back(line.substr(start, i - start));
  }
  return fields;
}

double parse_double(std::string_view text, const LineContext& where, const std::string& field) {
  return parse_floating<double>(text, where, field);
}

float parse_float(std::string_view text, const LineContext& where, const std::string& field) {
  return parse_floating<float>(text, where, field);
}

std::int64_t parse_integer(std::string_view text, const LineContext& where,
                           const std::string& field) {
  std::int64_t value = 0;
  std::string_view digits = text;
  if (!digits.empty() && digits.front() == '+') digits.remove_prefix(1);
  const auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
  if (digits.empty() || error == std::errc::invalid_argument ||
      end != digits.data() + digits.size()) {
    where.fail(field, "expected an integer, found " + shown(text));
  }
  if (error == std::errc::result_out_of_range) where.fail(field, shown(text) + " is out of range");
  return value;
}

std::string shortest(double value) {
  std::array<char, 32> buffer{};
  const auto result = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value);
  return std::string(buffer.data(), result.ptr);
}

std::string shortest(float value) {
  std::array<char, 32> buffer{};
  const auto result = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value);
  return std::string(buffer.data(), result.ptr);
}

bool is_quoted(std::string_view field) {
  return field.size() >= 2 && field.front() == '"' && field.back() == '"';
}

std::string_view unquote(std::string_view field) {
  return is_quoted(field) ? field.substr(1, field.size() - 2) : field;
}

}  // namespace impasto::input::detail
