#include "window/timelapse_export.hpp"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <utility>

#include "impasto/files/memory_budget.hpp"
#include "impasto/files/message_text.hpp"
#include "impasto/input/stroke_file.hpp"
#include "window/document.hpp"
#include "window/imgui_layout.hpp"

namespace impasto::app::window {
namespace {

constexpr std::array<const char*, 3> kSuffixes = {".mp4", ".webm", ".gif"};

// Thrown from the progress callback when the user stops the job.
struct Stopped {};

int even(int pixels) {
  return std::max(2, pixels - pixels % 2);
}

}  // namespace

std::filesystem::path timelapse_file(const TimelapseChoice& choice) {
  return choice.stem + kSuffixes[static_cast<std::size_t>(choice.format)];
}

TimelapseRequest timelapse_request(const TimelapseChoice& choice,
                                   const std::vector<TimelapseSource>& sources,
                                   const render::RenderSettings& settings) {
  if (choice.source >= sources.size()) throw std::runtime_error("time-lapse: no such session");
  const std::filesystem::path& recording = sources[choice.source].recording;
  std::ifstream in(recording, std::ios::binary);
  if (!in) throw std::runtime_error("cannot read " + recording.string());
  // Read whole now: the window goes on recording into it.
  std::stringstream text;
  text << in.rdbuf();
  TimelapseRequest request;
  request.strokes = input::parse_strokes(text, recording.string());
  request.out = timelapse_file(choice);
  request.options.fps = choice.fps;
  request.options.growth_seconds = choice.seconds;
  request.options.real_time = choice.real_time;
  request.options.hold_seconds = choice.hold_seconds;
  request.options.settings = settings;
  request.options.settings.threads = 1;  // the window's simulation keeps the other core
  if (choice.turn_light) request.options.light_azimuth_end_deg = choice.turn_to_deg;
  request.frame_size = CanvasSize{choice.width, choice.height};
  return request;
}

TimelapseJob::TimelapseJob(TimelapseRequest request)
    : request_(std::move(request)), thread_([this] { run(); }) {}

TimelapseJob::~TimelapseJob() {
  stop_ = true;
  thread_.join();
}

void TimelapseJob::run() {
  try {
    request_.options.progress = [this](std::size_t done, std::size_t total) {
      if (stop_) throw Stopped{};
      fraction_ = total > 0 ? static_cast<double>(done) / static_cast<double>(total) : 1.0;
    };
    session::ReplayOptions replay;
    replay.threads = 1;
    const TimelapseVideo video = write_timelapse_video(request_.strokes, replay, request_.options,
                                                       request_.out, request_.frame_size);
    warnings_ = video.report.warnings;
    outcome_ = timelapse_summary(video, request_.out, request_.options.fps);
    succeeded_ = true;
  } catch (const Stopped&) {
    outcome_ = "time-lapse stopped: " + request_.out.string() + " was not written";
  } catch (const std::exception& e) {
    outcome_ = "time-lapse not written: " + files::error_text(e);
  }
  finished_ = true;
}

void TimelapseExport::draw(WindowState& state, Document& document, int canvas_width,
                           int canvas_height) {
  if (std::exchange(state.timelapse_requested, false)) open(state, canvas_width, canvas_height);
  draw_job(state.notifications);
  draw_quit_question(state);
  if (!open_) return;
  const std::vector<TimelapseSource> sources = document.timelapse_sources();
  const std::optional<TimelapseChoice> choice = draw_dialog(sources);
  if (!choice) return;
  document.worker().wait_idle();  // every event applied so far is in the recording
  try {
    job_ = std::make_unique<TimelapseJob>(timelapse_request(*choice, sources, state.settings));
  } catch (const std::exception& e) {
    state.notifications.error("time-lapse not written: " + files::error_text(e));
  }
}

void TimelapseExport::open(const WindowState& state, int canvas_width, int canvas_height) {
  const std::optional<std::filesystem::path>& painting_file = state.file;
  open_ = true;
  choice_.turn_to_deg = std::fmod(state.settings.light_azimuth_deg + 180.0, 360.0);
  choice_.source = 0;
  choice_.width = even(canvas_width);
  choice_.height = even(canvas_height);
  const std::string stem = painting_file
                               ? (painting_file->parent_path() / painting_file->stem()).string()
                               : std::string("painting");
  std::snprintf(stem_.data(), stem_.size(), "%s", (stem + "-timelapse").c_str());
}

bool TimelapseExport::allow_quit() {
  if (!job_ || quit_agreed_) return true;
  ask_quit_ = true;
  return false;
}

void TimelapseExport::draw_quit_question(WindowState& state) {
  if (!ask_quit_) return;
  if (!job_) {  // it finished while the question was up
    ask_quit_ = false;
    state.quit = true;
    return;
  }
  if (!ImGui::IsPopupOpen("Quit while writing a time-lapse?")) {
    ImGui::OpenPopup("Quit while writing a time-lapse?");
  }
  if (!ImGui::BeginPopupModal("Quit while writing a time-lapse?", nullptr,
                              ImGuiWindowFlags_AlwaysAutoResize))
    return;
  ImGui::Text("%s is %d %% written; quitting stops it and leaves no file.",
              files::terminal_text(job_->out().filename().string()).c_str(),
              static_cast<int>(100.0 * job_->fraction_done()));
  if (ImGui::Button("Stop it and quit")) {
    job_->stop();
    quit_agreed_ = true;
    ask_quit_ = false;
    state.quit = true;
    ImGui::CloseCurrentPopup();
  }
  ImGui::SameLine();
  if (ImGui::Button("Keep working") || ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape))) {
    ask_quit_ = false;
    ImGui::CloseCurrentPopup();
  }
  ImGui::EndPopup();
}

void TimelapseExport::draw_job(Notifications& notes) {
  if (job_) {
    if (job_->finished()) {
      for (const auto& warning : job_->warnings()) notes.warning(warning);
      if (job_->succeeded()) {
        notes.info(job_->outcome());
      } else {
        notes.error(job_->outcome());
      }
      job_.reset();
    } else {
      ImGui::SetNextWindowPos(ImVec2(ImGui::GetMainViewport()->GetCenter().x, 40.0f),
                              ImGuiCond_Appearing, ImVec2(0.5f, 0.0f));
      ImGui::Begin("Time-lapse", nullptr,
                   ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_AlwaysAutoResize);
      ImGui::Text("Writing %s", files::terminal_text(job_->out().string()).c_str());
      ImGui::ProgressBar(static_cast<float>(job_->fraction_done()), ImVec2(320, 0));
      if (ImGui::Button("Stop")) job_->stop();
      ImGui::End();
    }
  }
}

std::optional<TimelapseChoice> TimelapseExport::draw_dialog(
    const std::vector<TimelapseSource>& sources) {
  const bool start = action_dialog("Export time-lapse", "Export", open_, [&] {
    if (sources.empty()) {
      ImGui::TextWrapped("This session is not recorded, and no other session is offered.");
      return false;
    }
    choice_.source = std::min(choice_.source, sources.size() - 1);
    if (ImGui::BeginCombo("session", sources[choice_.source].label.c_str())) {
      for (std::size_t i = 0; i < sources.size(); ++i) {
        ImGui::PushID(static_cast<int>(i));
        if (ImGui::Selectable(sources[i].label.c_str(), i == choice_.source)) choice_.source = i;
        ImGui::PopID();
      }
      ImGui::EndCombo();
    }
    ImGui::InputText("file (stem)", stem_.data(), stem_.size());
    choice_.stem = stem_.data();
    int format = static_cast<int>(choice_.format);
    ImGui::RadioButton("MP4 (H.264)", &format, 0);
    ImGui::SameLine();
    ImGui::RadioButton("WebM (VP9)", &format, 1);
    ImGui::SameLine();
    ImGui::RadioButton("GIF", &format, 2);
    choice_.format = static_cast<VideoFormat>(format);
    ImGui::InputInt("width (pixels)", &choice_.width, 2, 64);
    ImGui::InputInt("height (pixels)", &choice_.height, 2, 64);
    choice_.width = even(std::clamp(choice_.width, 2, 7680));
    choice_.height = even(std::clamp(choice_.height, 2, 4320));
    ImGui::Checkbox("at the session's own pace", &choice_.real_time);
    ImGui::BeginDisabled(choice_.real_time);
    ImGui::InputDouble("growth (s)", &choice_.seconds, 1.0, 10.0, "%.1f");
    ImGui::EndDisabled();
    choice_.seconds = std::clamp(choice_.seconds, 0.1, 3600.0);
    ImGui::InputDouble("frames a second", &choice_.fps, 1.0, 10.0, "%.0f");
    choice_.fps = std::clamp(choice_.fps, 1.0, 120.0);
    ImGui::InputDouble("finished painting held (s)", &choice_.hold_seconds, 0.5, 2.0, "%.1f");
    choice_.hold_seconds = std::clamp(choice_.hold_seconds, 0.0, 600.0);
    ImGui::Checkbox("the light turns, to azimuth", &choice_.turn_light);
    ImGui::SameLine();
    ImGui::BeginDisabled(!choice_.turn_light);
    ImGui::SetNextItemWidth(90);
    ImGui::InputDouble("deg", &choice_.turn_to_deg, 15.0, 90.0, "%.0f");
    ImGui::EndDisabled();
    choice_.turn_to_deg = std::clamp(choice_.turn_to_deg, -3600.0, 3600.0);
    ImGui::TextWrapped(
        "Under the window's light and surface. Written with one core while you paint on.");
    return !choice_.stem.empty() && !job_;
  });
  if (!start) return std::nullopt;
  return choice_;
}

}  // namespace impasto::app::window
