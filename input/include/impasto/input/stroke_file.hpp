#pragma once
// Reading and writing Impasto's own stroke files (docs/stroke-format.md).
#include <impasto/input/stroke_error.hpp>
#include <impasto/input/stroke_events.hpp>

#include <filesystem>
#include <iosfwd>
#include <string>

#include "impasto/input/append_only_file.hpp"

namespace impasto::input {

// Parses a stroke file from a stream; source_name is used in error messages.
// Throws InputFormatError naming the source, the line and the field. A last line without
// its newline is a torn write: it is skipped with a warning in StrokeFile::warnings (in a
// version 1 file only when it does not parse), and everything before it is kept.
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

// Appends events to a stroke file as they happen, each as one whole line written at once
// (a crash of the program loses nothing written; sync() makes it survive a power cut too).
// A write that fails (a full disk) stops the recording there: the file stays a readable
// prefix of the session and error() says why; the caller shows it.
class StrokeRecorder {
 public:
  // Creates the file, which must not exist yet (a symlink there is refused), and writes the
  // header line. Throws std::runtime_error naming the path when it cannot.
  explicit StrokeRecorder(const std::filesystem::path& path);

  // Records one event. False once the file cannot take it (error()). Throws
  // InputFormatError for an event that cannot be written exactly (NaN).
  bool record(const StrokeEvent& event);
  // Makes every record so far durable. False when it cannot (error()).
  bool sync() { return file_.sync(); }
  bool needs_sync() const { return file_.dirty(); }
  bool failed() const { return file_.failed(); }
  const std::string& error() const { return file_.error(); }
  const std::filesystem::path& path() const { return file_.path(); }
  std::size_t events_recorded() const { return count_; }

 private:
  AppendOnlyFile file_;
  std::size_t count_ = 0;
};

}  // namespace impasto::input
