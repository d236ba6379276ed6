#pragma once
// The session's safety net, shown over the canvas each frame: a red banner while the session
// is not recorded or an autosave failed (it stays for as long as that is so), a notice
// (a read-only folder, a recovered painting), and at start the offer to recover sessions
// that did not end cleanly.
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "impasto/paintcore/painting.hpp"
#include "impasto/session/session_registry.hpp"
#include "impasto/session/sim_worker.hpp"

namespace impasto::app::window {

void draw_session_banners(const session::SimStats& stats, const std::string& notice);

struct RecoveryChoice {
  enum Kind { kNone, kPreview, kRecover, kDiscard, kLater } kind = kNone;
  std::size_t index = 0;
};

// A rebuilt session's false-colour view, shown in the offer.
struct RecoveryPreview {
  std::size_t index = 0;  // of the session
  unsigned texture = 0;   // OpenGL texture name
  int width = 0, height = 0;
  std::string caption;
};

// A rebuilt session's false-colour view (session/preview.hpp), at most 480 px across, as an
// OpenGL texture for the offer.
class PreviewTexture {
 public:
  PreviewTexture() = default;
  PreviewTexture(const PreviewTexture&) = delete;
  PreviewTexture& operator=(const PreviewTexture&) = delete;
  ~PreviewTexture();
  void show(const paintcore::Painting& painting);
  unsigned texture() const { return texture_; }
  int width() const { return width_; }
  int height() const { return height_; }

 private:
  unsigned texture_ = 0;
  int width_ = 0, height_ = 0;
};

// The offer to recover `sessions`, modal (the canvas takes no input while it is open).
RecoveryChoice draw_recovery_offer(const std::vector<session::SessionEntry>& sessions,
                                   const std::optional<RecoveryPreview>& preview);

}  // namespace impasto::app::window
