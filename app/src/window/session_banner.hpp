#pragma once
// The session's safety net, shown over the canvas each frame: a red banner while the session
// is not recorded or an autosave failed (it stays for as long as that is so), a notice
// (a read-only folder, a recovered painting), and at start the offer to recover sessions
// that did not end cleanly.
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "session/session_registry.hpp"
#include "window/sim_worker.hpp"

namespace impasto::app::window {

void draw_session_banners(const SimStats& stats, const std::string& notice);

struct RecoveryChoice {
  enum Kind { kNone, kPreview, kRecover, kDiscard, kLater } kind = kNone;
  std::size_t index = 0;
};

// The offer to recover `sessions`; `previewing` is the one shown on the canvas, if any.
RecoveryChoice draw_recovery_offer(const std::vector<SessionEntry>& sessions,
                                   std::optional<std::size_t> previewing);

}  // namespace impasto::app::window
