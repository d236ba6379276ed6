#include "progress_reporter.hpp"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <string_view>

namespace impasto::app {
namespace {

bool g_quiet = false;

// An automatic report stays silent this long: a short job prints nothing extra.
constexpr double kQuietStartSeconds = 1.0;
// The bar redraws at most this often; lines come at each tenth, at most this often.
constexpr double kBarRedrawSeconds = 0.1;
constexpr double kLineSeconds = 1.0;
constexpr int kBarWidth = 24;

}  // namespace

void set_quiet(bool quiet) {
  g_quiet = quiet;
}

bool quiet() {
  return g_quiet;
}

ProgressStyle progress_style() {
  if (g_quiet) return ProgressStyle::none;
  const char* env = std::getenv("IMPASTO_PROGRESS");
  if (!env || !*env) return ProgressStyle::automatic;
  const std::string_view value(env);
  if (value == "auto") return ProgressStyle::automatic;
  if (value == "bar") return ProgressStyle::bar;
  if (value == "lines") return ProgressStyle::lines;
  if (value == "none") return ProgressStyle::none;
  throw std::runtime_error("IMPASTO_PROGRESS=" + std::string(value) +
                           ": expected auto, bar, lines or none");
}

std::string describe_duration(double seconds) {
  if (!(seconds >= 0.5)) return "<1 s";
  const long whole = std::lround(seconds);
  if (whole < 60) return std::to_string(whole) + " s";
  char text[32];
  std::snprintf(text, sizeof text, "%ld min %02ld s", whole / 60, whole % 60);
  return text;
}

ProgressReporter::ProgressReporter(std::string job, std::string unit)
    : job_(std::move(job)), unit_(std::move(unit)), style_(progress_style()) {
  if (style_ == ProgressStyle::automatic)
    style_ = isatty(STDERR_FILENO) ? ProgressStyle::bar : ProgressStyle::lines;
  // Forced styles (IMPASTO_PROGRESS) show short jobs too; automatic ones wait a second.
  wait_ = progress_style() == ProgressStyle::automatic;
}

ProgressReporter::~ProgressReporter() {
  finish();
}

util::ProgressCallback ProgressReporter::callback() {
  if (style_ == ProgressStyle::none) return {};
  return [this](std::uint64_t done, std::uint64_t total) { update(done, total); };
}

void ProgressReporter::update(std::uint64_t done, std::uint64_t total) {
  if (style_ == ProgressStyle::none) return;
  // Workers that find another one drawing skip: the next update draws their count.
  std::unique_lock lock(mutex_, std::try_to_lock);
  if (!lock.owns_lock() || finished_) return;
  if (done > done_ || total != total_) done_ = done;
  total_ = total;
  draw(done_, total_, false);
}

void ProgressReporter::finish() {
  std::lock_guard lock(mutex_);
  if (finished_) return;
  finished_ = true;
  if (shown_) draw(total_, total_, true);
}

void ProgressReporter::clear() {
  std::lock_guard lock(mutex_);
  if (style_ != ProgressStyle::bar || !shown_ || finished_) return;
  std::fprintf(stderr, "\r\x1b[K");
  std::fflush(stderr);
  last_draw_ = {};  // redraw at the next update
}

void ProgressReporter::draw(std::uint64_t done, std::uint64_t total, bool last) {
  const auto now = Clock::now();
  const double elapsed = std::chrono::duration<double>(now - start_).count();
  if (!last && wait_ && elapsed < kQuietStartSeconds) return;
  const double since_draw = std::chrono::duration<double>(now - last_draw_).count();
  const double share = total > 0 ? std::min(1.0, double(done) / double(total)) : 0.0;
  const int tenth = static_cast<int>(share * 10.0);
  if (!last) {
    if (style_ == ProgressStyle::bar && since_draw < kBarRedrawSeconds) return;
    if (style_ == ProgressStyle::lines &&
        (tenth == last_tenth_ || (shown_ && since_draw < kLineSeconds)))
      return;
  }
  last_draw_ = now;
  last_tenth_ = tenth;
  shown_ = true;
  const double rate = elapsed > 0 ? double(done) / elapsed : 0.0;
  char rate_text[48];
  std::snprintf(rate_text, sizeof rate_text, "%.4g %s/s", rate, unit_.c_str());
  std::string text = job_;
  if (style_ == ProgressStyle::bar) {
    const int filled = static_cast<int>(share * kBarWidth);
    text += " [" + std::string(filled, '#') + std::string(kBarWidth - filled, '-') + "]";
  } else {
    text += ":";
  }
  char head[96];
  std::snprintf(head, sizeof head, " %3d%% %llu/%llu %s, ", static_cast<int>(share * 100.0),
                static_cast<unsigned long long>(done), static_cast<unsigned long long>(total),
                unit_.c_str());
  text += head;
  text += rate_text;
  if (last) {
    char took[32];
    std::snprintf(took, sizeof took, ", done in %.1f s", elapsed);
    text += took;
  } else if (rate > 0) {
    text += ", " + describe_duration(double(total - std::min(done, total)) / rate) + " left";
  }
  if (style_ == ProgressStyle::bar) {
    std::fprintf(stderr, "\r%s\x1b[K%s", text.c_str(), last ? "\n" : "");
  } else {
    std::fprintf(stderr, "%s\n", text.c_str());
  }
  std::fflush(stderr);
}

}  // namespace impasto::app
