// Crash recovery without a window: the recovery folder is private and never /tmp, session
// names never collide, an entry is offered for recovery only once its process is gone, a
// recording rebuilds its painting from the latest save it marks (and from earlier ones when
// that is gone), and a painting in a read-only folder records into the recovery folder.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>
#include <impasto/input/stroke_file.hpp>

#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <set>
#include <string>

#include "../common/scoped_env.hpp"
#include "../common/short_session.hpp"
#include "impasto/session/rebuild.hpp"
#include "impasto/session/recovery_folder.hpp"
#include "impasto/session/session_registry.hpp"
#include "impasto/session/session_start.hpp"

namespace impasto::session {
namespace {

namespace fs = std::filesystem;
using impasto::test::ScopedEnv;

class TempDir {
 public:
  explicit TempDir(const std::string& name)
      : path_(fs::temp_directory_path() / (name + "_" + std::to_string(::getpid()))) {
    fs::remove_all(path_);
    fs::create_directories(path_);
  }
  ~TempDir() {
    std::error_code error;
    fs::permissions(path_, fs::perms::owner_all, fs::perm_options::add, error);
    fs::remove_all(path_, error);
  }
  const fs::path& path() const { return path_; }

 private:
  fs::path path_;
};

unsigned mode_of(const fs::path& path) {
  struct stat info {};
  ::lstat(path.c_str(), &info);
  return info.st_mode & 0777;
}

TEST(RecoveryFolder, IsPrivateUnderXdgStateHome) {
  TempDir dir("impasto_state");
  ScopedEnv state("XDG_STATE_HOME", dir.path().string());
  const fs::path folder = recovery_folder();
  EXPECT_EQ(folder, dir.path() / "impasto");
  EXPECT_EQ(mode_of(folder), 0700u);
  // A folder left open to others is closed again.
  fs::permissions(folder, fs::perms::all);
  recovery_folder();
  EXPECT_EQ(mode_of(folder), 0700u);
}

TEST(RecoveryFolder, ASymlinkedFolderIsRefused) {
  TempDir dir("impasto_state_link");
  fs::create_directories(dir.path() / "elsewhere");
  fs::create_directory_symlink(dir.path() / "elsewhere", dir.path() / "impasto");
  ScopedEnv state("XDG_STATE_HOME", dir.path().string());
  EXPECT_THROW(recovery_folder(), std::runtime_error);
}

TEST(RecoveryFolder, NeverTmpWithoutHomeOrXdgStateHome) {
  ScopedEnv state("XDG_STATE_HOME", std::nullopt);
  ScopedEnv home("HOME", std::nullopt);
  try {
    const fs::path folder = recovery_folder();  // the password database's home
    EXPECT_EQ(folder.filename(), "impasto");
    EXPECT_NE(folder.string().rfind(fs::temp_directory_path().string(), 0), 0u) << folder;
    EXPECT_EQ(mode_of(folder), 0700u);
  } catch (const std::runtime_error& e) {
    // No home at all: an error that says what to set, rather than a shared folder.
    EXPECT_NE(std::string(e.what()).find("XDG_STATE_HOME"), std::string::npos) << e.what();
  }
}

TEST(SessionNames, SessionsStartedInTheSameSecondGetTheirOwnFiles) {
  std::set<std::string> names;
  for (int i = 0; i < 1000; ++i) names.insert(unique_session_stem("p"));
  EXPECT_EQ(names.size(), 1000u);
  const std::string name = *names.begin();
  EXPECT_NE(name.find("-" + std::to_string(::getpid())), std::string::npos) << name;
  // A second process: its own pid, so its own name even in the same microsecond.
  TempDir dir("impasto_names");
  ScopedEnv state("XDG_STATE_HOME", dir.path().string());
  const pid_t child = ::fork();
  if (child == 0) {
    SessionStart start = start_session_recording(std::nullopt, std::nullopt);
    ::_exit(start.recorder && start.live ? 0 : 1);
  }
  SessionStart mine = start_session_recording(std::nullopt, std::nullopt);
  int status = 0;
  ::waitpid(child, &status, 0);
  ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0);
  ASSERT_TRUE(mine.recorder && mine.live);
  int recordings = 0;
  for (const auto& item : fs::directory_iterator(dir.path() / "impasto"))
    recordings += item.path().extension() == ".strokes";
  EXPECT_EQ(recordings, 2);
}

TEST(SessionRegistry, OnlySessionsWithWorkInThemAreWorthRecovering) {
  TempDir dir("impasto_registry_work");
  SessionEntry entry;
  entry.strokes = dir.path() / "s.strokes";
  entry.autosave = dir.path() / "s.autosave.impasto";
  {
    input::StrokeRecorder recorder(entry.strokes);
    recorder.record(input::CanvasEvent{64, 64, 150.0});
    recorder.record(input::OriginEvent{});
  }
  EXPECT_FALSE(has_work_to_recover(entry)) << "a header alone";
  { std::ofstream(entry.strokes, std::ios::app) << "wipe\n"; }
  EXPECT_TRUE(has_work_to_recover(entry));
  fs::remove(entry.strokes);
  EXPECT_TRUE(has_work_to_recover(entry)) << "an unreadable recording is the user's to judge";
}

// A FIFO under an entry's name, or as the recording an entry names, is skipped or refused
// without being opened for reading: opening it would wait for a writer forever (recover
// --list and the window's start hung).
TEST(SessionRegistry, AFifoInTheRecoveryFolderIsSkippedWithoutWaiting) {
  TempDir dir("impasto_registry_fifo");
  ASSERT_EQ(mkfifo((dir.path() / "planted.session").c_str(), 0600), 0);
  EXPECT_TRUE(unfinished_sessions(dir.path()).empty());
  SessionEntry entry;
  entry.strokes = dir.path() / "pipe.strokes";
  entry.autosave = dir.path() / "none.autosave.impasto";
  ASSERT_EQ(mkfifo(entry.strokes.c_str(), 0600), 0);
  EXPECT_TRUE(has_work_to_recover(entry)) << "an unreadable recording is the user's to judge";
}

TEST(SessionRegistry, AnEntryIsOfferedOnlyOnceItsSessionIsGone) {
  TempDir dir("impasto_registry");
  const fs::path strokes = dir.path() / "s.strokes";
  {
    LiveSession live(dir.path(), "one", fs::path("/p/a b.impasto"), strokes);
    EXPECT_TRUE(unfinished_sessions(dir.path()).empty()) << "a running session was offered";
    EXPECT_EQ(mode_of(live.entry().entry), 0600u);
    EXPECT_THROW(LiveSession(dir.path(), "one", std::nullopt, strokes), std::runtime_error);
  }  // gone without ending cleanly: a crash
  auto found = unfinished_sessions(dir.path());
  ASSERT_EQ(found.size(), 1u);
  EXPECT_EQ(found[0].id, "one");
  EXPECT_EQ(found[0].painting, fs::path("/p/a b.impasto"));
  EXPECT_EQ(found[0].strokes, strokes);
  EXPECT_EQ(found[0].autosave, dir.path() / "one.autosave.impasto");
  discard_session(found[0]);
  EXPECT_TRUE(unfinished_sessions(dir.path()).empty());
  {
    LiveSession live(dir.path(), "two", std::nullopt, strokes);
    live.end_cleanly();
  }
  EXPECT_TRUE(unfinished_sessions(dir.path()).empty()) << "a cleanly ended session was offered";
}

// An untitled painting saved as a file (or any Save as): a crash after it recovers that file,
// so Save goes back to it; the entry stays locked (the session is still running).
TEST(SessionRegistry, ASaveAsIsWhatARecoveryReopens) {
  TempDir dir("impasto_registry_save_as");
  const fs::path strokes = dir.path() / "s.strokes";
  {
    LiveSession live(dir.path(), "untitled", std::nullopt, strokes);
    live.painting_saved_as(dir.path() / "stilllife.impasto");
    EXPECT_EQ(live.entry().painting, dir.path() / "stilllife.impasto");
    EXPECT_TRUE(unfinished_sessions(dir.path()).empty()) << "the rewrite dropped the lock";
    live.painting_saved_as(dir.path() / "a.impasto");  // a shorter name: no tail left behind
  }
  const auto found = unfinished_sessions(dir.path());
  ASSERT_EQ(found.size(), 1u);
  EXPECT_EQ(found[0].painting, dir.path() / "a.impasto");
  EXPECT_EQ(found[0].strokes, strokes);
  EXPECT_EQ(found[0].autosave, dir.path() / "untitled.autosave.impasto");
}

// Another window (another process) holding a painting is found by the file, whatever path
// names it; this process's own sessions and other paintings are not; once that process is gone
// its entry is an unfinished session, no longer a running one.
TEST(SessionRegistry, AnotherProcessWithThePaintingOpenIsFound) {
  TempDir dir("impasto_registry_others");
  const fs::path painting = dir.path() / "shared.impasto";
  std::ofstream(painting) << "x";
  LiveSession mine(dir.path(), "mine", painting, dir.path() / "mine.strokes");
  int ready[2];
  ASSERT_EQ(::pipe(ready), 0);
  const pid_t other = ::fork();
  ASSERT_GE(other, 0);
  if (other == 0) {
    // The other window: through another spelling of the same path.
    LiveSession theirs(dir.path(), "theirs", dir.path() / "." / "shared.impasto",
                       dir.path() / "theirs.strokes");
    LiveSession elsewhere(dir.path(), "elsewhere", dir.path() / "other.impasto",
                          dir.path() / "elsewhere.strokes");
    const char byte = 1;
    if (::write(ready[1], &byte, 1) != 1) ::_exit(1);
    ::pause();
    ::_exit(0);
  }
  char byte = 0;
  ASSERT_EQ(::read(ready[0], &byte, 1), 1);
  const std::vector<SessionEntry> found = other_sessions_with(dir.path(), painting);
  ::kill(other, SIGKILL);
  ::waitpid(other, nullptr, 0);
  ::close(ready[0]);
  ::close(ready[1]);
  ASSERT_EQ(found.size(), 1u);
  EXPECT_EQ(found[0].id, "theirs");
  EXPECT_EQ(found[0].pid, static_cast<long>(other));
  EXPECT_TRUE(other_sessions_with(dir.path(), painting).empty()) << "a dead window still counted";
  EXPECT_EQ(unfinished_sessions(dir.path()).size(), 2u);
}

// A short session: a loaded brush and a few strokes on a small canvas.
input::SampleEvent pen(double t, double x, double y, bool down, float pressure = 0.8f) {
  paintcore::PenSample s;
  s.time_s = t;
  s.x_mm = x;
  s.y_mm = y;
  s.pressure = down ? pressure : 0.0f;
  s.buttons = paintcore::kPenInRange | (down ? paintcore::kPenTip : 0u);
  return {s};
}

std::vector<input::StrokeEvent> stroke(double y) {
  std::vector<input::StrokeEvent> events;
  events.push_back(input::LoadEvent{20.0, {{"Blue Red Shade", 1.0}}, {}});
  for (int i = 0; i <= 8; ++i) events.push_back(pen(0.01 * i, 2.0 + 0.8 * i, y, i < 8));
  return events;
}

// Plays events onto `painting` as the window does and records them, with marks for saves.
struct LiveRun {
  paintcore::Painting painting;
  ReplayOptions options;
  SessionPlayer player{painting, options, false};
  input::StrokeFile recording;

  explicit LiveRun(paintcore::CanvasSpec canvas = {80, 60, 254.0, 1}) : painting(canvas, 1) {
    options.threads = 1;
    const auto& spec = painting.canvas().spec();
    recording.events.push_back(input::CanvasEvent{spec.width_cells, spec.height_cells, spec.dpi});
  }
  void play(const std::vector<input::StrokeEvent>& events) {
    for (const auto& e : events) {
      recording.events.push_back(e);
      player.apply(e);
    }
    player.finish();
  }
  void save(const fs::path& file, bool as_origin = false) {
    painting.save(file);
    if (as_origin) {
      recording.events.push_back(input::OriginEvent{false, file.string(), painting.state_hash()});
    } else {
      recording.events.push_back(input::SavedEvent{file.string(), painting.state_hash()});
    }
  }
};

TEST(Rebuild, FromTheLatestMarkedSaveAndEarlierOnesWhenItIsGone) {
  TempDir dir("impasto_rebuild");
  LiveRun live;
  live.play(stroke(3.0));
  live.save(dir.path() / "start.impasto", true);  // the session "opened" this painting
  live.play(stroke(4.0));
  live.save(dir.path() / "autosave.impasto");
  live.play(stroke(5.0));
  const std::uint64_t expected = live.painting.state_hash();
  ReplayOptions options;
  options.threads = 1;

  RebuiltSession rebuilt = rebuild_session(live.recording, options);
  EXPECT_EQ(rebuilt.painting.state_hash(), expected);
  EXPECT_NE(rebuilt.base.find("autosave.impasto"), std::string::npos) << rebuilt.base;
  EXPECT_EQ(rebuilt.report.strokes, 1u) << "only the strokes after the autosave are replayed";

  fs::remove(dir.path() / "autosave.impasto");
  rebuilt = rebuild_session(live.recording, options);
  EXPECT_EQ(rebuilt.painting.state_hash(), expected);
  EXPECT_NE(rebuilt.base.find("start.impasto"), std::string::npos) << rebuilt.base;
  EXPECT_TRUE(rebuilt.warnings.empty());

  // The start painting changed since, and nothing else is left: a blank canvas, said aloud.
  paintcore::Painting(paintcore::CanvasSpec{80, 60, 254.0, 1}, 1)
      .save(dir.path() / "start.impasto");
  rebuilt = rebuild_session(live.recording, options);
  ASSERT_EQ(rebuilt.warnings.size(), 1u);
  EXPECT_NE(rebuilt.warnings[0].find("start.impasto"), std::string::npos) << rebuilt.warnings[0];
}

// A session that opens start.impasto, paints a stroke, saves it as saved.impasto (with its
// undo history or without), undoes the stroke and its load and paints another: the rebuild
// gives the live painting's hash; returns the painting it started from.
std::string base_of_an_undo_past_a_save(const std::string& folder, bool keep_history) {
  TempDir dir(folder);
  LiveRun live;
  live.save(dir.path() / "start.impasto", true);
  live.play(stroke(3.0));
  if (!keep_history) live.painting.set_saved_history_bytes(0);
  live.save(dir.path() / "saved.impasto");
  live.play({input::UndoEvent{}, input::UndoEvent{}});  // the stroke and its load
  live.play(stroke(5.0));
  ReplayOptions options;
  options.threads = 1;
  const RebuiltSession rebuilt = rebuild_session(live.recording, options);
  EXPECT_EQ(rebuilt.painting.state_hash(), live.painting.state_hash());
  return rebuilt.base;
}

TEST(Rebuild, AnUndoReachingBackPastASaveUsesAnEarlierBase) {
  // A save without its undo history (saved_history_bytes 0): the undos after it cannot be
  // replayed from it, so the rebuild starts from the painting the session opened.
  const std::string base = base_of_an_undo_past_a_save("impasto_rebuild_undo", false);
  EXPECT_NE(base.find("start.impasto"), std::string::npos) << base;
}

TEST(Rebuild, AnUndoReachingBackPastASaveUndoesIntoItsSavedHistory) {
  // By default a save keeps its undo history: the undos after it replay from it.
  const std::string base = base_of_an_undo_past_a_save("impasto_rebuild_undo_history", true);
  EXPECT_NE(base.find("saved.impasto"), std::string::npos) << base;
}

// A save mark is only as good as the round trip: the file must load with the hash the mark
// took from the live painting, whatever the session did (several pigments, wipes, paint left
// on the brush, a brush change). These strokes leave a brush cell holding 2.5928e-06 mm of
// paint and 2.60703e-06 mm of pigment (float rounding), which the loader keeps exactly.
TEST(Rebuild, ASavedPaintingLoadsWithTheHashItsMarkNames) {
  TempDir dir("impasto_rebuild_hash");
  using S = test::ShortSession;  // the session the command-line tests replay from a file
  LiveRun live(paintcore::CanvasSpec{S::kWidthCells, S::kHeightCells, S::kDpi, 1});
  live.play({input::BrushEvent{S::kBrush, S::kBrushSizeMm, S::kBrushStiffness, {}}});
  const auto strokes = S::strokes();
  for (std::size_t k = 0; k < strokes.size(); ++k) {
    std::vector<input::StrokeEvent> events = {
        input::WipeEvent{}, input::LoadEvent{S::kLoadMm3, {{S::kPigments[k], 1.0}}, {}}};
    for (const S::Pen& p : strokes[k])
      events.push_back(pen(p.time_s, p.x_mm, p.y_mm, p.down, static_cast<float>(S::kPressure)));
    live.play(events);
  }
  live.save(dir.path() / "p.impasto");
  const paintcore::Painting loaded = paintcore::Painting::load(dir.path() / "p.impasto", 1);
  EXPECT_EQ(loaded.canvas_totals().volume, live.painting.canvas_totals().volume);
  EXPECT_EQ(loaded.canvas_totals().pigment, live.painting.canvas_totals().pigment);
  EXPECT_EQ(loaded.brush_totals().pigment, live.painting.brush_totals().pigment);
  EXPECT_EQ(loaded.loaded_totals().pigment, live.painting.loaded_totals().pigment);
  EXPECT_EQ(loaded.wiped_totals().pigment, live.painting.wiped_totals().pigment);
  EXPECT_EQ(loaded.state_hash(), live.painting.state_hash());
}

// Run as another user when root, for whom no folder is read-only.
TEST(SessionStart, APaintingInAReadOnlyFolderRecordsIntoTheRecoveryFolder) {
  TempDir dir("impasto_readonly");
  const fs::path folder = dir.path() / "gallery";
  const fs::path state = dir.path() / "state";
  fs::create_directories(folder);
  fs::create_directories(state);
  const fs::path painting = folder / "study.impasto";
  paintcore::Painting(paintcore::CanvasSpec{16, 16, 150.0, 1}, 1).save(painting);
  fs::permissions(folder, fs::perms::owner_read | fs::perms::owner_exec | fs::perms::group_read |
                              fs::perms::group_exec | fs::perms::others_read |
                              fs::perms::others_exec);
  fs::permissions(dir.path(), fs::perms::all, fs::perm_options::add);
  const uid_t nobody = 65534;
  if (::geteuid() == 0) {
    ASSERT_EQ(::chown(state.c_str(), nobody, nobody), 0);
  }
  const pid_t child = ::fork();
  if (child == 0) {
    if (::geteuid() == 0 && (::setgid(nobody) != 0 || ::setuid(nobody) != 0)) ::_exit(10);
    ::setenv("XDG_STATE_HOME", state.c_str(), 1);
    SessionStart start = start_session_recording(painting, std::nullopt);
    if (!start.recorder) ::_exit(11);
    if (start.recorder->path().parent_path() != state / "impasto") ::_exit(12);
    if (start.notice.find("cannot be written") == std::string::npos) ::_exit(13);
    if (!start.live || start.live->entry().painting != painting) ::_exit(14);
    ::_exit(0);
  }
  int status = 0;
  ::waitpid(child, &status, 0);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 0) << "10 setuid, 11 no recording, 12 wrong folder, 13 no notice, "
                                       "14 no recovery entry";
  EXPECT_FALSE(fs::exists(folder / "study.impasto.strokes"));
}

}  // namespace
}  // namespace impasto::session
