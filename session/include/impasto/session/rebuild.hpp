#pragma once
// Rebuilding the painting a session ends with, from its recording alone (docs/replay.md):
// the recording names the painting it started from and marks every save and autosave with
// the file and the state it held, so the rebuild starts from the latest such file that still
// holds that state and replays only the records after its mark.
#include <impasto/input/stroke_events.hpp>
#include <impasto/paintcore/painting.hpp>

#include <string>
#include <vector>

#include "impasto/session/replay.hpp"

namespace impasto::session {

struct RebuiltSession {
  paintcore::Painting painting;
  std::string base;                   // what it was rebuilt from, in words
  std::vector<std::string> warnings;  // a torn last line, a start painting that is gone
  ReplayReport report;
};

// Starts from the latest mark (`from`, `saved`) whose file loads with the state hash it
// marked, and replays the records after it; a mark after which an undo reaches back past the
// mark is passed over for an earlier one. Without any usable mark it replays the whole file
// onto the canvas it names (warning when the session began from a painting that is gone or
// changed). Throws std::runtime_error naming the file and line of a record that cannot apply.
RebuiltSession rebuild_session(const input::StrokeFile& file, const ReplayOptions& options);

}  // namespace impasto::session
