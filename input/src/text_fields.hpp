#pragma once
// Splitting a text line into fields and reading numbers from them, with errors that name the
// source, line and field. Shared by the stroke reader and the importers.
#include <impasto/input/stroke_error.hpp>

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace impasto::input::detail {

// Where a line came from, for error messages.
struct LineContext {
  const std::string& source;
  int line;

  [[noreturn]] void fail(const std::string& field, const std::string& problem) const {
    throw InputFormatError(source, line, field, problem);
  }
};

// Splits on blanks; a field in double quotes may contain blanks (no escapes). An unquoted
// '#' starts a comment that runs to the end of the line.
std::vector<std::string_view> split_fields(std::string_view line, const LineContext& where);

// A finite number filling the whole field (no NaN, no infinity).
double parse_double(std::string_view text, const LineContext& where, const std::string& field);
float parse_float(std::string_view text, const LineContext& where, const std::string& field);
std::int64_t parse_integer(std::string_view text, const LineContext& where,
                           const std::string& field);

// The shortest text that reads back as the same value.
std::string shortest(double value);
std::string shortest(float value);

// True for a field in double quotes.
bool is_quoted(std::string_view field);
std::string_view unquote(std::string_view field);

}  // namespace impasto::input::detail
