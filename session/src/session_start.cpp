#include "impasto/session/session_start.hpp"

#include <vector>

#include "impasto/session/recovery_folder.hpp"

namespace impasto::session {

SessionStart start_session_recording(const std::optional<std::filesystem::path>& painting,
                                     const std::optional<std::filesystem::path>& record_to) {
  SessionStart start;
  std::optional<std::filesystem::path> folder;
  std::string no_folder;
  try {
    folder = recovery_folder();
  } catch (const std::exception& e) {
    no_folder = e.what();
  }
  const std::string stem =
      unique_session_stem(painting ? painting->stem().string() : std::string("untitled"));
  // Where the recording may go, in order of preference.
  std::vector<std::filesystem::path> places;
  if (record_to) {
    places.push_back(*record_to);
  } else {
    if (painting) {
      places.push_back((painting->has_parent_path() ? painting->parent_path() : ".") /
                       (stem + ".strokes"));
    }
    if (folder) places.push_back(*folder / (stem + ".strokes"));
  }
  std::string why;
  for (const auto& place : places) {
    try {
      start.recorder = std::make_unique<input::StrokeRecorder>(place);
      break;
    } catch (const std::exception& e) {
      why += (why.empty() ? "" : "; ") + std::string(e.what());
    }
  }
  if (!start.recorder) {
    start.not_recording = "this session is not recorded: " + (why.empty() ? no_folder : why);
    return start;
  }
  if (painting && !record_to && start.recorder->path() != places.front()) {
    start.notice = "The folder of " + painting->string() +
                   " cannot be written (read-only?): this session is recorded in " +
                   start.recorder->path().string() + ". Save the painting elsewhere to keep it.";
  }
  const auto add_notice = [&](const std::string& text) {
    start.notice += (start.notice.empty() ? "" : " ") + text;
  };
  if (!folder) {
    add_notice("No crash recovery: " + no_folder);
    return start;
  }
  try {
    std::error_code error;
    std::optional<std::filesystem::path> absolute;
    if (painting) absolute = std::filesystem::absolute(*painting, error);
    start.live = std::make_unique<LiveSession>(
        *folder, stem, absolute, std::filesystem::absolute(start.recorder->path(), error));
  } catch (const std::exception& e) {
    add_notice("No crash recovery: " + std::string(e.what()));
  }
  return start;
}

}  // namespace impasto::session
