#pragma once
// File > Export time-lapse...: a recorded session's growth as a video, from the window (the
// command line's `impasto timelapse`, through the same timelapse_video.hpp). The dialog
// chooses the session (this window's, or one offered for recovery), the file and its format,
// the frame size, the pace, and whether the light turns; the window's light and surface shade
// it. The video is written on a thread of its own, with one core, while the painting goes on;
// a small window shows its progress and can stop it (no file is left then).
#include <array>
#include <atomic>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "impasto/render/render_settings.hpp"
#include "impasto/session/timelapse.hpp"
#include "timelapse_video.hpp"
#include "window/notifications.hpp"
#include "window/window_state.hpp"

namespace impasto::app::window {

// A session that can be played: its label in the dialog and its recording.
struct TimelapseSource {
  std::string label;
  std::filesystem::path recording;
};

enum class VideoFormat { kMp4, kWebm, kGif };

// The dialog's fields as the user left them.
struct TimelapseChoice {
  std::size_t source = 0;  // into the sources the dialog lists
  std::string stem;        // the video's path less its suffix
  VideoFormat format = VideoFormat::kMp4;
  int width = 0, height = 0;  // pixels (even); the canvas's cells when opened
  double seconds = 10.0, fps = 30.0, hold_seconds = 2.0;
  bool real_time = false;
  bool turn_light = false;
  double turn_to_deg = 0.0;  // the light's azimuth at the last frame, when it turns
};

// What a time-lapse is made from: the recording's text as it was when asked (the window may
// go on recording), the video's file, and the options `impasto timelapse` would take.
struct TimelapseRequest {
  input::StrokeFile strokes;
  std::filesystem::path out;
  session::TimelapseOptions options;
  std::optional<CanvasSize> frame_size;
};

// The request for `choice`, shaded under `settings` (the window's light and surface) on one
// thread. Reads the chosen recording; throws std::runtime_error naming it when it cannot.
TimelapseRequest timelapse_request(const TimelapseChoice& choice,
                                   const std::vector<TimelapseSource>& sources,
                                   const render::RenderSettings& settings);

// "PATH.mp4" (".webm", ".gif") for the choice's stem and format.
std::filesystem::path timelapse_file(const TimelapseChoice& choice);

// A time-lapse being written on a thread of its own.
class TimelapseJob {
 public:
  explicit TimelapseJob(TimelapseRequest request);
  ~TimelapseJob();  // stops it (no file is left) and waits
  TimelapseJob(const TimelapseJob&) = delete;
  TimelapseJob& operator=(const TimelapseJob&) = delete;

  double fraction_done() const { return fraction_.load(); }
  void stop() { stop_ = true; }
  bool finished() const { return finished_.load(); }
  // Once finished: what was written (as the command line says it), or why not; warnings.
  const std::string& outcome() const { return outcome_; }
  bool succeeded() const { return succeeded_; }
  const std::vector<std::string>& warnings() const { return warnings_; }
  const std::filesystem::path& out() const { return request_.out; }

 private:
  void run();

  TimelapseRequest request_;
  std::atomic<double> fraction_{0.0};
  std::atomic<bool> stop_{false}, finished_{false};
  std::string outcome_;  // written by the thread before finished_ turns true
  bool succeeded_ = false;
  std::vector<std::string> warnings_;
  std::thread thread_;
};

class Document;

class TimelapseExport {
 public:
  // One frame of it: opens the dialog when state.timelapse_requested (its first fields from
  // the canvas's size, the painting's file and the light, which if it turns turns half a
  // circle), draws it over the document's sessions, starts the job on Export once the
  // document's worker has recorded every event it applied, and shows a running job's
  // progress; what a finished job did goes to state.notifications.
  void draw(WindowState& state, Document& document, int canvas_width, int canvas_height);
  bool running() const { return job_ != nullptr; }
  // The window is about to quit: while a time-lapse is being written, asks first (Stop it and
  // quit, or keep working) and returns false; true when the window may quit now.
  bool allow_quit();
  // The answer, drawn in draw(): sets state.quit when the painter chose to stop and quit.

 private:
  void open(const WindowState& state, int canvas_width, int canvas_height);
  void draw_job(Notifications& notes);
  // The choice in the frame the dialog's Export button is pressed.
  std::optional<TimelapseChoice> draw_dialog(const std::vector<TimelapseSource>& sources);

  void draw_quit_question(WindowState& state);

  bool open_ = false;
  bool ask_quit_ = false;     // the question is up
  bool quit_agreed_ = false;  // stop and quit was chosen: the next allow_quit lets it through
  TimelapseChoice choice_;
  std::array<char, 512> stem_{};
  std::unique_ptr<TimelapseJob> job_;
};

}  // namespace impasto::app::window
