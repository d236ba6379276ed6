// Crash recovery end to end, under Xvfb: a window session killed with SIGKILL is rebuilt by
// `impasto recover --apply` into the very painting it held; a window whose disk fills up
// goes on painting and fails the command, with a recording of whole lines.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <thread>

namespace {

namespace fs = std::filesystem;

struct CommandRun {
  int status = -1;
  std::string output;
};

CommandRun run(const std::string& command) {
  CommandRun result;
  FILE* pipe = popen((command + " 2>&1").c_str(), "r");
  if (!pipe) return result;
  char buffer[4096];
  while (std::fgets(buffer, sizeof buffer, pipe)) result.output += buffer;
  result.status = pclose(pipe);
  return result;
}

std::string quoted(const fs::path& path) {
  return "'" + path.string() + "'";
}

std::string replay_hash(const fs::path& strokes) {
  const CommandRun r =
      run(std::string(IMPASTO_EXECUTABLE) + " replay " + quoted(strokes) + " --json");
  EXPECT_EQ(r.status, 0) << r.output;
  return nlohmann::json::parse(r.output.substr(r.output.find('{'))).at("state_hash");
}

// A short session on a small canvas: three loaded strokes.
fs::path write_session(const fs::path& dir) {
  const fs::path path = dir / "short.strokes";
  std::ofstream out(path);
  out << "impasto-strokes 2\ncanvas 240 160 254\nbrush round size=4 stiffness=0.5\n";
  const char* pigments[] = {"Ultramarine Blue", "Pyrrole Red", "Titanium White"};
  double t = 0;
  for (int k = 0; k < 3; ++k) {
    out << "wipe\nload 30 \"" << pigments[k] << "\" 1\n";
    for (int i = 0; i <= 40; ++i, t += 0.01) {
      const bool down = i < 40;
      out << "pen " << t << " " << 2 + 0.45 * i << " " << 4 + 4 * k << " " << (down ? 0.7 : 0)
          << " 0 0 0 " << (down ? 17 : 16) << "\n";
    }
  }
  return path;
}

fs::path fresh_dir(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / (name + "_" + std::to_string(getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

template <typename Ready>
bool wait_for(Ready ready, double seconds) {
  const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  while (std::chrono::steady_clock::now() < end) {
    if (ready()) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  return false;
}

TEST(WindowRecovery, AKilledSessionIsRebuiltByRecoverApply) {
  ASSERT_NE(std::getenv("DISPLAY"), nullptr) << "run under xvfb-run -a";
  const fs::path dir = fresh_dir("impasto_window_recovery");
  const fs::path strokes = write_session(dir);
  const fs::path state = dir / "state";
  setenv("XDG_STATE_HOME", state.c_str(), 1);
  const pid_t window = fork();
  ASSERT_GE(window, 0);
  if (window == 0) {
    execl(IMPASTO_EXECUTABLE, IMPASTO_EXECUTABLE, "paint", "--replay", strokes.c_str(),
          "--window-width", "900", "--window-height", "600", static_cast<char*>(nullptr));
    _exit(127);
  }
  // Painted and autosaved (the pen rests once the replay is in): then killed outright.
  const auto autosaved = [&] {
    std::error_code error;
    for (const auto& item : fs::directory_iterator(state / "impasto", error)) {
      if (item.path().string().ends_with(".autosave.impasto")) return true;
    }
    return false;
  };
  const bool saved = wait_for(autosaved, 60.0);
  kill(window, SIGKILL);
  waitpid(window, nullptr, 0);
  ASSERT_TRUE(saved) << "no autosave within 60 s";

  const std::string impasto = IMPASTO_EXECUTABLE;
  const CommandRun list = run(impasto + " recover --list");
  EXPECT_EQ(list.status, 0) << list.output;
  EXPECT_NE(list.output.find("untitled.session-"), std::string::npos) << list.output;
  const fs::path out = dir / "recovered.impasto";
  const CommandRun apply = run(impasto + " recover --apply latest --save " + quoted(out));
  ASSERT_EQ(apply.status, 0) << apply.output;
  const auto at = apply.output.find("state_hash ");
  ASSERT_NE(at, std::string::npos) << apply.output;
  EXPECT_EQ(apply.output.substr(at + 11, 16), replay_hash(strokes)) << apply.output;
  EXPECT_TRUE(fs::exists(out));
  // Recovered: no longer offered.
  EXPECT_NE(run(impasto + " recover --list").output.find("no session to recover"),
            std::string::npos);
  unsetenv("XDG_STATE_HOME");
  fs::remove_all(dir);
}

TEST(WindowRecovery, AFullDiskFailsTheCommandAndLeavesWholeLines) {
  ASSERT_NE(std::getenv("DISPLAY"), nullptr) << "run under xvfb-run -a";
  const fs::path dir = fresh_dir("impasto_window_full_disk");
  const fs::path strokes = write_session(dir);
  const fs::path recording = dir / "session.strokes";
  setenv("XDG_STATE_HOME", (dir / "state").c_str(), 1);
  // Every file the window writes stops at 3 KB: the recording fills up mid-session.
  const CommandRun r = run("trap '' XFSZ; ulimit -f 3; exec " + std::string(IMPASTO_EXECUTABLE) +
                           " paint --replay " + quoted(strokes) + " --record " + quoted(recording) +
                           " --exit --window-width 900 --window-height 600");
  unsetenv("XDG_STATE_HOME");
  EXPECT_NE(r.status, 0) << "a session that lost its recording exited 0\n" << r.output;
  EXPECT_NE(r.output.find("no longer recorded"), std::string::npos) << r.output;
  std::ifstream in(recording, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  ASSERT_FALSE(text.str().empty());
  EXPECT_EQ(text.str().back(), '\n') << "a torn line";
  const CommandRun replay = run(std::string(IMPASTO_EXECUTABLE) + " replay " + quoted(recording));
  EXPECT_EQ(replay.status, 0) << replay.output;
  EXPECT_EQ(replay.output.find("warning"), std::string::npos) << replay.output;
  fs::remove_all(dir);
}

}  // namespace
