#pragma once
// Reading and writing Impasto's own stroke files (docs/stroke-format.md).
#include <impasto/input/stroke_error.hpp>
#include <impasto/input/stroke_events.hpp>

#include <filesystem>
#include <fstream>
#include <iosfwd>
#include <string>

namespace impasto::input {

// Parses a stroke file from a stream; source_name is used in error messages.
// Throws InputFormatError naming the source, the line and the field.
StrokeFile parse_strokes(std::istream& in, const std::string& source_name);

// Reads a stroke file; throws InputFormatError (also when it cannot be opened).
StrokeFile read_stroke_file(const std::filesystem::path& path);

// Writes the header line and every event. Doubles and floats are written in their shortest
// round-trip form, so reading the output gives identical events.
void format_strokes(std::ostream& out, const StrokeFile& file);

// One event as one line of the format (without the newline).
std::string format_event(const StrokeEvent& event);

// Writes a stroke file; throws std::runtime_error naming the path when it cannot.
void write_stroke_file(const std::filesystem::path& path, const StrokeFile& file);

// Appends events to a stroke file as they happen. Every record is flushed at once, so a
// crash loses at most the record being written.
class StrokeRecorder {
 public:
  // Creates (truncates) the file and writes the header line.
  explicit StrokeRecorder(const std::filesystem::path& path);

  void record(const StrokeEvent& event);
  const std::filesystem::path& path() const { return path_; }
  std::size_t events_recorded() const { return count_; }

 private:
  std::filesystem::path path_;
  std::ofstream out_;
  std::size_t count_ = 0;
};

}  // namespace impasto::input
