#pragma once
// The lines in which the painting window prints, at exit, how long the user waited for each
// kind of input it timed, and which `impasto bench window` reads back: one source for their
// wording. A line is
//   "<kind> latency (<event> to the swap showing it): median M ms, 95th percentile P ms over
//    N <events>"
// and the view's motion frames one more: the coarse ones (ShadedViewCache::Detail::kCoarse)
// and how far apart the frames that showed a motion came while it went on (one drag's moves
// wait for the frame under way, then their own):
//   "view motion: C coarse frames, median factor F; frames I ms apart while moving (median)".
#include <optional>
#include <string>
#include <string_view>

namespace impasto::app {

struct LatencyFigures {
  double median_ms = 0, p95_ms = 0;
  int events = 0;
};

// kind: "input" (pen samples), "zoom", "rotation", "pan", "light"; event: what one is ("wheel
// click"); events: what they are called counted ("clicks").
std::string latency_line(std::string_view kind, std::string_view event, std::string_view events,
                         const LatencyFigures& figures);
// The figures of the first line of that kind in `printed`; none if there is none.
std::optional<LatencyFigures> find_latency_line(std::string_view printed, std::string_view kind);

struct MotionFrames {
  int coarse = 0, median_factor = 0;
  double interval_ms = 0;  // 0: no two frames in a row showed a motion
};
std::string motion_frames_line(const MotionFrames& frames);
std::optional<MotionFrames> find_motion_frames_line(std::string_view printed);

}  // namespace impasto::app
