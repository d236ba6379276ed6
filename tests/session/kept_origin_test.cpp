// The painting a session began from, kept beside its recording (kept_origin.hpp): it survives
// the painting being saved over, is never written through a planted link, and lets the
// time-lapse show the session's strokes over that painting and a rebuild start from it.
#include <gtest/gtest.h>

#include <impasto/input/stroke_file.hpp>
#include <impasto/render/render_painting.hpp>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "../common/scratch_folder.hpp"
#include "impasto/session/kept_origin.hpp"
#include "impasto/session/rebuild.hpp"
#include "impasto/session/timelapse.hpp"

// (A namespace of its own: the session tests are compiled together, unity build.)
namespace impasto::session::kept_origin_test {
namespace {

namespace fs = std::filesystem;

input::SampleEvent pen(double t, double x, double y, bool down) {
  paintcore::PenSample s;
  s.time_s = t;
  s.x_mm = x;
  s.y_mm = y;
  s.pressure = down ? 0.8f : 0.0f;
  s.buttons = paintcore::kPenInRange | (down ? paintcore::kPenTip : 0u);
  return {s};
}

// A loaded brush's stroke across the small canvas at height y (mm).
std::vector<input::StrokeEvent> stroke(double y, const char* pigment) {
  std::vector<input::StrokeEvent> events;
  events.push_back(input::WipeEvent{});
  events.push_back(input::LoadEvent{20.0, {{pigment, 1.0}}, {}});
  for (int i = 0; i <= 8; ++i) events.push_back(pen(0.01 * i, 2.0 + 0.8 * i, y, i < 8));
  return events;
}

void play(paintcore::Painting& painting, const std::vector<input::StrokeEvent>& events) {
  ReplayOptions options;
  options.threads = 1;
  SessionPlayer player(painting, options, false);
  for (const auto& event : events) player.apply(event);
  player.finish();
}

// A session as the window records it: start.impasto (a blue stroke) is opened, a red stroke
// is painted and saved over start.impasto. The recording is `folder`/session.strokes.
struct OpenedAndSavedOver {
  fs::path folder, start, recording;
  paintcore::Painting opened{paintcore::CanvasSpec{80, 60, 254.0, 1}, 1};
  paintcore::Painting finished{paintcore::CanvasSpec{80, 60, 254.0, 1}, 1};
  input::StrokeFile file;

  explicit OpenedAndSavedOver(const std::string& name, bool keep = true)
      : folder(test::scratch_folder(name)),
        start(folder / "start.impasto"),
        recording(folder / "session.strokes") {
    play(opened, stroke(2.0, "Blue Red Shade"));
    opened.save(start);
    const auto& spec = opened.canvas().spec();
    file.events.push_back(input::CanvasEvent{spec.width_cells, spec.height_cells, spec.dpi});
    file.events.push_back(input::OriginEvent{false, start.string(), opened.state_hash()});
    if (keep) {
      EXPECT_EQ(keep_origin(start, recording), "");
    }
    const std::vector<input::StrokeEvent> red = stroke(4.0, "Red");
    file.events.insert(file.events.end(), red.begin(), red.end());
    input::write_stroke_file(recording, file);
    file = input::read_stroke_file(recording);  // as a reader finds it (its source)
    finished = paintcore::Painting::load(start, 1);
    play(finished, red);
    finished.save(start);  // saved over, without a mark in the recording
  }
};

TEST(KeptOrigin, KeepsTheFirstStateWhenThePaintingIsSavedOver) {
  OpenedAndSavedOver session("impasto_kept_origin_saved_over");
  const fs::path kept = kept_origin_path(session.recording);
  EXPECT_EQ(kept, session.folder / "session.origin");
  EXPECT_EQ(paintcore::Painting::load(kept, 1).state_hash(), session.opened.state_hash());
  EXPECT_NE(paintcore::Painting::load(session.start, 1).state_hash(), session.opened.state_hash());
  std::vector<std::string> warnings;
  const std::optional<paintcore::Painting> origin = load_session_origin(session.file, 1, warnings);
  ASSERT_TRUE(origin.has_value());
  EXPECT_EQ(origin->state_hash(), session.opened.state_hash());
  EXPECT_TRUE(warnings.empty());
}

TEST(KeptOrigin, NeverWritesThroughALinkPlantedWhereItGoes) {
  const fs::path folder = test::scratch_folder("impasto_kept_origin_planted");
  paintcore::Painting(paintcore::CanvasSpec{16, 16, 254.0, 1}, 1).save(folder / "p.impasto");
  fs::create_symlink(folder / "victim", folder / "s.origin");
  EXPECT_NE(keep_origin(folder / "p.impasto", folder / "s.strokes"), "");
  EXPECT_FALSE(fs::exists(folder / "victim"));
}

TEST(KeptOrigin, APaintingsFolderKeepsTheNewestSessionsOrigins) {
  const fs::path folder = test::scratch_folder("impasto_kept_origin_pruned");
  paintcore::Painting(paintcore::CanvasSpec{16, 16, 254.0, 1}, 1).save(folder / "p.impasto");
  const auto session = [&](const char* painting, int day) {
    char name[96];
    std::snprintf(name, sizeof name, "%s.session-202601%02d-120000.000000-1", painting, day);
    return folder / name;
  };
  for (int day = 1; day <= 10; ++day) {
    std::ofstream(session("p", day).string() + ".origin") << "an older version";
    std::ofstream(session("q", day).string() + ".origin") << "another painting's";
  }
  EXPECT_EQ(keep_origin(folder / "p.impasto", session("p", 20).string() + ".strokes"), "");
  int kept_p = 0, kept_q = 0;
  for (const auto& entry : fs::directory_iterator(folder)) {
    const std::string name = entry.path().filename().string();
    kept_p += name.starts_with("p.session-") ? 1 : 0;
    kept_q += name.starts_with("q.session-") ? 1 : 0;
  }
  EXPECT_EQ(kept_p, static_cast<int>(kKeptOrigins));
  EXPECT_EQ(kept_q, 10) << "another painting's origins are its own";
  EXPECT_TRUE(fs::exists(session("p", 20).string() + ".origin"));
  EXPECT_FALSE(fs::exists(session("p", 1).string() + ".origin")) << "the oldest go first";
  EXPECT_TRUE(fs::exists(session("p", 10).string() + ".origin"));
}

TEST(KeptOrigin, ATimelapseShowsTheStrokesOverThePaintingTheSessionBeganFrom) {
  OpenedAndSavedOver session("impasto_kept_origin_timelapse");
  TimelapseOptions options;
  options.fps = 2;
  options.growth_seconds = 1;
  options.hold_seconds = 0;
  std::vector<render::Image> frames;
  ReplayOptions replay;
  replay.threads = 1;
  TimelapseReport report = play_timelapse(session.file, replay, options,
                                          [&](const render::Image& f) { frames.push_back(f); });
  EXPECT_EQ(report.base, "the painting the session began from");
  EXPECT_TRUE(report.warnings.empty());
  ASSERT_EQ(frames.size(), 2u);
  // The last frame is the finished painting, the blue stroke under the red one.
  EXPECT_EQ(frames.back().rgb, render::render_painting(session.finished, {}).rgb);

  // Without the kept copy, the strokes on a blank canvas, said aloud.
  fs::remove(kept_origin_path(session.recording));
  frames.clear();
  report = play_timelapse(session.file, replay, options,
                          [&](const render::Image& f) { frames.push_back(f); });
  EXPECT_EQ(report.base, "a blank canvas");
  ASSERT_EQ(report.warnings.size(), 1u);
  EXPECT_NE(report.warnings[0].find("start.impasto"), std::string::npos) << report.warnings[0];
  EXPECT_NE(frames.back().rgb, render::render_painting(session.finished, {}).rgb);
}

TEST(KeptOrigin, ARebuildStartsFromTheKeptCopy) {
  OpenedAndSavedOver session("impasto_kept_origin_rebuild");
  ReplayOptions options;
  options.threads = 1;
  const RebuiltSession rebuilt = rebuild_session(session.file, options);
  EXPECT_EQ(rebuilt.painting.state_hash(), session.finished.state_hash());
  EXPECT_NE(rebuilt.base.find("session.origin"), std::string::npos) << rebuilt.base;
  EXPECT_TRUE(rebuilt.warnings.empty());
}

}  // namespace
}  // namespace impasto::session::kept_origin_test
