#pragma once
// The running sessions, as entries in the recovery folder (recovery_folder.hpp): one file
// "<id>.session" per session, naming its painting, its recording and its autosave, and held
// locked (flock) by the process for as long as it runs. An entry nobody holds is a session
// that did not end cleanly (a crash, a kill, a power cut): the window offers to recover it at
// start and `impasto recover` lists and rebuilds it.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace impasto::session {

struct SessionEntry {
  std::string id;                                 // the entry's file stem
  std::filesystem::path entry;                    // <folder>/<id>.session
  std::optional<std::filesystem::path> painting;  // the painting file it was opened from
  std::filesystem::path strokes;                  // its recording
  std::filesystem::path autosave;                 // <folder>/<id>.autosave.impasto
  long pid = 0;
};

class LiveSession {
 public:
  // Creates the entry exclusively (never through a symlink), syncs it and locks it.
  // Throws std::runtime_error naming the file when it cannot.
  LiveSession(const std::filesystem::path& folder, const std::string& id,
              const std::optional<std::filesystem::path>& painting,
              const std::filesystem::path& strokes);
  // Unlocks without removing: a session that did not end_cleanly() stays recoverable.
  ~LiveSession();
  LiveSession(const LiveSession&) = delete;
  LiveSession& operator=(const LiveSession&) = delete;

  // The session ended as the user chose (saved, or discarded on purpose): removes the entry
  // and the autosave. The recording stays.
  void end_cleanly();
  // The painting was saved as `painting` (an untitled one's first save, or Save as): the entry
  // names it from now on, so a recovery reopens with that file. Rewritten in place (the lock
  // stays with the file) and synced; throws std::runtime_error naming the entry.
  void painting_saved_as(const std::filesystem::path& painting);
  const SessionEntry& entry() const { return entry_; }

 private:
  SessionEntry entry_;
  int fd_ = -1;
};

// The entries in `folder` that no running process holds, newest first. Entries that cannot be
// read are skipped (their problem is in `problems` when given).
std::vector<SessionEntry> unfinished_sessions(const std::filesystem::path& folder,
                                              std::vector<std::string>* problems = nullptr);

// The running sessions of other processes (other windows) that opened `painting`, the same
// file by its canonical path: a window opening it says so.
std::vector<SessionEntry> other_sessions_with(const std::filesystem::path& folder,
                                              const std::filesystem::path& painting);

// Whether an unfinished session holds anything to recover: an autosave, or a recording with
// more than its header (canvas, brush, where it began). An unreadable recording counts.
bool has_work_to_recover(const SessionEntry& session);

// Forgets an unfinished session: removes its entry and autosave (its recording stays).
void discard_session(const SessionEntry& session);

}  // namespace impasto::session
