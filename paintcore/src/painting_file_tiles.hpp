#pragma once
// The payload's wet tiles, read in batches that are decoded in parallel (docs/painting-format.md):
// a tile is a fixed-size record, so a batch's bytes are read (and hashed) in file order, then
// its tiles checked, allocated with their weave and filled on every thread, while the next
// batch is read.
#include <tbb/task_arena.h>

#include <cstdint>

#include "impasto/paintcore/canvas.hpp"
#include "painting_file_io.hpp"

namespace impasto::paintcore::file_io {

// Reads `count` tiles of `slots` pigment slots into the canvas (which holds none yet). Field
// errors name the first bad tile ("tiles[3].wet_volume"), whatever the threads did.
void read_wet_tiles(Reader& r, Canvas& canvas, int slots, std::uint32_t count,
                    tbb::task_arena& arena);

}  // namespace impasto::paintcore::file_io
