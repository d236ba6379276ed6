#include <impasto/input/stroke_error.hpp>

namespace impasto::input {

namespace {

std::string compose(const std::string& source, int line, const std::string& field,
                    const std::string& problem) {
  std::string message = source;
  if (line > 0) message += ":" + std::to_string(line);
  message += ": ";
  if (!field.empty()) message += "field '" + field + "': ";
  return message + problem;
}

}  // namespace

InputFormatError::InputFormatError(std::string source, int line, std::string field,
                                   const std::string& problem)
    : std::runtime_error(compose(source, line, field, problem)),
      source_(std::move(source)),
      line_(line),
      field_(std::move(field)) {}

}  // namespace impasto::input
