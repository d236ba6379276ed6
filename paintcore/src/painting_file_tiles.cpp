#include "painting_file_tiles.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_group.h>

#include <algorithm>
#include <cstring>
#include <string>
#include <vector>

namespace impasto::paintcore::file_io {

namespace {

// About 8 MB a batch; two are held: one is read while the other is decoded.
constexpr std::uint64_t kBatchBytes = 8u << 20;

struct Problem {
  std::string field, why;  // empty field: none
};

struct Batch {
  std::uint32_t first = 0;  // the file's number of its first tile
  std::uint32_t count = 0;
  std::uint32_t decodable = 0;  // tiles before the first bad index
  Problem index_problem;        // the first bad index, if any
  std::vector<unsigned char> bytes;
  std::vector<Problem> problems;  // per tile, from decoding
};

std::string tile_field(std::uint32_t number) {
  return "tiles[" + std::to_string(number) + "]";
}

std::uint32_t index_at(const unsigned char* record) {
  std::uint32_t index = 0;
  std::memcpy(&index, record, 4);
  return index;
}

// A tile whose index was checked: its amounts, then the tile is allocated (with its weave)
// and put in place. Tiles of one batch have distinct indices, so threads never share a slot.
Problem decode_tile(Canvas& canvas, int slots, const unsigned char* record, std::uint32_t number) {
  const auto index = static_cast<int>(index_at(record));
  auto tile = canvas.make_tile(index, slots);
  const unsigned char* p = record + 4;
  const auto take = [&](float* out, std::size_t count, const char* name) -> Problem {
    std::memcpy(out, p, count * sizeof(float));
    p += count * sizeof(float);
    std::string why = Reader::amounts_problem(out, count);
    if (why.empty()) return {};
    return {tile_field(number) + "." + name, std::move(why)};
  };
  if (Problem bad = take(tile->dry_height_mm.data(), kTileCells, "dry_height"); !bad.field.empty())
    return bad;
  if (Problem bad = take(tile->wet_volume_mm.data(), kTileCells, "wet_volume"); !bad.field.empty())
    return bad;
  if (slots > 0) {
    if (Problem bad = take(tile->pigment_mm.data(), tile->pigment_mm.size(), "pigment");
        !bad.field.empty())
      return bad;
    repair_pigment(tile->wet_volume_mm.data(), tile->pigment_mm.data(), slots, kTileCells);
  }
  canvas.tile_slot(index) = std::move(tile);
  return {};
}

void decode(Canvas& canvas, int slots, std::uint64_t record_bytes, Batch& batch) {
  batch.problems.assign(batch.decodable, Problem{});
  tbb::parallel_for(tbb::blocked_range<std::uint32_t>(0, batch.decodable),
                    [&](const tbb::blocked_range<std::uint32_t>& range) {
                      for (std::uint32_t k = range.begin(); k != range.end(); ++k)
                        batch.problems[k] = decode_tile(
                            canvas, slots, batch.bytes.data() + k * record_bytes, batch.first + k);
                    });
}

// The first problem of a decoded batch in file order, thrown.
void throw_first_problem(const Reader& r, const Batch& batch) {
  for (const Problem& problem : batch.problems)
    if (!problem.field.empty()) r.fail(problem.field, problem.why);
  if (!batch.index_problem.field.empty())
    r.fail(batch.index_problem.field, batch.index_problem.why);
}

}  // namespace

void read_wet_tiles(Reader& r, Canvas& canvas, int slots, std::uint32_t count,
                    tbb::task_arena& arena) {
  const std::uint64_t record_bytes =
      kMinWetTileBytes + static_cast<std::uint64_t>(slots) * kTileCells * sizeof(float);
  const auto per_batch =
      static_cast<std::uint32_t>(std::max<std::uint64_t>(1, kBatchBytes / record_bytes));
  const auto tile_count = static_cast<std::uint32_t>(canvas.tile_count());
  Batch batches[2];
  std::int64_t previous = -1;  // tiles come in ascending index order
  // Checks the batch's indices in order before anything is decoded.
  const auto check_indices = [&](Batch& batch) {
    batch.decodable = batch.count;
    batch.index_problem = {};
    for (std::uint32_t k = 0; k < batch.count; ++k) {
      const std::uint32_t index = index_at(batch.bytes.data() + k * record_bytes);
      if (index > tile_count - 1) {
        batch.index_problem = {
            tile_field(batch.first + k) + ".index",
            std::to_string(index) + " exceeds the limit " + std::to_string(tile_count - 1)};
      } else if (static_cast<std::int64_t>(index) <= previous) {
        batch.index_problem = {tile_field(batch.first + k) + ".index",
                               "tiles are not in ascending order"};
      } else {
        previous = index;
        continue;
      }
      batch.decodable = k;
      return;
    }
  };
  arena.execute([&] {
    tbb::task_group decoding;
    Batch* in_flight = nullptr;
    try {
      for (std::uint32_t first = 0, b = 0; first < count; first += per_batch, ++b) {
        Batch& batch = batches[b % 2];
        batch.first = first;
        batch.count = std::min(per_batch, count - first);
        batch.bytes.resize(batch.count * record_bytes);
        r.get_bytes(batch.bytes.data(), batch.bytes.size(), tile_field(first));
        check_indices(batch);
        if (in_flight != nullptr) {
          decoding.wait();
          throw_first_problem(r, *in_flight);
        }
        in_flight = &batch;
        decoding.run(
            [&canvas, slots, record_bytes, &batch] { decode(canvas, slots, record_bytes, batch); });
        if (!batch.index_problem.field.empty()) break;
      }
      if (in_flight != nullptr) {
        decoding.wait();
        throw_first_problem(r, *in_flight);
      }
    } catch (...) {
      decoding.wait();  // no task outlives the batches it reads
      throw;
    }
  });
}

}  // namespace impasto::paintcore::file_io
