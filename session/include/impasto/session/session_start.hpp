#pragma once
// Starting a session's recording and its recovery entry (docs/guarantees.md): the recording
// goes beside the painting when that folder can be written, else (a read-only folder, a new
// canvas) to the recovery folder, and the entry that makes it recoverable to the recovery
// folder. What could not be done is said, never silently dropped.
#include <impasto/input/stroke_file.hpp>

#include <filesystem>
#include <memory>
#include <optional>
#include <string>

#include "impasto/session/session_registry.hpp"

namespace impasto::session {

struct SessionStart {
  std::unique_ptr<input::StrokeRecorder> recorder;  // none: not recorded (not_recording says why)
  std::unique_ptr<LiveSession> live;                // none: no crash recovery (notice says why)
  std::string not_recording;
  std::string notice;  // for the user: where the recording went instead, no recovery folder
};

// `painting`: the file the session's painting belongs to (none: a new canvas); `record_to`:
// an explicit recording path (a new file), which is then the only place tried.
SessionStart start_session_recording(const std::optional<std::filesystem::path>& painting,
                                     const std::optional<std::filesystem::path>& record_to);

}  // namespace impasto::session
