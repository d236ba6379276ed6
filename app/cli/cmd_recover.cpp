// impasto recover: list and rebuild the sessions that did not end cleanly (a crash, a kill,
// a power cut), headless; the window offers the same at start (docs/guarantees.md).
#include <impasto/input/stroke_file.hpp>

#include <cstdio>
#include <filesystem>
#include <iostream>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>

#include "command.hpp"
#include "impasto/session/rebuild.hpp"
#include "impasto/session/recovery_folder.hpp"
#include "impasto/session/session_registry.hpp"
#include "progress_reporter.hpp"
#include "vocabulary.hpp"

// A namespace of its own: the command files are compiled together (unity build).
namespace impasto::app::recover_cmd {
namespace {

struct RecoverArgs {
  bool list = false;
  std::string apply, discard, save;
  bool force = false, keep = false;
  bool json = false;
};

std::string hex64(std::uint64_t value) {
  char text[17];
  std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(value));
  return text;
}

// The session by id; "latest" (or empty) is the newest.
session::SessionEntry find_session(const std::vector<session::SessionEntry>& sessions,
                                   const std::string& id) {
  if (sessions.empty()) throw std::runtime_error("no session to recover");
  if (id.empty() || id == "latest") return sessions.front();
  for (const auto& s : sessions) {
    if (s.id == id) return s;
  }
  throw std::runtime_error("no unfinished session '" + id + "' (impasto recover --list)");
}

void run_recover(const RecoverArgs& args) {
  const std::filesystem::path folder = session::recovery_folder();
  std::vector<std::string> problems;
  const std::vector<session::SessionEntry> sessions =
      session::unfinished_sessions(folder, &problems);
  for (const auto& p : problems) std::cerr << "impasto: warning: " << p << "\n";
  if (!args.discard.empty()) {
    const session::SessionEntry s = find_session(sessions, args.discard);
    discard_session(s);
    std::cout << "discarded " << s.id << " (its recording stays: " << s.strokes.string() << ")\n";
    return;
  }
  if (!args.apply.empty()) {
    const session::SessionEntry s = find_session(sessions, args.apply);
    std::filesystem::path out = args.save;
    if (out.empty()) {
      out = (s.painting ? s.painting->stem().string() : std::string("untitled")) +
            ".recovered.impasto";
    }
    if (std::filesystem::exists(out) && !args.force) {
      throw std::runtime_error(out.string() + ": exists; give another --save or --force");
    }
    session::ReplayOptions options;
    ProgressReporter progress("rebuild", "records");
    options.progress = progress.callback();
    session::RebuiltSession rebuilt = rebuild_session(input::read_stroke_file(s.strokes), options);
    progress.finish();
    for (const auto& w : rebuilt.warnings) std::cerr << "impasto: warning: " << w << "\n";
    rebuilt.painting.save(out);
    std::cout << "recovered " << s.id << " from " << rebuilt.base << " and "
              << rebuilt.report.samples << " pen samples after it into " << out.string()
              << "\nstate_hash " << hex64(rebuilt.painting.state_hash()) << "\n";
    if (!args.keep) discard_session(s);
    return;
  }
  if (args.json) {
    nlohmann::json list = nlohmann::json::array();
    for (const auto& s : sessions)
      list.push_back(
          {{"id", s.id},
           {"painting", s.painting ? s.painting->string() : ""},
           {"recording", s.strokes.string()},
           {"autosave", std::filesystem::exists(s.autosave) ? s.autosave.string() : ""}});
    std::cout << nlohmann::json{{"folder", folder.string()}, {"sessions", list}}.dump(2) << "\n";
    return;
  }
  std::cout << "recovery folder: " << folder.string() << "\n";
  if (sessions.empty()) std::cout << "no session to recover\n";
  for (const auto& s : sessions) {
    std::cout << s.id << "\n  painting: " << (s.painting ? s.painting->string() : "new")
              << "\n  recording: " << s.strokes.string() << "\n  autosave: "
              << (std::filesystem::exists(s.autosave) ? s.autosave.string() : "none") << "\n";
  }
}

const CommandRegistrar registrar("recover", [](CLI::App& root) {
  auto args = std::make_shared<RecoverArgs>();
  CLI::App* cmd = root.add_subcommand(
      "recover", "List or rebuild painting sessions that did not end cleanly (crash recovery)");
  cmd->add_flag("--list", args->list, "List the sessions that can be recovered (the default)");
  cmd->add_option("--apply", args->apply,
                  "Rebuild this session (its id, or 'latest') and save the painting (--save)");
  cmd->add_option("--discard", args->discard,
                  "Forget this session: remove its entry and autosave (the recording stays)");
  add_save_option(*cmd, args->save, "--apply's (default: NAME.recovered.impasto in this folder)");
  cmd->add_flag("--force", args->force, "Let --apply replace an existing --save file");
  cmd->add_flag("--keep", args->keep, "Keep the session recoverable after --apply");
  add_json_flag(*cmd, args->json, "the list: the folder, and each session's id and files");
  add_deprecated_option(*cmd, "--out", "--save",
                        [args](const std::string& file) { args->save = file; });
  cmd->callback([args] { run_recover(*args); });
});

}  // namespace
}  // namespace impasto::app::recover_cmd
