#include <gtest/gtest.h>

#include "test_util.hpp"

namespace impasto::paintcore {
namespace {

using test::flat_spec;
using test::round_brush;
using test::stroke_line;

TEST(Undo, StrokeRoundTripIsBitExact) {
  Painting p(CanvasSpec{128, 128, 254.0, 2});
  p.set_brush(round_brush());
  p.load_brush({{"red", 1.0}}, 5.0);
  stroke_line(p, 2.0, 3.0, 10.0, 3.0, 0.8f);
  const std::uint64_t before = p.state_hash();
  const std::size_t tiles_before = p.canvas().allocated_tiles();
  stroke_line(p, 2.0, 9.0, 10.0, 3.0, 0.9f);  // reaches tiles not painted before
  const std::uint64_t after = p.state_hash();
  ASSERT_NE(before, after);
  const Painting::ChangeSubscriber changes = p.subscribe_changes();
  (void)p.take_changes(changes);
  ASSERT_TRUE(p.undo());
  EXPECT_EQ(p.state_hash(), before);
  EXPECT_EQ(p.canvas().allocated_tiles(), tiles_before);
  EXPECT_FALSE(p.take_changes(changes).empty());
  ASSERT_TRUE(p.redo());
  EXPECT_EQ(p.state_hash(), after);
  EXPECT_FALSE(p.redo());
}

TEST(Undo, LoadWipeAndDryUndoToo) {
  Painting p(flat_spec());
  p.set_brush(round_brush());
  const std::uint64_t h0 = p.state_hash();
  p.load_brush({{"red", 1.0}}, 5.0);
  const std::uint64_t h1 = p.state_hash();
  stroke_line(p, 2.0, 3.0, 10.0, 3.0, 0.8f);
  const std::uint64_t h2 = p.state_hash();
  p.dry(0.4);
  const std::uint64_t h3 = p.state_hash();
  p.wipe_brush();
  const std::uint64_t h4 = p.state_hash();
  EXPECT_EQ(p.canvas().dry_layers().size(), 1u);
  ASSERT_TRUE(p.undo());
  EXPECT_EQ(p.state_hash(), h3);
  ASSERT_TRUE(p.undo());
  EXPECT_EQ(p.state_hash(), h2);
  EXPECT_TRUE(p.canvas().dry_layers().empty());
  ASSERT_TRUE(p.undo());
  EXPECT_EQ(p.state_hash(), h1);
  ASSERT_TRUE(p.undo());
  EXPECT_EQ(p.state_hash(), h0);
  EXPECT_EQ(p.loaded_totals().volume, 0.0);
  for (std::uint64_t h : {h1, h2, h3, h4}) {
    ASSERT_TRUE(p.redo());
    EXPECT_EQ(p.state_hash(), h);
  }
  EXPECT_EQ(p.canvas().dry_layers().size(), 1u);
}

TEST(Undo, NewOperationClearsRedo) {
  Painting p(flat_spec());
  p.set_brush(round_brush());
  p.load_brush({{"red", 1.0}}, 5.0);
  stroke_line(p, 2.0, 3.0, 10.0, 3.0, 0.8f);
  ASSERT_TRUE(p.undo());
  EXPECT_EQ(p.redo_depth(), 1u);
  p.load_brush({{"red", 1.0}}, 1.0);
  EXPECT_EQ(p.redo_depth(), 0u);
  EXPECT_FALSE(p.redo());
}

TEST(Undo, BudgetDropsOldestButNeverTheLast) {
  Painting p(flat_spec());
  p.set_brush(round_brush());
  p.load_brush({{"red", 1.0}}, 5.0);
  for (int k = 0; k < 5; ++k) stroke_line(p, 2.0, 1.0 + 2.0 * k, 10.0, 1.0 + 2.0 * k, 0.8f, 8);
  EXPECT_EQ(p.undo_depth(), 7u);  // set_brush, load, 5 strokes
  const std::size_t full = p.undo_bytes();
  p.set_undo_budget_bytes(full / 2);
  EXPECT_LT(p.undo_depth(), 7u);
  EXPECT_LE(p.undo_bytes(), full / 2);
  p.set_undo_budget_bytes(1);
  EXPECT_EQ(p.undo_depth(), 1u);
  const std::uint64_t last = p.state_hash();
  EXPECT_TRUE(p.undo());
  EXPECT_NE(p.state_hash(), last);
  EXPECT_FALSE(p.undo());
}

}  // namespace
}  // namespace impasto::paintcore
