#include "impasto/session/sim_worker.hpp"

#include "impasto/session/kept_origin.hpp"

#include <algorithm>
#include <chrono>
#include <iostream>
#include <variant>

namespace impasto::session {
namespace {

// The recording is synced at every stroke end and at least this often while it has news.
constexpr double kSyncEvery_s = 2.0;
// An autosave keeps only the newest undo steps: it runs every few seconds, and the session's
// recording holds the rest (a recovery that must undo further starts from an earlier mark,
// session/rebuild.hpp). File > Save keeps the painting's own cap (64 MB by default).
constexpr std::size_t kAutosaveHistoryBytes = std::size_t{4} << 20;

double now_s() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

}  // namespace

SimWorker::SimWorker(paintcore::Painting painting, SessionRecording recording)
    : painting_(std::move(painting)) {
  player_ = std::make_unique<SessionPlayer>(painting_, options_, false);
  start_recording(std::move(recording));
  window_start_s_ = now_s();
  thread_ = std::thread([this] { run(); });
}

SimWorker::~SimWorker() {
  {
    std::lock_guard lock(queue_mutex_);
    stopping_ = true;
  }
  queue_changed_.notify_all();
  thread_.join();
  std::lock_guard lock(painting_mutex_);
  player_->finish();
  sync_recording(true);
}

void SimWorker::start_recording(SessionRecording recording) {
  recorder_ = std::move(recording.recorder);
  recording_error_ = recording.not_recording;
  tip_was_down_ = false;
  if (recorder_) {
    // The session starts from this canvas and brush: write them so the file replays alone,
    // then where it started from, so a rebuild can start from that painting instead.
    const auto& spec = painting_.canvas().spec();
    record(input::CanvasEvent{spec.width_cells, spec.height_cells, spec.dpi});
    if (!painting_.brush().empty()) {
      const auto& brush = painting_.brush().settings();
      record(input::BrushEvent{brush.head, brush.size_mm, brush.stiffness, {}});
    }
    input::OriginEvent origin;
    if (recording.opened_from) {
      std::error_code error;
      origin = {false, std::filesystem::absolute(*recording.opened_from, error).string(),
                painting_.state_hash()};
    }
    record(origin);
    sync_recording(true);
    // Saving over the painting replaces its file: its first state is kept for the time-lapse
    // and the rebuild (kept_origin.hpp). Without it they still work from the session's saves.
    if (recorder_ && recording.opened_from) {
      const std::string not_kept = keep_origin(*recording.opened_from, recorder_->path());
      if (!not_kept.empty())
        std::cerr << "impasto: warning: the painting the session began from is not kept beside "
                     "its recording ("
                  << not_kept << ")\n";
    }
  }
  std::lock_guard lock(queue_mutex_);
  stats_.recording_error = recording_error_;
}

void SimWorker::record(const input::StrokeEvent& event) {
  if (!recorder_) return;
  if (!recorder_->record(event)) {
    recording_error_ = "the session is no longer recorded (" + recorder_->error() +
                       "); the painting goes on: save it to keep it";
    recorder_.reset();
  }
}

void SimWorker::sync_recording(bool now) {
  if (!recorder_ || !recorder_->needs_sync()) return;
  if (!now && now_s() - last_sync_s_ < kSyncEvery_s) return;
  if (!recorder_->sync()) {
    recording_error_ = "the session is no longer recorded (" + recorder_->error() +
                       "); the painting goes on: save it to keep it";
    recorder_.reset();
  }
  last_sync_s_ = now_s();
}

void SimWorker::mark_saved(const std::filesystem::path& file) {
  std::error_code error;
  record(
      input::SavedEvent{std::filesystem::absolute(file, error).string(), painting_.state_hash()});
  sync_recording(true);
}

void SimWorker::submit(input::StrokeEvent event) {
  {
    std::lock_guard lock(queue_mutex_);
    ++stats_.submitted;
    queue_.push_back({std::move(event), std::nullopt, false, std::nullopt});
  }
  queue_changed_.notify_all();
}

void SimWorker::set_auto_load(bool auto_load) {
  {
    std::lock_guard lock(queue_mutex_);
    ++stats_.submitted;
    queue_.push_back({input::ToolEvent{"brush"}, auto_load, false, std::nullopt});
  }
  queue_changed_.notify_all();
}

void SimWorker::finish_stroke() {
  {
    std::lock_guard lock(queue_mutex_);
    ++stats_.submitted;
    queue_.push_back({input::ToolEvent{"brush"}, std::nullopt, true, std::nullopt});
  }
  queue_changed_.notify_all();
}

void SimWorker::autosave(const std::filesystem::path& file) {
  {
    std::lock_guard lock(queue_mutex_);
    ++stats_.submitted;
    queue_.push_back({input::ToolEvent{"brush"}, std::nullopt, false, file});
  }
  queue_changed_.notify_all();
}

void SimWorker::wait_idle() {
  std::unique_lock lock(queue_mutex_);
  queue_changed_.wait(lock, [&] { return queue_.empty() && !busy_; });
}

bool SimWorker::wait_idle_for(std::chrono::microseconds limit) {
  std::unique_lock lock(queue_mutex_);
  return queue_changed_.wait_for(lock, limit, [&] { return queue_.empty() && !busy_; });
}

bool SimWorker::idle() const {
  std::lock_guard lock(queue_mutex_);
  return queue_.empty() && !busy_;
}

// Between strokes only: a save ends an open stroke, which the live session has not done.
void SimWorker::do_autosave(const std::filesystem::path& file) {
  std::string error;
  bool saved = false;
  if (!painting_.in_stroke()) {
    const std::size_t history = painting_.saved_history_bytes();
    try {
      painting_.set_saved_history_bytes(std::min(history, kAutosaveHistoryBytes));
      painting_.save(file);
      painting_.set_saved_history_bytes(history);
      mark_saved(file);
      saved = true;
    } catch (const std::exception& e) {
      painting_.set_saved_history_bytes(history);
      error = std::string("autosave failed: ") + e.what();
    }
  }
  std::lock_guard lock(queue_mutex_);
  if (saved) {
    stats_.events_since_autosave = 0;
    ++stats_.autosaves;
  }
  if (saved || !error.empty()) stats_.autosave_error = error;
}

void SimWorker::run() {
  for (;;) {
    Job job;
    {
      std::unique_lock lock(queue_mutex_);
      // While the recording has unsynced records, wake to sync them even without input.
      while (!stopping_ && queue_.empty()) {
        if (queue_changed_.wait_for(lock, std::chrono::duration<double>(kSyncEvery_s)) ==
            std::cv_status::timeout) {
          lock.unlock();
          {
            std::lock_guard painting_lock(painting_mutex_);
            sync_recording(false);
          }
          lock.lock();
          stats_.recording_error = recording_error_;
        }
      }
      if (queue_.empty()) return;  // stopping with nothing left to do
      job = std::move(queue_.front());
      queue_.pop_front();
      busy_ = true;
    }
    const double start = now_s();
    std::string error;
    bool session_event = false;
    {
      std::lock_guard lock(painting_mutex_);
      if (job.autosave_to) {
        do_autosave(*job.autosave_to);
      } else if (job.finish) {
        player_->finish();
      } else if (job.auto_load) {
        player_->finish();
        player_ = std::make_unique<SessionPlayer>(painting_, options_, *job.auto_load);
      } else {
        session_event = true;
        // Recorded first, so that a crash while applying it still has it; a recording that
        // fails stops recording but never the painting.
        record(job.event);
        try {
          player_->apply(job.event);
        } catch (const std::exception& e) {
          error = e.what();
        }
        const auto* pen = std::get_if<input::SampleEvent>(&job.event);
        // A stroke's end (or any other event: they are few) is synced at once; a change of
        // quality may come mid-stroke, while the simulation catches up, and waits with it.
        if (!std::holds_alternative<input::QualityEvent>(job.event)) {
          const bool tip_down = pen && pen->sample.tip_down();
          sync_recording(!tip_down && (tip_was_down_ || !pen));
          tip_was_down_ = tip_down;
        }
      }
    }
    const double elapsed_ms = 1e3 * (now_s() - start);
    {
      std::lock_guard lock(queue_mutex_);
      busy_ = false;
      stats_.last_event_ms = elapsed_ms;
      ++stats_.applied;
      if (session_event) {
        ++stats_.events_since_save;
        ++stats_.events_since_autosave;
      }
      if (!error.empty()) stats_.last_error = error;
      stats_.recording_error = recording_error_;
      busy_window_ms_ += elapsed_ms;
      if (now_s() - window_start_s_ >= 1.0) {
        stats_.busy_ms_per_s = busy_window_ms_ / (now_s() - window_start_s_);
        busy_window_ms_ = 0.0;
        window_start_s_ = now_s();
      }
    }
    queue_changed_.notify_all();
  }
}

void SimWorker::replace_painting(paintcore::Painting painting, SessionRecording recording,
                                 bool unsaved) {
  wait_idle();
  std::lock_guard lock(painting_mutex_);
  player_->finish();
  sync_recording(true);
  painting_ = std::move(painting);
  player_ = std::make_unique<SessionPlayer>(painting_, options_, false);
  start_recording(std::move(recording));
  std::lock_guard queue_lock(queue_mutex_);
  stats_.events_since_save = unsaved ? 1 : 0;
  stats_.events_since_autosave = 0;
  stats_.autosave_error.clear();
}

void SimWorker::save(const std::filesystem::path& file) {
  wait_idle();
  std::lock_guard lock(painting_mutex_);
  player_->finish();
  painting_.save(file);
  mark_saved(file);
  std::lock_guard queue_lock(queue_mutex_);
  stats_.events_since_save = 0;
  stats_.recording_error = recording_error_;
}

SimStats SimWorker::stats() const {
  std::lock_guard lock(queue_mutex_);
  SimStats copy = stats_;
  copy.queued = queue_.size();
  return copy;
}

std::optional<std::filesystem::path> SimWorker::recording_path() const {
  std::lock_guard lock(painting_mutex_);
  if (!recorder_) return std::nullopt;
  return recorder_->path();
}

}  // namespace impasto::session
