#include <impasto/input/stroke_events.hpp>

namespace impasto::input {

bool SampleEvent::operator==(const SampleEvent& other) const {
  const paintcore::PenSample& a = sample;
  const paintcore::PenSample& b = other.sample;
  return a.time_s == b.time_s && a.x_mm == b.x_mm && a.y_mm == b.y_mm && a.pressure == b.pressure &&
         a.tilt_x_deg == b.tilt_x_deg && a.tilt_y_deg == b.tilt_y_deg &&
         a.rotation_deg == b.rotation_deg && a.buttons == b.buttons;
}

std::string StrokeFile::where(std::size_t i) const {
  if (!source.empty() && i < lines.size()) return source + ":" + std::to_string(lines[i]);
  return "record " + std::to_string(i + 1);
}

std::vector<paintcore::PenSample> pen_samples(const StrokeFile& file) {
  std::vector<paintcore::PenSample> samples;
  for (const StrokeEvent& event : file.events) {
    if (const auto* pen = std::get_if<SampleEvent>(&event)) samples.push_back(pen->sample);
  }
  return samples;
}

std::vector<StrokeSpan> split_strokes(const std::vector<paintcore::PenSample>& samples) {
  std::vector<StrokeSpan> strokes;
  bool in_stroke = false;
  for (std::size_t i = 0; i < samples.size(); ++i) {
    const bool down = samples[i].tip_down();
    if (down && !in_stroke) strokes.push_back({i, i});
    if (down) strokes.back().end = i + 1;
    in_stroke = down;
  }
  return strokes;
}

}  // namespace impasto::input
