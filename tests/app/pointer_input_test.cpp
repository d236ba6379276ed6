// The painting window's mouse path without a window: events queued as GLFW's callbacks
// deliver them (pointer_events), applied in order by PointerGestures, fed as pen samples
// through session::PenFeed (whose sink is the simulation's queue in the window), and the latency
// measure of the status bar.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <variant>
#include <vector>

#include "impasto/session/pen_feed.hpp"
#include "latency_lines.hpp"
#include "window/pointer_events.hpp"
#include "window/pointer_gestures.hpp"
#include "window/pointer_latency.hpp"
#include "window/pointer_server_times.hpp"

namespace impasto::app::window {
namespace {

constexpr double kMmPerPixel = 0.1;

// The window's mouse path with the identity view: window pixel (x, y) is canvas
// (x, y) * kMmPerPixel. Records what the simulation would be sent.
struct MousePath {
  std::vector<paintcore::PenSample> sent;
  session::PenFeed feed{[this](input::StrokeEvent event) {
    sent.push_back(std::get<input::SampleEvent>(event).sample);
  }};
  double pan_dx = 0, pan_dy = 0;
  std::vector<double> rotation_times;  // of each rotating move
  PointerGestures gestures{{
      [this](const PointerEvent& at, bool tip_down) {
        paintcore::PenSample s;
        s.x_mm = at.x * kMmPerPixel;
        s.y_mm = at.y * kMmPerPixel;
        s.time_s = at.time_s;
        s.pressure = tip_down ? 0.6f : 0.0f;
        s.buttons = paintcore::kPenInRange | (tip_down ? paintcore::kPenTip : 0u);
        feed.feed(s);
      },
      [this](double fx, double fy, double tx, double ty, double) {
        pan_dx += tx - fx;
        pan_dy += ty - fy;
      },
      [this](double, double, double, double, double time_s) { rotation_times.push_back(time_s); },
  }};
};

struct Stroke {
  std::vector<paintcore::PenSample> down;  // tip-down samples
  paintcore::PenSample end;                // the tip-up sample that ended it
};

// Splits the samples sent into strokes: each begins with a tip-down sample after a tip-up
// one (or the first) and ends with a tip-up sample. Fails the test on a sample that is
// neither (a hovering sample should never be sent).
std::vector<Stroke> strokes_of(const std::vector<paintcore::PenSample>& sent) {
  std::vector<Stroke> strokes;
  bool open = false;
  for (const auto& s : sent) {
    if (s.tip_down()) {
      if (!open) strokes.emplace_back();
      strokes.back().down.push_back(s);
      open = true;
    } else {
      EXPECT_TRUE(open) << "a tip-up sample outside a stroke at t=" << s.time_s;
      if (open) strokes.back().end = s;
      open = false;
    }
  }
  EXPECT_FALSE(open) << "the last stroke was not ended";
  return strokes;
}

TEST(PointerEventQueue, KeepsEveryEventInOrderWithItsTime) {
  PointerEventQueue queue;
  queue.set_position(10, 20);
  queue.button(kLeftButton, true, 1.000);
  queue.moved(11, 21, 1.001);
  queue.moved(12, 23, 1.002);
  queue.button(kLeftButton, false, 1.003);
  queue.button(kMiddleButton, true, 1.004);
  ASSERT_EQ(queue.size(), 5u);
  const std::vector<PointerEvent> events = queue.take();
  ASSERT_EQ(events.size(), 5u);
  EXPECT_EQ(queue.size(), 0u);
  EXPECT_TRUE(queue.take().empty());

  const PointerAction actions[] = {PointerAction::kPress, PointerAction::kMove,
                                   PointerAction::kMove, PointerAction::kRelease,
                                   PointerAction::kPress};
  const int buttons[] = {kLeftButton, -1, -1, kLeftButton, kMiddleButton};
  // A button event carries no position: it happened where the cursor last was.
  const double xs[] = {10, 11, 12, 12, 12}, ys[] = {20, 21, 23, 23, 23};
  const double times[] = {1.000, 1.001, 1.002, 1.003, 1.004};
  for (std::size_t i = 0; i < events.size(); ++i) {
    EXPECT_EQ(events[i].action, actions[i]) << i;
    EXPECT_EQ(events[i].button, buttons[i]) << i;
    EXPECT_EQ(events[i].x, xs[i]) << i;
    EXPECT_EQ(events[i].y, ys[i]) << i;
    EXPECT_EQ(events[i].time_s, times[i]) << i;
  }
}

TEST(PointerEventQueue, HoldsTimeThatWentBackwardsAtTheLastTime) {
  PointerEventQueue queue;
  queue.moved(1, 1, 2.0);
  queue.moved(2, 2, 1.5);
  const auto events = queue.take();
  ASSERT_EQ(events.size(), 2u);
  EXPECT_EQ(events[1].time_s, 2.0);
  EXPECT_EQ(events[1].x, 2.0);
}

TEST(PointerGestures, ReleaseMovePressWithinOneFrameMakesTwoStrokesWithNothingBetween) {
  PointerEventQueue queue;
  queue.set_position(100, 100);
  queue.button(kLeftButton, true, 0.010);
  queue.moved(120, 100, 0.011);
  queue.moved(140, 100, 0.012);
  queue.button(kLeftButton, false, 0.013);
  // Between the strokes the cursor crosses the canvas with the button up.
  queue.moved(200, 150, 0.014);
  queue.moved(300, 200, 0.015);
  queue.button(kLeftButton, true, 0.016);
  queue.moved(320, 200, 0.017);
  queue.button(kLeftButton, false, 0.018);

  MousePath path;
  path.gestures.apply(queue.take(), PointerFrame{});  // all of it in one frame
  const std::vector<Stroke> strokes = strokes_of(path.sent);
  ASSERT_EQ(strokes.size(), 2u);
  ASSERT_EQ(strokes[0].down.size(), 3u);
  ASSERT_EQ(strokes[1].down.size(), 2u);
  EXPECT_DOUBLE_EQ(strokes[0].down.front().x_mm, 100 * kMmPerPixel);
  EXPECT_DOUBLE_EQ(strokes[0].end.x_mm, 140 * kMmPerPixel);
  EXPECT_DOUBLE_EQ(strokes[0].end.time_s, 0.013);
  // The second stroke starts where the button went down, not where the first one ended.
  EXPECT_DOUBLE_EQ(strokes[1].down.front().x_mm, 300 * kMmPerPixel);
  EXPECT_DOUBLE_EQ(strokes[1].down.front().y_mm, 200 * kMmPerPixel);
  EXPECT_DOUBLE_EQ(strokes[1].down.front().time_s, 0.016);
  for (const auto& s : path.sent) {
    EXPECT_FALSE(s.x_mm > 140 * kMmPerPixel && s.x_mm < 300 * kMmPerPixel)
        << "a sample joins the strokes at x=" << s.x_mm;
  }
  EXPECT_FALSE(path.gestures.painting());
}

TEST(PointerGestures, FastCircleWithinOneFrameReachesTheFeedAsEverySample) {
  // 360 moves around a 200 px circle, all delivered before one frame.
  constexpr int kMoves = 360;
  constexpr double kCx = 400, kCy = 300, kR = 200;
  PointerEventQueue queue;
  queue.set_position(kCx + kR, kCy);
  queue.button(kLeftButton, true, 5.0);
  for (int i = 1; i <= kMoves; ++i) {
    const double a = 2.0 * std::numbers::pi * i / kMoves;
    queue.moved(kCx + kR * std::cos(a), kCy + kR * std::sin(a), 5.0 + 1e-4 * i);
  }
  queue.button(kLeftButton, false, 5.0 + 1e-4 * (kMoves + 1));
  const std::size_t events = queue.size();

  MousePath path;
  path.gestures.apply(queue.take(), PointerFrame{});
  ASSERT_EQ(path.sent.size(), events);  // the press, every move and the release
  EXPECT_EQ(path.feed.fed(), events);
  const std::vector<Stroke> strokes = strokes_of(path.sent);
  ASSERT_EQ(strokes.size(), 1u);
  double worst_radial_mm = 0.0, last_time = -1.0;
  for (const auto& s : path.sent) {
    const double r = std::hypot(s.x_mm - kCx * kMmPerPixel, s.y_mm - kCy * kMmPerPixel);
    worst_radial_mm = std::max(worst_radial_mm, std::abs(r - kR * kMmPerPixel));
    EXPECT_GT(s.time_s, last_time);  // each sample keeps its own time
    last_time = s.time_s;
  }
  EXPECT_LT(worst_radial_mm, 1e-9);
}

TEST(PointerGestures, PressOnThePanelsDoesNotPaintAndItsDragStaysTheirs) {
  PointerFrame frame;
  frame.canvas_at = [](double x, double) { return x < 500; };  // a panel right of x = 500
  PointerEventQueue queue;
  queue.set_position(600, 100);
  queue.button(kLeftButton, true, 1.0);
  queue.moved(300, 100, 1.1);  // dragging a slider out over the canvas
  queue.button(kLeftButton, false, 1.2);
  queue.button(kLeftButton, true, 1.3);  // a press on the canvas paints
  queue.moved(310, 100, 1.4);
  queue.button(kLeftButton, false, 1.5);
  MousePath path;
  path.gestures.apply(queue.take(), frame);
  const std::vector<Stroke> strokes = strokes_of(path.sent);
  ASSERT_EQ(strokes.size(), 1u);
  EXPECT_DOUBLE_EQ(strokes[0].down.front().time_s, 1.3);
}

TEST(PointerGestures, NearTabletOrSpaceKeepsTheMouseFromPainting) {
  PointerEventQueue queue;
  queue.set_position(100, 100);
  queue.button(kLeftButton, true, 1.0);
  queue.moved(150, 120, 1.1);
  queue.button(kLeftButton, false, 1.2);
  const std::vector<PointerEvent> drag = queue.take();

  MousePath near_tablet;
  PointerFrame tablet_frame;
  tablet_frame.tablet_near = true;
  near_tablet.gestures.apply(drag, tablet_frame);
  EXPECT_TRUE(near_tablet.sent.empty());

  MousePath with_space;
  PointerFrame space_frame;
  space_frame.space_down = true;
  with_space.gestures.apply(drag, space_frame);
  EXPECT_TRUE(with_space.sent.empty());
  EXPECT_DOUBLE_EQ(with_space.pan_dx, 50);
  EXPECT_DOUBLE_EQ(with_space.pan_dy, 20);
}

TEST(PointerGestures, MiddlePansAndRightRotatesWithEveryMove) {
  PointerEventQueue queue;
  queue.set_position(0, 0);
  queue.button(kMiddleButton, true, 1.0);
  for (int i = 1; i <= 10; ++i) queue.moved(3.0 * i, -2.0 * i, 1.0 + 0.001 * i);
  queue.button(kMiddleButton, false, 1.1);
  queue.button(kRightButton, true, 1.2);
  for (int i = 1; i <= 7; ++i) queue.moved(30 + i, -20, 1.2 + 0.001 * i);
  queue.button(kRightButton, false, 1.3);
  MousePath path;
  path.gestures.apply(queue.take(), PointerFrame{});
  EXPECT_TRUE(path.sent.empty());
  EXPECT_DOUBLE_EQ(path.pan_dx, 30);
  EXPECT_DOUBLE_EQ(path.pan_dy, -20);
  // Each rotating move with its own time (the view's latency counts from it).
  ASSERT_EQ(path.rotation_times.size(), 7u);
  for (int i = 1; i <= 7; ++i) EXPECT_DOUBLE_EQ(path.rotation_times[i - 1], 1.2 + 0.001 * i);
}

TEST(SpeedPressure, UsesTheSamplesOwnTimes) {
  // 150 mm/s, sampled every 2 ms: pressure 1 - 150/375 = 0.6 once the window has filled.
  SpeedPressure steady;
  float pressure = 1.0f;
  for (int i = 0; i <= 100; ++i) pressure = steady.at(0.3 * i, 0.0, 0.002 * i);
  EXPECT_NEAR(steady.speed_mm_s(), 150.0, 1e-6);
  EXPECT_NEAR(pressure, 0.6f, 1e-5);

  // The same path delivered in bursts (a frame's events arriving together, 16 ms apart):
  // the speed is still the path over the time it took, not over the microseconds between
  // the samples of a burst.
  SpeedPressure bursts;
  for (int frame = 0; frame < 12; ++frame) {
    for (int i = 0; i < 8; ++i) {
      const int n = frame * 8 + i;
      pressure = bursts.at(0.3 * n, 0.0, 0.016 * frame + 1e-6 * i);
    }
  }
  EXPECT_NEAR(bursts.speed_mm_s(), 150.0, 15.0);
  EXPECT_GT(pressure, 0.5f);

  // At rest: full pressure.
  SpeedPressure rest;
  for (int i = 0; i < 50; ++i) pressure = rest.at(1.0, 1.0, 0.002 * i);
  EXPECT_FLOAT_EQ(pressure, 1.0f);
}

TEST(CatchUp, FastFromFallingBehindUntilCaughtUp) {
  using paintcore::StepQuality;
  CatchUp catch_up;
  EXPECT_EQ(catch_up.next(StepQuality::balanced, true, 20.0), StepQuality::balanced);
  EXPECT_EQ(catch_up.next(StepQuality::balanced, true, 120.0), StepQuality::balanced);
  EXPECT_EQ(catch_up.next(StepQuality::balanced, true, 160.0), StepQuality::fast);
  EXPECT_TRUE(catch_up.catching_up());
  // Between the thresholds it keeps catching up...
  EXPECT_EQ(catch_up.next(StepQuality::balanced, true, 80.0), StepQuality::fast);
  // ...until the screen is back within 50 ms.
  EXPECT_EQ(catch_up.next(StepQuality::balanced, true, 40.0), StepQuality::balanced);
  EXPECT_FALSE(catch_up.catching_up());
  // Exact is the chosen level again once caught up; turned off, it never leaves it.
  EXPECT_EQ(catch_up.next(StepQuality::exact, true, 400.0), StepQuality::fast);
  EXPECT_EQ(catch_up.next(StepQuality::exact, true, 10.0), StepQuality::exact);
  EXPECT_EQ(catch_up.next(StepQuality::exact, false, 400.0), StepQuality::exact);
  EXPECT_FALSE(catch_up.catching_up());
  // Fast chosen: nothing to catch up with.
  EXPECT_EQ(catch_up.next(StepQuality::fast, true, 400.0), StepQuality::fast);
  EXPECT_FALSE(catch_up.catching_up());
}

TEST(InputLatency, MeasuresFromEachSamplesTimeToTheFirstSwapAfterItWasApplied) {
  InputLatency latency(4);
  EXPECT_FALSE(latency.recent_median_ms());
  latency.submitted(3, 1.000);
  latency.submitted(4, 1.002);
  latency.submitted(7, 1.004);
  latency.shown(2, 1.010);  // applied before any of them: nothing shown yet
  EXPECT_EQ(latency.shown_count(), 0u);
  latency.shown(4, 1.020);  // jobs 3 and 4
  EXPECT_EQ(latency.shown_count(), 2u);
  EXPECT_EQ(latency.waiting(), 1u);
  latency.shown(9, 1.034);  // job 7
  EXPECT_EQ(latency.shown_count(), 3u);
  EXPECT_NEAR(*latency.recent_median_ms(), 20.0, 1e-9);  // 20, 18, 30 ms
  EXPECT_NEAR(*latency.percentile_ms(1.0), 30.0, 1e-9);
  EXPECT_NEAR(*latency.percentile_ms(0.0), 18.0, 1e-9);
  // Only the last `recent` count in the median.
  for (int i = 0; i < 4; ++i) latency.submitted(10 + i, 2.0);
  latency.shown(20, 2.005);
  EXPECT_NEAR(*latency.recent_median_ms(), 5.0, 1e-9);
  EXPECT_EQ(latency.shown_count(), 7u);
}

// The status bar's figures count every sample from its own event, queued or not, and say how
// far the screen is behind while samples wait.
TEST(InputLatency, SaysHowFarTheScreenIsBehindThePen) {
  InputLatency latency(100);
  EXPECT_EQ(pen_to_screen_text(-1.0, -1.0, 0.0), "pen to screen: paint to measure");
  EXPECT_EQ(latency.behind_ms(5.0), 0.0);
  // 20 samples 8 ms apart; the simulation falls behind: each is shown later than the last.
  for (int i = 0; i < 20; ++i) latency.submitted(i + 1, 1.0 + 0.008 * i);
  EXPECT_NEAR(latency.behind_ms(1.5), 500.0, 1e-9);  // the first sample, 1.0 s, not yet shown
  for (int i = 0; i < 10; ++i) latency.shown(i + 1, 1.02 + 0.02 * i);  // 20 ms, then + 12 each
  EXPECT_NEAR(latency.behind_ms(1.3), 1e3 * (1.3 - 1.08), 1e-9);       // sample 11, at 1.08 s
  for (int i = 10; i < 20; ++i) latency.shown(i + 1, 1.02 + 0.02 * i);
  EXPECT_EQ(latency.behind_ms(2.0), 0.0);
  // Shown 20, 32, ..., 248 ms after their events (nearest ranks: the 11th and the 19th).
  EXPECT_NEAR(*latency.recent_median_ms(), 140.0, 1e-6);
  EXPECT_NEAR(*latency.recent_percentile_ms(0.95), 236.0, 1e-6);
  EXPECT_EQ(pen_to_screen_text(134.0, 236.6, 0.0), "pen to screen 134 / 237 ms");
  EXPECT_EQ(pen_to_screen_text(134.0, 236.6, 40.0), "pen to screen 134 / 237 ms");
  EXPECT_EQ(pen_to_screen_text(134.0, 236.6, 420.0), "pen to screen 134 / 237 ms, behind 420 ms");
}

TEST(ViewLatency, TimesEachKindFromItsEventsToTheFirstSwapAfterTheFrameAppliedThem) {
  ViewLatency view;
  // Two wheel clicks reach the window; the frame that zooms applies both.
  view.submitted(ViewMotion::kZoom, 1.000);
  view.submitted(ViewMotion::kZoom, 1.010);
  view.shown(1.020);  // not applied yet: nothing shown
  EXPECT_EQ(view.of(ViewMotion::kZoom).shown_count(), 0u);
  view.applied(ViewMotion::kZoom);
  // A rotating move, applied at once; a click that arrives after the zoom frame's input.
  view.submitted(ViewMotion::kRotate, 1.030);
  view.applied(ViewMotion::kRotate);
  view.submitted(ViewMotion::kZoom, 1.035);
  view.shown(1.050);
  EXPECT_EQ(view.of(ViewMotion::kZoom).shown_count(), 2u);  // 50 and 40 ms
  EXPECT_EQ(view.of(ViewMotion::kZoom).waiting(), 1u);
  EXPECT_NEAR(*view.of(ViewMotion::kZoom).percentile_ms(1.0), 50.0, 1e-9);
  EXPECT_NEAR(*view.of(ViewMotion::kRotate).percentile_ms(0.5), 20.0, 1e-9);
  EXPECT_EQ(view.of(ViewMotion::kLight).shown_count(), 0u);
  view.applied(ViewMotion::kZoom);
  view.shown(1.100);
  EXPECT_EQ(view.of(ViewMotion::kZoom).shown_count(), 3u);
  EXPECT_EQ(view.of(ViewMotion::kRotate).shown_count(), 1u);  // shown once, by its first frame
  // A click that scrolled a panel is not timed, nor held for the next zoom.
  view.submitted(ViewMotion::kZoom, 1.200);
  view.dropped(ViewMotion::kZoom);
  view.submitted(ViewMotion::kZoom, 1.300);
  view.applied(ViewMotion::kZoom);
  view.shown(1.330);
  EXPECT_EQ(view.of(ViewMotion::kZoom).shown_count(), 4u);
  EXPECT_EQ(view.of(ViewMotion::kZoom).waiting(), 0u);
  EXPECT_NEAR(*view.of(ViewMotion::kZoom).percentile_ms(0.0), 30.0, 1e-9);
}

TEST(ViewLatency, ReportsInLinesTheBenchReadsBack) {
  ViewLatency view;
  EXPECT_EQ(view.report({8}), "");  // nothing timed, nothing said
  for (int i = 0; i < 5; ++i) view.submitted(ViewMotion::kLight, 2.0 + 0.01 * i);
  view.applied(ViewMotion::kLight);
  view.shown(2.1);  // 100, 90, 80, 70, 60 ms
  const std::string printed = "wrote x.png\n" + view.report({12, 8, 9});
  const auto light = find_latency_line(printed, "light");
  ASSERT_TRUE(light);
  EXPECT_NEAR(light->median_ms, 80.0, 1e-6);
  EXPECT_NEAR(light->p95_ms, 100.0, 1e-6);
  EXPECT_EQ(light->events, 5);
  EXPECT_FALSE(find_latency_line(printed, "rotation"));  // no rotation: no line
  const auto frames = find_motion_frames_line(printed);
  ASSERT_TRUE(frames);
  EXPECT_EQ(frames->coarse, 3);
  EXPECT_EQ(frames->median_factor, 9);
  EXPECT_EQ(frames->interval_ms, 0.0);  // one frame showed the motion: no interval
}

TEST(ViewLatency, MeasuresHowFarApartTheFramesOfAMotionCame) {
  ViewLatency view;
  const auto move_and_swap = [&](double event_s, double swap_s) {
    view.submitted(ViewMotion::kRotate, event_s);
    view.applied(ViewMotion::kRotate);
    view.shown(swap_s);
  };
  EXPECT_FALSE(view.moving());
  move_and_swap(1.00, 1.05);
  EXPECT_TRUE(view.moving());
  move_and_swap(1.04, 1.11);  // 60 ms after the last
  move_and_swap(1.10, 1.18);  // 70
  view.shown(1.25);           // nothing moved: the motion paused
  EXPECT_FALSE(view.moving());
  move_and_swap(1.90, 1.95);  // the next drag: not an interval of this one
  move_and_swap(1.93, 2.00);  // 50
  EXPECT_EQ(view.motion_frame_intervals_ms().size(), 3u);
  const auto frames = find_motion_frames_line(view.report({}));
  ASSERT_TRUE(frames);
  EXPECT_NEAR(frames->interval_ms, 60.0, 1e-6);
  EXPECT_EQ(frames->coarse, 0);
}

TEST(LatencyLines, ReadBackWhatTheyWriteAndOnlyAtALinesStart) {
  const std::string line = latency_line("input", "pen event", "samples", {61.5, 97.25, 360});
  EXPECT_EQ(line,
            "input latency (pen event to the swap showing it): median 61.5 ms, 95th percentile "
            "97.25 ms over 360 samples");
  const auto figures = find_latency_line("noise\n" + line + "; 12 mouse events\n", "input");
  ASSERT_TRUE(figures);
  EXPECT_DOUBLE_EQ(figures->median_ms, 61.5);
  EXPECT_DOUBLE_EQ(figures->p95_ms, 97.25);
  EXPECT_EQ(figures->events, 360);
  EXPECT_FALSE(find_latency_line("no input latency (here)\n", "input"));
  EXPECT_FALSE(find_latency_line("zoom latency (wheel click ...): median x ms\n", "zoom"));
  EXPECT_FALSE(find_motion_frames_line("view motion: none\n"));
  const auto frames = find_motion_frames_line(motion_frames_line({14, 10, 57.5}));
  ASSERT_TRUE(frames);
  EXPECT_EQ(frames->coarse, 14);
  EXPECT_EQ(frames->median_factor, 10);
  EXPECT_DOUBLE_EQ(frames->interval_ms, 57.5);
}

TEST(ServerTime, MovesOntoTheGlfwClockByItsAgeAcrossTheWrap) {
  // Monotonic clock 1234.5678 s, GLFW clock 10.0 s: an event 25 ms before the current
  // millisecond began is 25.8 ms old.
  const std::uint32_t now_ms = 1234567;
  auto t = server_time_on_glfw_clock(now_ms - 25, 1234.5678, 10.0);
  ASSERT_TRUE(t);
  EXPECT_NEAR(*t, 10.0 - 0.0258, 1e-9);
  // The server's ms counter wraps at 2^32 (49.7 days): an event just before the wrap, read
  // just after it.
  const double after_wrap_s = 4294967296.0 * 1e-3 + 0.003;  // 3 ms past the wrap
  t = server_time_on_glfw_clock(0xFFFFFFFFu, after_wrap_s, 50.0);
  ASSERT_TRUE(t);
  EXPECT_NEAR(*t, 50.0 - 0.004, 1e-6);
  // A server on another clock: in the future, or older than the limit.
  EXPECT_FALSE(server_time_on_glfw_clock(now_ms + 5, 1234.5678, 10.0));
  EXPECT_FALSE(server_time_on_glfw_clock(now_ms - 3000, 1234.5678, 10.0));
}

TEST(ServerTime, CallbacksTakeTheTimesOfTheirOwnEventsInOrder) {
  ServerTimeMatcher matcher;
  matcher.add_button(kLeftButton, true, 1.000);
  matcher.add_move(10, 10, 1.001);
  matcher.add_move(10, 10, 1.002);  // GLFW drops a move to where the cursor is
  matcher.add_move(11, 10, 1.003);
  matcher.add_button(kLeftButton, false, 1.004);
  matcher.add_move(12, 10, 1.005);
  EXPECT_EQ(matcher.button(kLeftButton, true), 1.000);
  EXPECT_EQ(matcher.move(10, 10), 1.001);
  EXPECT_EQ(matcher.move(11, 10), 1.003);  // the dropped move is passed over
  EXPECT_EQ(matcher.button(kLeftButton, false), 1.004);
  // An event that arrived after the scan has no time here and takes nothing away.
  EXPECT_FALSE(matcher.move(40, 40));
  EXPECT_FALSE(matcher.button(kRightButton, true));
  EXPECT_EQ(matcher.size(), 1u);
  EXPECT_EQ(matcher.move(12, 10), 1.005);
  EXPECT_EQ(matcher.size(), 0u);
}

TEST(ServerTime, AWheelClickTakesItsOwnTime) {
  ServerTimeMatcher matcher;
  matcher.add_move(10, 10, 1.000);
  matcher.add_wheel(1.001);
  matcher.add_button(kLeftButton, true, 1.002);
  matcher.add_wheel(1.003);
  EXPECT_EQ(matcher.move(10, 10), 1.000);
  EXPECT_EQ(matcher.wheel(), 1.001);
  EXPECT_EQ(matcher.wheel(), 1.003);  // past the press GLFW did not deliver
  EXPECT_FALSE(matcher.wheel());
  EXPECT_FALSE(matcher.button(kLeftButton, true));
}

}  // namespace
}  // namespace impasto::app::window
