// Input: stroke files and HID pen reports. Run: impasto_microbench --benchmark_filter='Strokes|Hid'
#include <impasto/input/hid_pen.hpp>
#include <impasto/input/stroke_file.hpp>

#include <benchmark/benchmark.h>

#include <cmath>
#include <sstream>
#include <vector>

namespace {

namespace input = impasto::input;
namespace hid = impasto::input::hid;

// A pen with X, Y (0.01 mm), tip/barrel/in-range switches, 12-bit pressure and tilts.
const std::vector<std::uint8_t> kPenDescriptor = {
    0x05, 0x0D, 0x09, 0x02, 0xA1, 0x01, 0x85, 0x02, 0x09, 0x20, 0xA1, 0x00, 0x09, 0x42,
    0x09, 0x44, 0x09, 0x32, 0x15, 0x00, 0x25, 0x01, 0x75, 0x01, 0x95, 0x03, 0x81, 0x02,
    0x95, 0x05, 0x81, 0x03, 0xA4, 0x05, 0x01, 0x09, 0x30, 0x09, 0x31, 0x65, 0x11, 0x55,
    0x0D, 0x26, 0x10, 0x27, 0x46, 0x10, 0x27, 0x75, 0x10, 0x95, 0x02, 0x81, 0x02, 0xB4,
    0x09, 0x30, 0x26, 0xFF, 0x0F, 0x75, 0x10, 0x95, 0x01, 0x81, 0x02, 0x09, 0x3D, 0x09,
    0x3E, 0x15, 0xC4, 0x25, 0x3C, 0x75, 0x08, 0x95, 0x02, 0x81, 0x02, 0xC0, 0xC0};

std::string session_text(int samples) {
  input::StrokeFile file;
  for (int i = 0; i < samples; ++i) {
    impasto::paintcore::PenSample s;
    s.time_s = i / 200.0;
    s.x_mm = 100.0 + 50.0 * std::cos(i * 0.01);
    s.y_mm = 80.0 + 40.0 * std::sin(i * 0.013);
    s.pressure = static_cast<float>(0.5 + 0.4 * std::sin(i * 0.05));
    s.tilt_x_deg = static_cast<float>(20.0 * std::sin(i * 0.002));
    s.buttons = impasto::paintcore::kPenTip | impasto::paintcore::kPenInRange;
    file.events.push_back(input::SampleEvent{s});
  }
  std::ostringstream out;
  input::format_strokes(out, file);
  return out.str();
}

void BM_StrokesParse(benchmark::State& state) {
  const std::string text = session_text(static_cast<int>(state.range(0)));
  for (auto _ : state) {
    std::istringstream in(text);
    benchmark::DoNotOptimize(input::parse_strokes(in, "bench"));
  }
  state.SetItemsProcessed(state.iterations() * state.range(0));
  state.SetBytesProcessed(state.iterations() * static_cast<std::int64_t>(text.size()));
}
BENCHMARK(BM_StrokesParse)->Arg(10000);

void BM_StrokesWrite(benchmark::State& state) {
  std::istringstream in(session_text(static_cast<int>(state.range(0))));
  const input::StrokeFile file = input::parse_strokes(in, "bench");
  for (auto _ : state) {
    std::ostringstream out;
    input::format_strokes(out, file);
    benchmark::DoNotOptimize(out.str());
  }
  state.SetItemsProcessed(state.iterations() * state.range(0));
}
BENCHMARK(BM_StrokesWrite)->Arg(10000);

void BM_HidParseDescriptor(benchmark::State& state) {
  for (auto _ : state) benchmark::DoNotOptimize(hid::parse_report_descriptor(kPenDescriptor));
}
BENCHMARK(BM_HidParseDescriptor);

void BM_HidDecodePenReport(benchmark::State& state) {
  const hid::PenDecoder pen(hid::parse_report_descriptor(kPenDescriptor));
  std::vector<std::uint8_t> report = {0x02, 0x05, 0x88, 0x13, 0x10, 0x0E, 0x00, 0x08, 0x0A, 0xF6};
  double t = 0.0;
  for (auto _ : state) {
    report[2] = static_cast<std::uint8_t>(report[2] + 1);
    benchmark::DoNotOptimize(pen.decode(report, t));
    t += 0.005;
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_HidDecodePenReport);

}  // namespace
