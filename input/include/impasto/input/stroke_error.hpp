#pragma once
// The error thrown for a malformed stroke, descriptor or report file: it names the file, the
// line (1-based; 0 when the problem is not on one line) and, where known, the field.
#include <stdexcept>
#include <string>

namespace impasto::input {

class InputFormatError : public std::runtime_error {
 public:
  InputFormatError(std::string source, int line, std::string field, const std::string& problem);

  const std::string& source() const { return source_; }
  int line() const { return line_; }
  const std::string& field() const { return field_; }

 private:
  std::string source_;
  int line_;
  std::string field_;
};

}  // namespace impasto::input
