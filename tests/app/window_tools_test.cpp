// The window's everyday tools, headless: the shortcut table (one source for keys, menus and
// Help), and the eyedropper's model (the pick, the palette's mix, the pick gesture).
#include <gtest/gtest.h>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <impasto/data/pigments.hpp>

#include <set>
#include <string>
#include <utility>
#include <vector>

#include "window/eyedropper.hpp"
#include "window/shortcuts.hpp"
#include "window_test_pigments.hpp"

namespace impasto::app::window {
namespace {

TEST(Shortcuts, EveryChordIsBoundOnceAndEveryCommandIsNamed) {
  std::set<std::pair<int, int>> chords;
  for (const Shortcut& s : shortcuts()) {
    EXPECT_TRUE(chords.insert({s.key, s.mods}).second) << chord_text(s) << " bound twice";
    EXPECT_NO_THROW(command_info(s.command));
  }
  for (const CommandInfo& info : commands()) EXPECT_FALSE(std::string(info.name).empty());
}

// One queue of requests: the File menu takes the file commands (the later of two), the rest
// stay in order for the input router.
TEST(Shortcuts, TheFileMenuTakesItsCommandsFromTheOneQueue) {
  std::vector<Command> queue = {Command::kUndo, Command::kSave, Command::kBrushLarger,
                                Command::kQuit, Command::kFitCanvas};
  EXPECT_EQ(take_file_command(queue), Command::kQuit);
  EXPECT_EQ(queue,
            (std::vector<Command>{Command::kUndo, Command::kBrushLarger, Command::kFitCanvas}));
  EXPECT_EQ(take_file_command(queue), std::nullopt);
  for (const CommandInfo& info : commands()) {
    const bool file = std::string(info.group) == "File";
    EXPECT_EQ(is_file_command(info.command), file) << info.name;
  }
}

TEST(Shortcuts, KeysFindTheirCommandsWithExactlyTheirModifiers) {
  EXPECT_EQ(command_for_key(GLFW_KEY_S, GLFW_MOD_CONTROL), Command::kSave);
  EXPECT_EQ(command_for_key(GLFW_KEY_S, GLFW_MOD_CONTROL | GLFW_MOD_SHIFT), Command::kSaveAs);
  EXPECT_EQ(command_for_key(GLFW_KEY_S, 0), std::nullopt);
  EXPECT_EQ(command_for_key(GLFW_KEY_Z, GLFW_MOD_CONTROL), Command::kUndo);
  EXPECT_EQ(command_for_key(GLFW_KEY_Z, GLFW_MOD_CONTROL | GLFW_MOD_SHIFT), Command::kRedo);
  EXPECT_EQ(command_for_key(GLFW_KEY_Y, GLFW_MOD_CONTROL), Command::kRedo);
  EXPECT_EQ(command_for_key(GLFW_KEY_I, 0), Command::kEyedropper);
  EXPECT_EQ(command_for_key(GLFW_KEY_I, GLFW_MOD_CONTROL), std::nullopt);
  // Caps Lock and Num Lock do not change a key.
  EXPECT_EQ(command_for_key(GLFW_KEY_B, GLFW_MOD_CAPS_LOCK | GLFW_MOD_NUM_LOCK), Command::kBrush);
  // Held keys repeat only where that makes sense: the brush size, not Save.
  EXPECT_EQ(command_for_key(GLFW_KEY_RIGHT_BRACKET, 0, true), Command::kBrushLarger);
  EXPECT_EQ(command_for_key(GLFW_KEY_LEFT_BRACKET, 0, true), Command::kBrushSmaller);
  EXPECT_EQ(command_for_key(GLFW_KEY_S, GLFW_MOD_CONTROL, true), std::nullopt);
}

TEST(Shortcuts, MenuTextComesFromTheTable) {
  EXPECT_EQ(shortcut_text(Command::kSave), "Ctrl+S");
  EXPECT_EQ(shortcut_text(Command::kSaveAs), "Ctrl+Shift+S");
  EXPECT_EQ(shortcut_text(Command::kBrushSmaller), "[");
  EXPECT_EQ(shortcut_text(Command::kShowShortcuts), "F1");
  EXPECT_EQ(all_shortcut_texts(Command::kRedo), "Ctrl+Shift+Z, Ctrl+Y");
  std::vector<Command> pending{Command::kUndo, Command::kSave};
  EXPECT_TRUE(take_command(pending, Command::kSave));
  EXPECT_FALSE(take_command(pending, Command::kSave));
  EXPECT_EQ(pending, std::vector<Command>{Command::kUndo});
}

using test::kBlue;
using test::kWhite;

paintcore::Painting painted_mix() {
  paintcore::Painting p(paintcore::CanvasSpec{128, 128, 254.0, 0});
  p.set_brush({"round", 3.0, 0.5});
  p.load_brush({{kWhite, 3.0}, {kBlue, 1.0}}, 20.0);
  p.begin_stroke();
  for (int i = 0; i < 20; ++i) {
    paintcore::PenSample s;
    s.x_mm = 2.0 + 0.4 * i;
    s.y_mm = 6.0;
    s.pressure = 0.8f;
    s.buttons = paintcore::kPenTip;
    p.stroke_to(s);
  }
  p.end_stroke();
  return p;
}

TEST(Eyedropper, PicksThePigmentsByNameLargestFirstAndLoadsThem) {
  const paintcore::Painting p = painted_mix();
  const auto picked = pick_paint(p, 60.5, 60.5);
  ASSERT_TRUE(picked);
  ASSERT_EQ(picked->mix.size(), 2u);
  EXPECT_EQ(picked->mix[0].pigment, kWhite);
  EXPECT_NEAR(picked->mix[0].parts, 75.0, 0.1);
  EXPECT_EQ(picked->mix[1].pigment, kBlue);
  EXPECT_NEAR(picked->mix[1].parts, 25.0, 0.1);
  EXPECT_FALSE(picked->dry);
  EXPECT_GT(picked->wet_mm, 0.01);
  EXPECT_FALSE(pick_paint(p, 120.5, 120.5));  // bare canvas

  const input::LoadEvent load = picked_load(*picked, 55.0, "paste");
  EXPECT_EQ(load.volume_mm3, 55.0);
  EXPECT_EQ(load.body, "paste");
  EXPECT_EQ(load.mix, picked->mix);

  // The palette's sliders: the largest part at the top of the scale, the rest in proportion.
  std::vector<float> parts;
  EXPECT_TRUE(set_palette_mix(picked->mix, parts).empty());
  const auto& pigments = data::PigmentDatabase::defaults().all();
  ASSERT_EQ(parts.size(), pigments.size());
  float white = -1, blue = -1;
  for (std::size_t i = 0; i < pigments.size(); ++i) {
    if (pigments[i].name == kWhite) white = parts[i];
    if (pigments[i].name == kBlue) blue = parts[i];
  }
  EXPECT_FLOAT_EQ(white, 10.0f);
  EXPECT_NEAR(blue, 10.0f / 3.0f, 0.051f);
  EXPECT_EQ(set_palette_mix({{input::PigmentPart{"Unobtainium", 1.0}}}, parts),
            std::vector<std::string>{"Unobtainium"});
}

TEST(Eyedropper, PicksTheMediumOfThePaintAndLoadsAndShowsIt) {
  const paintcore::Painting plain = painted_mix();
  const auto without = pick_paint(plain, 60.5, 60.5);
  ASSERT_TRUE(without);
  EXPECT_FALSE(without->medium);
  EXPECT_TRUE(picked_load(*without, 40.0, "").medium.empty());
  EXPECT_EQ(picked_medium_text(*without), "none");

  paintcore::Painting p(paintcore::CanvasSpec{128, 128, 254.0, 0});
  p.set_brush({"round", 3.0, 0.5});
  const paintcore::Medium gloss{paintcore::Finish::gloss, 0.5};
  p.load_brush({{kWhite, 1.0}}, 20.0, paintcore::kDefaultPaintBody, gloss);
  p.begin_stroke();
  for (int i = 0; i < 20; ++i) {
    paintcore::PenSample s;
    s.x_mm = 2.0 + 0.4 * i;
    s.y_mm = 6.0;
    s.pressure = 0.8f;
    s.buttons = paintcore::kPenTip;
    p.stroke_to(s);
  }
  p.end_stroke();
  const auto picked = pick_paint(p, 60.5, 60.5);
  ASSERT_TRUE(picked);
  ASSERT_TRUE(picked->medium);
  EXPECT_EQ(picked->medium->finish, paintcore::Finish::gloss);
  EXPECT_NEAR(picked->medium->amount, 0.5, 1e-4);
  EXPECT_EQ(picked_medium_text(*picked), "gloss:0.50");
  // The load carries it as a stroke file spells it, and reads back the same.
  const input::LoadEvent load = picked_load(*picked, 40.0, "");
  const paintcore::Medium loaded = paintcore::parse_medium(load.medium);
  EXPECT_EQ(loaded.finish, paintcore::Finish::gloss);
  EXPECT_NEAR(loaded.amount, 0.5, 1e-4);
  // The Palette's medium follows the pick, and "none" clears it.
  std::optional<paintcore::Finish> finish;
  float amount = 1.0f;
  set_palette_medium(*picked, finish, amount);
  EXPECT_EQ(finish, paintcore::Finish::gloss);
  EXPECT_NEAR(amount, 0.5f, 1e-4f);
  set_palette_medium(*without, finish, amount);
  EXPECT_FALSE(finish);
}

TEST(Eyedropper, TheChipsAreRenderedFromTheMix) {
  const paintcore::Painting p = painted_mix();
  auto picked = pick_paint(p, 60.5, 60.5);
  ASSERT_TRUE(picked);
  render_picked_colours(*picked, render::RenderSettings{});
  EXPECT_TRUE(picked->rendered);
  // White with a quarter of Blue Red Shade: a light blue, bluer than red.
  EXPECT_GT(picked->masstone_rgb[2], picked->masstone_rgb[0] + 0.05f);
  EXPECT_GT(picked->masstone_rgb[2], 0.4f);
}

PointerEvent event(PointerAction action, int button, double x) {
  return PointerEvent{action, button, x, 10.0, 0.0};
}

TEST(Eyedropper, APickTakesItsPressMovesAndReleaseAndNothingElse) {
  PickGesture gesture;
  std::vector<std::pair<double, bool>> picks;
  const auto pick = [&](const PointerEvent& at, bool released) {
    picks.emplace_back(at.x, released);
  };
  const auto canvas = [](double x, double) { return x < 100.0; };
  const std::vector<PointerEvent> frame{
      event(PointerAction::kMove, -1, 1.0),
      event(PointerAction::kPress, kLeftButton, 2.0),
      event(PointerAction::kMove, -1, 3.0),
      event(PointerAction::kPress, kMiddleButton, 3.0),
      event(PointerAction::kRelease, kLeftButton, 4.0),
      event(PointerAction::kMove, -1, 5.0),
  };
  const std::vector<PointerEvent> rest = gesture.take_picks(frame, true, canvas, pick);
  ASSERT_EQ(picks.size(), 3u);
  EXPECT_EQ(picks[0], std::make_pair(2.0, false));
  EXPECT_EQ(picks[1], std::make_pair(3.0, false));
  EXPECT_EQ(picks[2], std::make_pair(4.0, true));
  ASSERT_EQ(rest.size(), 3u);  // the moves outside the pick and the middle press
  EXPECT_EQ(rest[1].button, kMiddleButton);
  EXPECT_FALSE(gesture.held());
  // Not picking, or a press on the panels: everything goes on to the canvas's gestures.
  picks.clear();
  EXPECT_EQ(gesture.take_picks(frame, false, canvas, pick).size(), frame.size());
  const std::vector<PointerEvent> on_panel{event(PointerAction::kPress, kLeftButton, 200.0)};
  EXPECT_EQ(gesture.take_picks(on_panel, true, canvas, pick).size(), 1u);
  EXPECT_TRUE(picks.empty());
  // A pick held over two frames goes on until its release, picking or not.
  gesture.take_picks({{event(PointerAction::kPress, kLeftButton, 1.0)}}, true, canvas, pick);
  EXPECT_TRUE(gesture.held());
  EXPECT_TRUE(
      gesture.take_picks({{event(PointerAction::kRelease, kLeftButton, 1.0)}}, false, canvas, pick)
          .empty());
  EXPECT_FALSE(gesture.held());
}

}  // namespace
}  // namespace impasto::app::window
