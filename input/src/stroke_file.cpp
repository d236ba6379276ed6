#include <impasto/input/stroke_file.hpp>

#include <fstream>
#include <istream>
#include <ostream>
#include <sstream>

#include "impasto/files/atomic_file.hpp"
#include "impasto/paintcore/brush_head.hpp"
#include "recording_input.hpp"
#include "stroke_record.hpp"
#include "text_fields.hpp"

namespace impasto::input {

namespace {

constexpr std::string_view kMagic = "impasto-strokes";

void parse_header(const std::string& line, const detail::LineContext& where, StrokeFile& file) {
  const auto fields = detail::split_fields(line, where);
  if (fields.size() != 2 || fields[0] != kMagic) {
    where.fail("", "not an Impasto stroke file (the first line must be 'impasto-strokes " +
                       std::to_string(kStrokeFormatVersion) + "')");
  }
  file.version = static_cast<int>(detail::parse_integer(fields[1], where, "version"));
  if (file.version < kOldestStrokeFormatVersion || file.version > kStrokeFormatVersion) {
    where.fail("version", "unsupported version " + std::string(fields[1]) +
                              " (this program reads versions " +
                              std::to_string(kOldestStrokeFormatVersion) + " to " +
                              std::to_string(kStrokeFormatVersion) + ")");
  }
}

// Rules that span lines: one canvas record and one origin before the first sample, time
// never goes back.
class SessionChecks {
 public:
  void check(const StrokeEvent& event, const detail::LineContext& where) {
    if (std::holds_alternative<OriginEvent>(event)) {
      if (seen_origin_) where.fail("", "a second 'from' record");
      if (seen_sample_) where.fail("", "'from' must come before the first pen sample");
      seen_origin_ = true;
    } else if (std::holds_alternative<CanvasEvent>(event)) {
      if (seen_canvas_) where.fail("", "a second 'canvas' record");
      if (seen_sample_) where.fail("", "'canvas' must come before the first pen sample");
      seen_canvas_ = true;
    } else if (const auto* pen = std::get_if<SampleEvent>(&event)) {
      if (seen_sample_ && pen->sample.time_s < last_time_s_) {
        where.fail("time", "time goes backwards (" + detail::shortest(pen->sample.time_s) +
                               " s after " + detail::shortest(last_time_s_) + " s)");
      }
      seen_sample_ = true;
      last_time_s_ = pen->sample.time_s;
    }
  }

 private:
  bool seen_canvas_ = false;
  bool seen_origin_ = false;
  bool seen_sample_ = false;
  double last_time_s_ = 0.0;
};

}  // namespace

StrokeFile parse_strokes(std::istream& in, const std::string& source_name) {
  StrokeFile file;
  file.source = source_name;
  std::string line;
  int line_number = 0;
  if (!std::getline(in, line)) throw InputFormatError(source_name, 1, "", "empty file");
  ++line_number;
  parse_header(line, {source_name, line_number}, file);
  SessionChecks checks;
  while (std::getline(in, line)) {
    ++line_number;
    const detail::LineContext where{source_name, line_number};
    // getline reached the end of the input without a newline: the last write was torn.
    const bool torn = in.eof() && !line.empty();
    const auto skip_torn = [&] {
      file.warnings.push_back(source_name + ":" + std::to_string(line_number) +
                              ": the last line is cut short (no newline: a torn write); "
                              "skipped, everything before it is kept");
    };
    if (torn && file.version >= 2) {
      skip_torn();
      break;
    }
    StrokeEvent event;
    try {
      const auto fields = detail::split_fields(line, where);
      if (fields.empty()) continue;  // blank or comment
      event = detail::parse_record(fields, where);
      checks.check(event, where);
    } catch (const InputFormatError&) {
      if (!torn) throw;
      skip_torn();
      break;
    }
    if (const auto* brush = std::get_if<BrushEvent>(&event))
      for (const BrushParam& param : brush->params)
        if (!paintcore::find_bristle_setting(param.key))
          file.warnings.push_back(source_name + ":" + std::to_string(line_number) +
                                  ": brush setting '" + param.key +
                                  "' is not one this version knows (" +
                                  paintcore::bristle_setting_names() + "); ignored");
    file.events.push_back(std::move(event));
    file.lines.push_back(line_number);
  }
  if (in.bad()) throw InputFormatError(source_name, line_number, "", "read error");
  return file;
}

StrokeFile read_stroke_file(const std::filesystem::path& path) {
  const auto in = detail::open_recording(path, "stroke file");
  return parse_strokes(in->stream(), path.string());
}

std::string format_event(const StrokeEvent& event) {
  std::string line = detail::record_line(event);
  // Check the line by the reader's own rules, so that nothing written is unreadable.
  const std::string source = "event to write";
  const detail::LineContext where{source, 0};
  const auto fields = detail::split_fields(line, where);
  if (fields.empty() || detail::parse_record(fields, where) != event) {
    throw InputFormatError(source, 0, "", "cannot be written exactly: " + line);
  }
  return line;
}

void format_strokes(std::ostream& out, const StrokeFile& file) {
  if (file.version < kOldestStrokeFormatVersion || file.version > kStrokeFormatVersion) {
    throw std::runtime_error("cannot write stroke file version " + std::to_string(file.version));
  }
  out << kMagic << ' ' << file.version << '\n';
  for (const StrokeEvent& event : file.events) out << format_event(event) << '\n';
}

void write_stroke_file(const std::filesystem::path& path, const StrokeFile& file) {
  std::ostringstream text;
  format_strokes(text, file);
  files::write_file_atomically(path, text.str());
}

StrokeRecorder::StrokeRecorder(const std::filesystem::path& path) : file_(path) {
  if (!file_.append_line(std::string(kMagic) + ' ' + std::to_string(kStrokeFormatVersion))) {
    throw std::runtime_error(file_.error());
  }
}

bool StrokeRecorder::record(const StrokeEvent& event) {
  if (!file_.append_line(format_event(event))) return false;
  ++count_;
  return true;
}

}  // namespace impasto::input
