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

#include "../common/short_session.hpp"
#include "window_driver.hpp"

namespace {

namespace fs = std::filesystem;
using namespace std::chrono_literals;
using impasto::window_test::run_output;
using impasto::window_test::test_dir;
using impasto::window_test::wait_for;

struct CommandRun {
  int status = -1;
  std::string output;
};

CommandRun run(const std::string& command) {
  CommandRun result;
  result.output = run_output(command, &result.status);
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

fs::path write_session(const fs::path& dir) {
  return impasto::test::write_short_session(dir / "short.strokes");
}

TEST(WindowRecovery, AKilledSessionIsRebuiltByRecoverApply) {
  ASSERT_NE(std::getenv("DISPLAY"), nullptr) << "run under xvfb-run -a";
  const fs::path dir = test_dir("impasto_window_recovery");
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
  const bool saved = wait_for(autosaved, 60s);
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
  const fs::path dir = test_dir("impasto_window_full_disk");
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
