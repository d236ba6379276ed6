#pragma once
// The note shown when the painting carries a pigment that differs from the library's (its K
// or S, metadata or flakes were edited, or the library no longer has it): the painting keeps
// rendering with its own until one chooses "Use the library's" (re-rendered) or keeps them.
#include <impasto/render/pigment_records.hpp>

#include <cstdint>
#include <string>
#include <vector>

#include "impasto/session/sim_worker.hpp"
#include "window/window_state.hpp"

namespace impasto::app::window {

class PigmentDriftNote {
 public:
  void draw(WindowState& state, session::SimWorker& worker);
  const std::vector<render::PigmentDrift>& drift() const { return drift_; }

 private:
  // What was checked: the painting's records, the library; checked again when either changes.
  struct Checked {
    const void* records = nullptr;
    std::size_t count = 0;
    const void* library = nullptr;
    bool operator==(const Checked&) const = default;
  };
  Checked checked_;
  std::vector<render::PigmentDrift> drift_;
  bool dismissed_ = false;
  std::string error_;
};

}  // namespace impasto::app::window
