// The Surface panel's varnish choice (app/window/surface_panel.hpp), without a window: the
// names are the command line's (--varnish none|gloss|satin|matte), each maps to its setting
// and back, and what the panel sets is what render::parse_varnish reads from that name.
#include <gtest/gtest.h>

#include <impasto/render/surface_settings.hpp>

#include "window/surface_panel.hpp"

namespace impasto::app::window {
namespace {

TEST(SurfacePanel, VarnishChoicesAreTheCommandLinesNamesAndRoundTrip) {
  const std::vector<std::string> names = varnish_names();
  ASSERT_EQ(names.size(), render::surface::kFinishNames.size() + 1);
  EXPECT_EQ(names.front(), "none");
  for (std::size_t i = 0; i < names.size(); ++i) {
    const int index = static_cast<int>(i);
    const std::optional<render::surface::Finish> varnish = varnish_at(index);
    EXPECT_EQ(varnish, render::parse_varnish(names[i])) << names[i];
    EXPECT_EQ(varnish_index(varnish), index) << names[i];
  }
  EXPECT_EQ(varnish_at(-1), std::nullopt);
  EXPECT_EQ(varnish_at(static_cast<int>(names.size())), std::nullopt);
}

}  // namespace
}  // namespace impasto::app::window
