#pragma once
// Where sessions are kept for recovery (docs/guarantees.md): $XDG_STATE_HOME/impasto, else
// ~/.local/state/impasto (the home from the password database when HOME is unset), a
// folder of this user's only (0700), never a shared one such as /tmp.
#include <filesystem>
#include <string>

namespace impasto::session {

// The recovery folder, created (0700) when missing and made private when it is not.
// Throws std::runtime_error when there is no home to put it in, or when it is a symlink or
// belongs to another user.
std::filesystem::path recovery_folder();

// A name stem no other session has: "<stem>.session-<YYYYmmdd-HHMMSS>.<microseconds>-<pid>".
// Sub-second time and the process id keep two sessions started in the same second apart;
// the files are still created exclusively, so a clash is an error, never a shared file.
std::string unique_session_stem(const std::string& stem);

}  // namespace impasto::session
