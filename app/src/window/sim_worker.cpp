#include "window/sim_worker.hpp"

#include <chrono>
#include <variant>

namespace impasto::app::window {
namespace {

double now_s() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

}  // namespace

SimWorker::SimWorker(paintcore::Painting painting, std::optional<std::filesystem::path> record_to)
    : painting_(std::move(painting)) {
  player_ = std::make_unique<SessionPlayer>(painting_, options_, false);
  start_recording(record_to);
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
}

void SimWorker::start_recording(const std::optional<std::filesystem::path>& record_to) {
  recorder_.reset();
  if (!record_to) return;
  recorder_ = std::make_unique<input::StrokeRecorder>(*record_to);
  // The session starts from this canvas and brush: write them so the file replays alone.
  const auto& spec = painting_.canvas().spec();
  recorder_->record(input::CanvasEvent{spec.width_cells, spec.height_cells, spec.dpi});
  if (!painting_.brush().empty()) {
    const auto& brush = painting_.brush().settings();
    recorder_->record(input::BrushEvent{brush.head, brush.size_mm, brush.stiffness, {}});
  }
}

void SimWorker::submit(input::StrokeEvent event) {
  {
    std::lock_guard lock(queue_mutex_);
    ++stats_.submitted;
    queue_.push_back({std::move(event), std::nullopt, false});
  }
  queue_changed_.notify_all();
}

void SimWorker::set_auto_load(bool auto_load) {
  {
    std::lock_guard lock(queue_mutex_);
    ++stats_.submitted;
    queue_.push_back({input::ToolEvent{"brush"}, auto_load, false});
  }
  queue_changed_.notify_all();
}

void SimWorker::finish_stroke() {
  {
    std::lock_guard lock(queue_mutex_);
    ++stats_.submitted;
    queue_.push_back({input::ToolEvent{"brush"}, std::nullopt, true});
  }
  queue_changed_.notify_all();
}

void SimWorker::wait_idle() {
  std::unique_lock lock(queue_mutex_);
  queue_changed_.wait(lock, [&] { return queue_.empty() && !busy_; });
}

bool SimWorker::idle() const {
  std::lock_guard lock(queue_mutex_);
  return queue_.empty() && !busy_;
}

void SimWorker::run() {
  for (;;) {
    Job job;
    {
      std::unique_lock lock(queue_mutex_);
      queue_changed_.wait(lock, [&] { return stopping_ || !queue_.empty(); });
      if (queue_.empty()) return;  // stopping with nothing left to do
      job = std::move(queue_.front());
      queue_.pop_front();
      busy_ = true;
    }
    const double start = now_s();
    std::string error;
    {
      std::lock_guard lock(painting_mutex_);
      if (job.finish) {
        player_->finish();
      } else if (job.auto_load) {
        player_->finish();
        player_ = std::make_unique<SessionPlayer>(painting_, options_, *job.auto_load);
      } else {
        try {
          if (recorder_) recorder_->record(job.event);
          player_->apply(job.event);
        } catch (const std::exception& e) {
          error = e.what();
        }
      }
    }
    const double elapsed_ms = 1e3 * (now_s() - start);
    {
      std::lock_guard lock(queue_mutex_);
      busy_ = false;
      stats_.last_event_ms = elapsed_ms;
      ++stats_.applied;
      if (!job.auto_load && !job.finish) ++stats_.events_since_save;
      if (!error.empty()) stats_.last_error = error;
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

void SimWorker::replace_painting(paintcore::Painting painting,
                                 std::optional<std::filesystem::path> record_to) {
  wait_idle();
  std::lock_guard lock(painting_mutex_);
  player_->finish();
  painting_ = std::move(painting);
  player_ = std::make_unique<SessionPlayer>(painting_, options_, false);
  start_recording(record_to);
  std::lock_guard queue_lock(queue_mutex_);
  stats_.events_since_save = 0;
}

void SimWorker::save(const std::filesystem::path& file) {
  wait_idle();
  std::lock_guard lock(painting_mutex_);
  player_->finish();
  painting_.save(file);
  std::lock_guard queue_lock(queue_mutex_);
  stats_.events_since_save = 0;
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

}  // namespace impasto::app::window
