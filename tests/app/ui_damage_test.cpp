// The window's partial presentation: the part of the screen ImGui's drawing changed.
#include <gtest/gtest.h>
#include <imgui.h>

#include <vector>

#include "window/ui_damage.hpp"

namespace impasto::app::window {
namespace {

UiTriangle triangle(float x, float y, float size, std::uint32_t colour = 0xffffffff) {
  UiTriangle t;
  t.x[0] = x, t.y[0] = y;
  t.x[1] = x + size, t.y[1] = y;
  t.x[2] = x, t.y[2] = y + size;
  for (std::uint32_t& c : t.colour) c = colour;
  t.clip = {0, 0, 1000, 1000};
  return t;
}

TEST(UiDamage, TheSameTrianglesDamageNothing) {
  const std::vector<UiTriangle> frame = {triangle(10, 10, 5), triangle(50, 50, 5)};
  EXPECT_TRUE(changed_box(frame, frame).empty());
}

TEST(UiDamage, AChangedTriangleDamagesItsOldAndNewBoxOnly) {
  const std::vector<UiTriangle> before = {triangle(10, 10, 5), triangle(100, 100, 5),
                                          triangle(500, 500, 5)};
  std::vector<UiTriangle> after = before;
  after[1] = triangle(110, 100, 5);  // moved right by 10
  const UiRect box = changed_box(before, after);
  EXPECT_EQ(box, (UiRect{99, 99, 116, 106}));  // both boxes, a pixel wider
}

TEST(UiDamage, InsertedTrianglesDamageWhereTheyAre) {
  const std::vector<UiTriangle> before = {triangle(10, 10, 5), triangle(500, 500, 5)};
  std::vector<UiTriangle> after = before;
  after.insert(after.begin() + 1, triangle(200, 300, 4, 0xff0000ff));  // a longer text
  EXPECT_EQ(changed_box(before, after), (UiRect{199, 299, 205, 305}));
  EXPECT_EQ(changed_box(after, before), (UiRect{199, 299, 205, 305}));  // and removed
}

TEST(UiDamage, AColourChangeDamagesAndTheClipRectangleBoundsIt) {
  std::vector<UiTriangle> before = {triangle(10, 10, 50)};
  before[0].clip = {20, 20, 30, 30};
  std::vector<UiTriangle> after = before;
  after[0].colour[2] = 0xff00ff00;
  EXPECT_EQ(changed_box(before, after), (UiRect{20, 20, 30, 30}));
}

TEST(UiDamage, ConvertsBetweenImGuiAndGlPixels) {
  // A 100x50 framebuffer at scale 1: ImGui's y goes down, GL's up.
  const render_gl::PixelRect gl = to_gl_pixels({10.5f, 5, 20, 15.5f}, 1.0, 100, 50);
  EXPECT_EQ(gl.x0, 10);
  EXPECT_EQ(gl.x1, 20);
  EXPECT_EQ(gl.y0, 50 - 16);
  EXPECT_EQ(gl.y1, 50 - 5);
  EXPECT_EQ(to_ui_rect({10, 34, 20, 45}, 1.0, 50), (UiRect{10, 5, 20, 16}));
  const render_gl::PixelRect outside = to_gl_pixels({-10, -10, 500, 500}, 2.0, 100, 50);
  EXPECT_EQ(outside.x0, 0);
  EXPECT_EQ(outside.y0, 0);
  EXPECT_EQ(outside.x1, 100);
  EXPECT_EQ(outside.y1, 50);
}

// Real ImGui frames: a window whose text changes damages that text's line, and a second,
// unchanged window nothing.
class ImGuiFrames : public ::testing::Test {
 protected:
  ImGuiFrames() {
    ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr;
    io.DisplaySize = {800, 600};
    io.DeltaTime = 1.0f / 60.0f;
    unsigned char* pixels = nullptr;
    int w = 0, h = 0;
    io.Fonts->GetTexDataAsRGBA32(&pixels, &w, &h);
  }
  ~ImGuiFrames() override { ImGui::DestroyContext(); }

  const ImDrawData& frame(const char* status) {
    ImGui::NewFrame();
    ImGui::SetNextWindowPos({0, 0});
    ImGui::SetNextWindowSize({300, 200});
    ImGui::Begin("panel");
    ImGui::Text("a fixed line");
    ImGui::Text("%s", status);
    ImGui::Text("another fixed line");
    ImGui::End();
    ImGui::SetNextWindowPos({400, 300});
    ImGui::SetNextWindowSize({200, 100});
    ImGui::Begin("other");
    ImGui::Text("never changes");
    ImGui::End();
    ImGui::Render();
    return *ImGui::GetDrawData();
  }
};

TEST_F(ImGuiFrames, AChangedLineIsTheDamage) {
  UiDamage damage;
  const std::vector<UiRect> first = damage.update(frame("frame 1.0 ms"));
  ASSERT_FALSE(first.empty());  // everything is new
  // Frames may differ while ImGui settles its layout; then they are identical.
  damage.update(frame("frame 1.0 ms"));
  EXPECT_TRUE(damage.update(frame("frame 1.0 ms")).empty());
  const std::vector<UiRect> changed = damage.update(frame("frame 27.5 ms"));
  ASSERT_EQ(changed.size(), 1u);
  const UiRect& r = changed[0];
  EXPECT_LT(r.x1, 300.0f);  // inside the panel, not the other window
  EXPECT_LT(r.y1, 200.0f);
  const float line = ImGui::GetTextLineHeightWithSpacing();
  EXPECT_LE(r.y1 - r.y0, line + 2.0f);  // the one line, not the panel
}

// An image whose texels changed is drawn the same: the panel says so, and its box is the
// damage (the palette board re-renders into its texture as it is scrubbed).
TEST_F(ImGuiFrames, AChangedTextureDamagesTheImageThatDrawsIt) {
  const auto board = static_cast<std::uintptr_t>(7);
  const auto frame_with_image = [&] {
    ImGui::NewFrame();
    ImGui::SetNextWindowPos({0, 0});
    ImGui::SetNextWindowSize({300, 200});
    ImGui::Begin("panel");
    ImGui::Text("a fixed line");
    ImGui::Image(reinterpret_cast<ImTextureID>(board), {100, 50});
    ImGui::End();
    ImGui::Render();
    return ImGui::GetDrawData();
  };
  UiDamage damage;
  damage.update(*frame_with_image());
  damage.update(*frame_with_image());
  EXPECT_TRUE(damage.update(*frame_with_image()).empty());
  damage.texture_changed(board);
  const std::vector<UiRect> changed = damage.update(*frame_with_image());
  ASSERT_EQ(changed.size(), 1u);
  EXPECT_NEAR(changed[0].x1 - changed[0].x0, 100.0f, 2.0f);  // the image, a pixel wider
  EXPECT_NEAR(changed[0].y1 - changed[0].y0, 50.0f, 2.0f);
  EXPECT_TRUE(damage.update(*frame_with_image()).empty());  // told once, damaged once
}

}  // namespace
}  // namespace impasto::app::window
