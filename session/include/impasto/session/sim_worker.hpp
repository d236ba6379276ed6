#pragma once
// The simulation thread of the painting window. The UI thread submits session events (pen
// samples, brush, load, dry, undo, ...); the worker applies them in order to the painting
// through the same SessionPlayer as `impasto replay`, and records each one to the session's
// stroke file first, so that the file replays the session exactly.
#include <impasto/input/stroke_events.hpp>
#include <impasto/input/stroke_file.hpp>
#include <impasto/paintcore/painting.hpp>

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <deque>
#include <filesystem>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

#include "impasto/session/replay.hpp"

namespace impasto::session {

struct SimStats {
  double last_event_ms = 0.0;   // time the last applied event took
  double busy_ms_per_s = 0.0;   // simulation load over the last second
  std::size_t queued = 0;       // events waiting
  std::uint64_t applied = 0;    // events applied since the worker started
  std::uint64_t submitted = 0;  // jobs queued since the worker started (applied + waiting)
  std::uint64_t events_since_save = 0;
  std::uint64_t events_since_autosave = 0;
  std::string last_error;  // the most recent event that could not be applied
  // Why the session is not being recorded (the recording stopped, or never started); empty
  // while it is. It stays until the painting is replaced: the window shows it as a banner.
  std::string recording_error;
  std::string autosave_error;  // the last autosave's failure; empty once one succeeds
  std::uint64_t autosaves = 0;
};

// What a session is recorded with: the recorder (none when recording is off or could not
// start, with the reason), and the painting file it was opened from (none: a new canvas).
struct SessionRecording {
  std::unique_ptr<input::StrokeRecorder> recorder;
  std::string not_recording;  // why there is no recorder, when that is a problem
  std::optional<std::filesystem::path> opened_from;
};

class SimWorker {
 public:
  // Takes the painting and the recording; writes the recording's header (canvas, brush and
  // `from`, so the file rebuilds the painting alone).
  SimWorker(paintcore::Painting painting, SessionRecording recording);
  ~SimWorker();
  SimWorker(const SimWorker&) = delete;
  SimWorker& operator=(const SimWorker&) = delete;

  // Queues an event; returns at once. Events apply in submission order.
  void submit(input::StrokeEvent event);
  // Blocks until every submitted event has been applied.
  void wait_idle();
  // Waits as wait_idle() does, for at most `limit`; returns whether the worker is idle.
  bool wait_idle_for(std::chrono::microseconds limit);
  bool idle() const;

  // Strokes without a load record get a brush auto-loaded per stroke (as `impasto replay`
  // does for recordings from other programs). Applies to events submitted afterwards.
  void set_auto_load(bool auto_load);
  // Ends an open stroke, as the end of a replayed file does (not recorded: a replay of the
  // recording ends it the same way).
  void finish_stroke();

  // Runs f(painting) with the painting locked against the worker (keep it short).
  template <typename F>
  decltype(auto) with_painting(F&& f) {
    std::lock_guard lock(painting_mutex_);
    return f(static_cast<const paintcore::Painting&>(painting_));
  }
  // A consumer of what the painting's strokes change (the window's view): subscribe once; the
  // subscription outlives replace_painting, its next take seeing the new canvas whole.
  paintcore::Painting::ChangeSubscriber subscribe_changes() {
    std::lock_guard lock(painting_mutex_);
    return painting_.subscribe_changes();
  }
  // Runs f(painting, changed) locked, with the tiles changed since the subscriber's previous
  // take (Painting::take_changes).
  template <typename F>
  decltype(auto) with_changes(paintcore::Painting::ChangeSubscriber subscriber, F&& f) {
    std::lock_guard lock(painting_mutex_);
    const std::vector<paintcore::DirtyTile> changed = painting_.take_changes(subscriber);
    return f(static_cast<const paintcore::Painting&>(painting_), changed);
  }
  // The same for a change outside the session's events: the pigments a painting carries
  // (window/pigment_drift_note.cpp), which the simulation never reads.
  template <typename F>
  decltype(auto) edit_painting(F&& f) {
    std::lock_guard lock(painting_mutex_);
    return f(painting_);
  }
  // Waits for the queue to drain, then replaces the painting (new, open, recovered) and the
  // recording; `unsaved`: the painting differs from its file (a recovered one).
  void replace_painting(paintcore::Painting painting, SessionRecording recording,
                        bool unsaved = false);
  // Saves under the lock (after the queue drained); resets events_since_save and marks the
  // save in the recording.
  void save(const std::filesystem::path& file);
  // Queues an autosave to `file` (atomic, as every save), done between strokes on the
  // worker's thread and marked in the recording; its failure goes to stats().autosave_error.
  void autosave(const std::filesystem::path& file);

  SimStats stats() const;
  std::optional<std::filesystem::path> recording_path() const;

 private:
  struct Job {
    input::StrokeEvent event;
    std::optional<bool> auto_load;  // a change of auto-load, in order with the events
    bool finish = false;            // end an open stroke
    std::optional<std::filesystem::path> autosave_to;
  };
  void run();
  void start_recording(SessionRecording recording);
  // Writes to the recording; on its first failure keeps the reason and stops recording.
  // Holding painting_mutex_.
  void record(const input::StrokeEvent& event);
  // Syncs the recording when `now` (a stroke ended) or when it has waited kSyncEvery.
  void sync_recording(bool now);
  void mark_saved(const std::filesystem::path& file);
  void do_autosave(const std::filesystem::path& file);

  paintcore::Painting painting_;
  ReplayOptions options_;
  std::unique_ptr<SessionPlayer> player_;
  std::unique_ptr<input::StrokeRecorder> recorder_;
  std::string recording_error_;  // guarded by painting_mutex_, copied into stats_
  double last_sync_s_ = 0.0;
  bool tip_was_down_ = false;
  mutable std::mutex painting_mutex_;

  mutable std::mutex queue_mutex_;
  std::condition_variable queue_changed_;
  std::deque<Job> queue_;
  bool busy_ = false;
  bool stopping_ = false;
  SimStats stats_;
  double busy_window_ms_ = 0.0;
  double window_start_s_ = 0.0;
  std::thread thread_;
};

}  // namespace impasto::session
