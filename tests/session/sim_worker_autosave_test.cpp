// The painting window's autosave stays cheap: it keeps only the newest few MB of undo history
// (the recording holds the rest), while File > Save keeps the painting's own cap.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <impasto/paintcore/synthetic_painting.hpp>
#include <string>

#include "impasto/session/sim_worker.hpp"

namespace impasto::session {
namespace {

namespace fs = std::filesystem;

TEST(SimWorkerAutosave, KeepsAFewMegabytesOfHistoryAndSaveKeepsAll) {
  const fs::path dir =
      fs::temp_directory_path() / ("impasto_autosave_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  // 90 painted tiles of four pigments: drying them is one undo step of about 9 MB.
  paintcore::SyntheticPaintingSpec spec;
  spec.width_cells = spec.height_cells = 1024;
  spec.painted_share = 90.0 / 256.0;
  spec.slots = {"Blue Red Shade", "White", "Red Oxide", "Red"};
  SimWorker worker(paintcore::synthetic_painting(spec, 1), SessionRecording{});
  const std::size_t own_cap =
      worker.with_painting([](const paintcore::Painting& p) { return p.saved_history_bytes(); });
  worker.edit_painting([](paintcore::Painting& p) { p.dry(0.5); });
  const std::size_t step_bytes =
      worker.with_painting([](const paintcore::Painting& p) { return p.undo_bytes(); });
  ASSERT_GT(step_bytes, std::size_t{8} << 20);
  ASSERT_LT(step_bytes, own_cap);

  worker.autosave(dir / "a.autosave.impasto");
  worker.wait_idle();
  ASSERT_EQ(worker.stats().autosaves, 1u) << worker.stats().autosave_error;
  const paintcore::Painting autosaved = paintcore::Painting::load(dir / "a.autosave.impasto", 1);
  EXPECT_EQ(autosaved.undo_depth(), 0u) << "the drying's step is beyond the autosave's cap";
  EXPECT_EQ(
      worker.with_painting([](const paintcore::Painting& p) { return p.saved_history_bytes(); }),
      own_cap)
      << "the painting's own cap is back after the autosave";

  worker.save(dir / "saved.impasto");
  const paintcore::Painting saved = paintcore::Painting::load(dir / "saved.impasto", 1);
  EXPECT_EQ(saved.undo_depth(), worker.with_painting([](const paintcore::Painting& p) {
    return p.undo_depth();
  })) << "File > Save keeps every step";
  EXPECT_GE(saved.undo_depth(), 1u);
  EXPECT_EQ(saved.state_hash(), autosaved.state_hash());
  fs::remove_all(dir);
}

}  // namespace
}  // namespace impasto::session
