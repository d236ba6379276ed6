#pragma once
// The window's document controller: the painting the window edits and its session, a thin
// adapter over session/ (the simulation's worker, the session's recording and recovery entry,
// autosave, the sessions offered for recovery) and the file actions on it (new, open, save,
// export, the Image menu's reframe). It knows nothing of GLFW or the GPU: the window tells it
// the time and what the user chose, and resets its view when the painting is replaced.
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "impasto/session/rebuild.hpp"
#include "impasto/session/session_registry.hpp"
#include "impasto/session/session_start.hpp"
#include "impasto/session/sim_worker.hpp"
#include "window/canvas_menu.hpp"
#include "window/paint_options.hpp"
#include "window/palette_board_panel.hpp"
#include "window/panels.hpp"
#include "window/session_banner.hpp"
#include "window/timelapse_export.hpp"
#include "window/window_state.hpp"

namespace impasto::app::window {

class Document {
 public:
  // The painting the options name (a file, a replay's canvas or a new canvas), its session
  // recorded unless options.no_record, the replay's events queued, and the unfinished
  // sessions of other windows found (not in scripted replays). `board` is the Palette panel's
  // board, kept beside the painting's file.
  Document(const PaintOptions& options, WindowState& state, PaletteBoardPanel& board);
  Document(const Document&) = delete;
  Document& operator=(const Document&) = delete;
  ~Document();

  session::SimWorker& worker() { return *worker_; }
  // What the panels show of the painting this frame (waits for the simulation's lock).
  PaintingSnapshot snapshot();
  // What the session's start or a recovery has to say (a banner), until the next save.
  const std::string& notice() const { return notice_; }

  // The pen went down or moved at `now_s`; an autosave waits for it to rest.
  void note_input(double now_s) { last_input_s_ = now_s; }
  // Between strokes, once the pen has rested kAutosaveQuiet_s or the painting has gone on for
  // options.autosave_seconds since the last autosave.
  void maybe_autosave(double now_s, bool in_stroke);

  // The file actions of the File menu and dialogs.
  FileActions file_actions();
  // New, Open or Open recent once the user confirmed it (state.pending). Returns whether
  // the painting was replaced (the window then shows the new one whole).
  bool run_pending_action();
  // The Image menu: an export, a varnish coat, or a crop or resize (which replaces the
  // painting: returns true).
  bool apply_canvas_request(const CanvasMenuRequest& request);

  // The sessions offered for recovery, and the one being previewed (rebuilt).
  const std::vector<session::SessionEntry>& recoverable() const { return recoverable_; }
  // The sessions a time-lapse can be made of: this window's, then the earlier ones of this
  // window and those found unfinished at its start, the latest first.
  std::vector<TimelapseSource> timelapse_sources() const;
  std::optional<std::size_t> previewing() const { return previewing_; }
  const session::RebuiltSession* preview() const { return preview_.get(); }
  enum class Recovered { kNothing, kPreviewReady, kReplaced };
  Recovered recover(const RecoveryChoice& choice);

  // The window closes: `terminated` by a signal. Unsaved work a signal interrupted is
  // autosaved and its session left recoverable; otherwise the session ends cleanly. Throws
  // when any recording of this window's life failed, so scripts notice.
  void close(bool terminated);
  // Keeps the first recording failure of the window's life (close() reports it).
  void note_recording_failure();

 private:
  // Starts a session's recording and its recovery entry: beside `painting` when its folder
  // can be written, else in the recovery folder (and says so). `origin` is the file the
  // painting starts as (none: a new canvas).
  session::SessionRecording begin_session(const std::optional<std::filesystem::path>& painting,
                                          const std::optional<std::filesystem::path>& origin);
  void end_session();  // the user closed the painting on purpose: nothing to recover
  void opened_file(const std::filesystem::path& file);
  void open_board_for(const std::optional<std::filesystem::path>& painting);
  void find_recoverable_sessions();
  void queue_replay(input::StrokeFile strokes);

  const PaintOptions& options_;
  WindowState& state_;
  PaletteBoardPanel& board_;
  std::unique_ptr<session::SimWorker> worker_;
  std::unique_ptr<session::LiveSession> live_session_;
  std::string notice_;
  std::vector<session::SessionEntry> recoverable_;
  std::vector<TimelapseSource> earlier_sessions_;  // their recordings, oldest first
  std::optional<std::size_t> previewing_;
  std::unique_ptr<session::RebuiltSession> preview_;
  double last_input_s_ = 0.0, last_autosave_s_ = 0.0;
  std::string recording_failure_;  // the first failure of any recording in this window's life
};

}  // namespace impasto::app::window
