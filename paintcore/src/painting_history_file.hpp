#pragma once
// The undo history section of the painting file (version 5, docs/painting-format.md): the
// newest undo steps and the nearest redo steps, as many as fit the painting's
// saved_history_bytes. It follows the painting's checksum with a checksum of its own, so a
// damaged history costs only the history.
#include "painting_file_io.hpp"
#include "undo_history.hpp"

namespace impasto::paintcore {

struct SavedSteps {
  std::size_t undo = 0;  // the newest ones
  std::size_t redo = 0;  // the ones redone next
  bool empty() const { return undo == 0 && redo == 0; }
};

// Which steps fit `budget` bytes (as the history counts them): undo steps newest first, then
// redo steps nearest first.
SavedSteps steps_to_save(const UndoHistory& history, std::size_t budget);

// The steps of the history of the painting on `canvas` (from version 8 each step's tiles are
// coded against their newer states, the canvas's first).
void write_history(const Canvas& canvas, const UndoHistory& history, SavedSteps steps,
                   file_io::Writer<file_io::ByteSink>& w);

// Reads the section and installs it as the history of the painting on `canvas`. Every step is
// checked against the canvas, dry layers and slots it would be applied to (what undo and redo
// index), so a crafted history cannot reach outside them; throws std::runtime_error naming the
// field.
void read_history(const Canvas& canvas, UndoHistory& history, file_io::Reader& r,
                  const std::string& file, std::uint32_t version);

}  // namespace impasto::paintcore
