#pragma once
// The painting file's building blocks, shared by the painting (painting_file.cpp) and its
// undo history section (painting_history_file.cpp): checked little-endian fields, sinks that
// count or hash what is written, and the records both write (totals, quadrics, cracks).
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <iterator>
#include <limits>
#include <stdexcept>
#include <string>

#include "hasher.hpp"
#include "impasto/files/atomic_file.hpp"
#include "impasto/files/input_file.hpp"
#include "impasto/paintcore/painting.hpp"
#include "impasto/paintcore/painting_file_header.hpp"
#include "painting_file_codec.hpp"

namespace impasto::paintcore::file_io {

constexpr char kMagic[8] = {'I', 'M', 'P', 'A', 'S', 'T', 'O', '\0'};
// Version 2 added the cracks section; version 3 the physical transfer parameters (replacing
// IMPaSTo's per-step ones, which older files' readers skip), the paint body on the brush and
// the head's bristles; version 4 the pigments' records (their spectra, so the painting renders
// the same without the library). Versions 1 and 2 still load, with today's default parameters;
// files before version 4 render with the library's pigments. Version 5 added the weave's
// origin (a cropped canvas keeps its cloth) and, after the payload's checksum, the optional
// undo history section with a checksum of its own (painting_history_file.cpp). Version 6
// added the media and varnish of the tiles that have them (painting_surface_file.hpp). Version
// 7 added the long steps' settings after the other parameters (the version each parameter
// came in is in simulation_params.cpp's list); older files load with their defaults.
// Version 8 compresses the payload and the history (painting_file_codec.hpp). Version 9 added
// touch_mm (the film split's fade at the contact's edge); older files load with its default.
constexpr std::uint32_t kVersion = kPaintingFileVersion;
constexpr std::uint32_t kCompressedVersion = 8;
constexpr std::uint32_t kOldestVersion = 1;
static_assert(sizeof(kMagic) == kPaintingFileMagicBytes);
constexpr std::size_t kHeaderBytes = kPaintingFileHeaderBytes;
constexpr std::uint32_t kMaxStringBytes = 4096;
// A pigment record is a spectral CSV with its flake data: kilobytes; 16 MB is far beyond any.
constexpr std::uint32_t kMaxRecordBytes = 16u << 20;
constexpr std::uint32_t kMaxPigmentRecords = 4 * kMaxPigmentSlots;
// Larger amounts (FLT_MAX in a crafted file) are refused: painting never leaves them.
constexpr float kMaxAmountMm = kMaxPaintHeightMm;
// Pigment beyond kMaxPigmentRatio times a cell's paint plus kPigmentSlackMm cannot come from
// painting (real cells hold pigment = paint, to rounding); pigment in less paint than
// kMinPaintedVolumeMm (a denormal, where 1 / volume overflows) is dropped with it.
constexpr double kMaxPigmentRatio = 4.0;
constexpr double kPigmentSlackMm = 1e-6;
constexpr float kMinPaintedVolumeMm = std::numeric_limits<float>::min();
// The smallest stored wet tile (index and two planes) and dry tile (index, volume, count).
constexpr std::uint64_t kMinWetTileBytes = 4 + 2 * kTileCells * sizeof(float);
constexpr std::uint64_t kMinDryTileBytes = 4 + kTileCells * sizeof(float) + 1;

// A plane coded against a newer one (the undo history's tiles, painting_history_file.cpp):
// the XOR of the values' bits, so that unchanged values code as zero (decoding is the same).
inline void code_against(const float* values, const float* newer, std::size_t count, float* out) {
  for (std::size_t i = 0; i < count; ++i)
    out[i] = std::bit_cast<float>(std::bit_cast<std::uint32_t>(values[i]) ^
                                  std::bit_cast<std::uint32_t>(newer[i]));
}

template <typename Sink>
class Writer {
 public:
  explicit Writer(Sink& sink) : sink_(sink) {}
  template <typename T>
  void put(const T& value) {
    sink_.write(&value, sizeof(T));
  }
  void put_floats(const float* values, std::size_t count) {
    sink_.write(values, count * sizeof(float));
  }
  // Values stored coded against `newer` (code_against); null: as they are.
  void put_floats(const float* values, std::size_t count, const float* newer) {
    if (newer == nullptr) return put_floats(values, count);
    float coded[1024];
    for (std::size_t at = 0; at < count; at += std::size(coded)) {
      const std::size_t n = std::min(count - at, std::size(coded));
      code_against(values + at, newer + at, n, coded);
      sink_.write(coded, n * sizeof(float));
    }
  }
  void put_zeros(std::size_t count) {
    static constexpr float zeros[kTileCells] = {};
    for (std::size_t left = count; left > 0;) {
      const std::size_t n = std::min<std::size_t>(left, kTileCells);
      sink_.write(zeros, n * sizeof(float));
      left -= n;
    }
  }
  void put_string(const std::string& s) {
    put(static_cast<std::uint32_t>(s.size()));
    sink_.write(s.data(), s.size());
  }

 private:
  Sink& sink_;
};

// Reads fields from the file through a small buffer; every read is checked against the bytes
// left, so a declared size larger than the file fails before anything is allocated for it.
class Reader {
 public:
  Reader(files::InputFile& in, std::uint64_t size, std::uint64_t offset, std::string file)
      : in_(&in), size_(size), offset_(offset), file_(std::move(file)) {}
  // A compressed section (version 8): offsets in messages count within the section.
  Reader(DecompressingSource& in, std::uint64_t size, std::string file)
      : section_(&in), size_(size), offset_(0), file_(std::move(file)) {}

  [[noreturn]] void fail(const std::string& field, const std::string& why) const {
    throw std::runtime_error(file_ + ": field '" + field + "': " + why);
  }
  template <typename T>
  T get(const std::string& field) {
    need(sizeof(T), field);
    T value;
    read(&value, sizeof(T));
    return value;
  }
  double get_finite(const std::string& field) {
    const auto value = get<double>(field);
    if (!std::isfinite(value)) fail(field, "is not a finite number");
    return value;
  }
  // Reads count amounts (mm of paint) into out: each finite, >= 0 and at most kMaxAmountMm.
  // `newer`: the values were stored coded against it (Writer::put_floats).
  void get_amounts(float* out, std::size_t count, const std::string& field,
                   const float* newer = nullptr) {
    need(count * sizeof(float), field);
    read(out, count * sizeof(float));
    if (newer != nullptr) code_against(out, newer, count, out);
    if (std::string why = amounts_problem(out, count); !why.empty()) fail(field, why);
  }
  // Why amounts read elsewhere (tiles decoded in parallel) are not amounts, or "".
  static std::string amounts_problem(const float* values, std::size_t count) {
    for (std::size_t i = 0; i < count; ++i)
      if (!std::isfinite(values[i]) || values[i] < 0.0f || values[i] > kMaxAmountMm) {
        char why[96];
        std::snprintf(why, sizeof why, " (%g) is negative, not finite or above %g mm",
                      static_cast<double>(values[i]), static_cast<double>(kMaxAmountMm));
        return "value " + std::to_string(i) + why;
      }
    return "";
  }
  // Raw bytes (a batch of tiles, decoded elsewhere).
  void get_bytes(void* out, std::size_t bytes, const std::string& field) {
    need(bytes, field);
    read(out, bytes);
  }
  // Every byte read from now on is hashed too, so the checksum is checked in the same pass.
  void hash_into(StreamHasher* hasher) { hasher_ = hasher; }
  // Reads (and hashes) what is left: after a field failed, the checksum says whether the
  // file is corrupt rather than crafted.
  void skip_rest() {
    if (section_ != nullptr) {  // it hashes what it stores, not what it decodes
      section_->skip_rest();
      pos_ = size_;
      return;
    }
    unsigned char chunk[64 << 10];
    while (left() > 0)
      read(chunk, static_cast<std::size_t>(std::min<std::uint64_t>(left(), sizeof chunk)));
  }
  std::string get_string(const std::string& field, std::uint32_t max_bytes = kMaxStringBytes) {
    const auto size = get<std::uint32_t>(field + " length");
    if (size > max_bytes) fail(field, "length " + std::to_string(size) + " is absurd");
    need(size, field);
    std::string s(size, '\0');
    read(s.data(), size);
    return s;
  }
  std::uint32_t get_count(const std::string& field, std::uint32_t max) {
    const auto n = get<std::uint32_t>(field);
    if (n > max) fail(field, std::to_string(n) + " exceeds the limit " + std::to_string(max));
    return n;
  }
  // A count of records of at least `record_bytes` each must fit in the bytes left.
  std::uint32_t get_count(const std::string& field, std::uint32_t max, std::uint64_t record_bytes) {
    const auto n = get_count(field, max);
    if (n * record_bytes > left())
      fail(field, std::to_string(n) + " records of " + std::to_string(record_bytes) +
                      " bytes do not fit in the " + std::to_string(left()) +
                      " bytes left (a truncated or crafted file)");
    return n;
  }
  std::uint64_t left() const { return size_ - pos_; }
  bool at_end() const { return pos_ == size_; }

 private:
  void need(std::uint64_t bytes, const std::string& field) const {
    if (left() < bytes)
      fail(field, "the file is truncated (needs " + std::to_string(bytes) + " bytes at offset " +
                      std::to_string(offset_ + pos_) +
                      (section_ != nullptr ? " of the decompressed section, " : ", ") +
                      std::to_string(left()) + " left)");
  }
  void read(void* out, std::size_t bytes) {
    if (section_ != nullptr)
      section_->read_exact(out, bytes);
    else
      in_->read_exact(out, bytes);
    if (hasher_ != nullptr) hasher_->bytes(out, bytes);
    pos_ += bytes;
  }
  files::InputFile* in_ = nullptr;
  DecompressingSource* section_ = nullptr;
  StreamHasher* hasher_ = nullptr;
  std::uint64_t size_;
  std::uint64_t offset_;
  std::uint64_t pos_ = 0;
  std::string file_;
};

// A cell's pigment is part of its paint: a crafted or damaged file with far more pigment than
// paint (900 mm of pigment in 1e-37 mm) would reach the renderer as concentrations of 1e39.
// Such cells are scaled back to their paint (to none in a denormal volume). What rounding
// leaves in nearly empty cells (0.5 % over in 2.6e-6 mm) is kept exactly, so that a save
// loads back to the same state; the renderer bounds concentrations itself.
inline void repair_pigment(const float* volume, float* pigment, int slots, std::size_t cells) {
  for (std::size_t c = 0; c < cells; ++c) {
    double sum = 0.0;
    for (int s = 0; s < slots; ++s) sum += pigment[static_cast<std::size_t>(s) * cells + c];
    if (!(sum > kMaxPigmentRatio * volume[c] + kPigmentSlackMm)) continue;
    const double scale = volume[c] >= kMinPaintedVolumeMm ? volume[c] / sum : 0.0;
    for (int s = 0; s < slots; ++s)
      pigment[static_cast<std::size_t>(s) * cells + c] =
          static_cast<float>(pigment[static_cast<std::size_t>(s) * cells + c] * scale);
  }
}

template <typename W>
void write_quadric(W& w, const Quadric2& q) {
  for (double c : {q.uu, q.vv, q.uv, q.u_lin, q.v_lin, q.constant}) w.put(c);
}

inline Quadric2 read_quadric(Reader& r, const std::string& field) {
  Quadric2 q;
  for (double* c : {&q.uu, &q.vv, &q.uv, &q.u_lin, &q.v_lin, &q.constant}) *c = r.get_finite(field);
  return q;
}

template <typename W>
void write_totals(W& w, const PaintTotals& t, int slots) {
  w.put(t.volume);
  for (int s = 0; s < slots; ++s)
    w.put(static_cast<std::size_t>(s) < t.pigment.size() ? t.pigment[static_cast<std::size_t>(s)]
                                                         : 0.0);
}

inline PaintTotals read_totals(Reader& r, int slots, const std::string& field) {
  PaintTotals t;
  t.volume = r.get_finite(field + ".volume");
  for (int s = 0; s < slots; ++s)
    t.pigment.push_back(r.get_finite(field + ".pigment[" + std::to_string(s) + "]"));
  return t;
}

// Cracks, sparse twice over: only tiles with a crack, and in them only the crack cells.
template <typename W>
void write_cracks(W& w, const CrackLayer& cracks) {
  w.put(static_cast<std::uint32_t>(cracks.allocated_tiles()));
  for (int index = 0; index < cracks.tile_extent(); ++index) {
    const CrackTile* tile = cracks.tile(index);
    if (tile == nullptr) continue;
    w.put(static_cast<std::uint32_t>(index));
    const auto count = std::count_if(tile->cells.begin(), tile->cells.end(),
                                     [](const CrackRecord& c) { return c.has_crack(); });
    w.put(static_cast<std::uint32_t>(count));
    for (int cell = 0; cell < kTileCells; ++cell) {
      const CrackRecord& c = tile->cells[static_cast<std::size_t>(cell)];
      if (!c.has_crack()) continue;
      w.put(static_cast<std::uint16_t>(cell));
      w.put(c.depth_mm);
      w.put(c.half_width_mm);
      w.put(c.shape);
      w.put(c.exposed_layer);
    }
  }
}

inline CrackLayer read_cracks(Reader& r, const Canvas& canvas, const std::string& file) {
  CrackLayer cracks;
  const int tile_count = canvas.tile_count();
  const auto tiles = r.get_count("cracks.tiles.count", static_cast<std::uint32_t>(tile_count));
  int previous = -1;
  for (std::uint32_t k = 0; k < tiles; ++k) {
    const std::string field = "cracks.tiles[" + std::to_string(k) + "]";
    const auto index =
        static_cast<int>(r.get_count(field + ".index", static_cast<std::uint32_t>(tile_count - 1)));
    if (index <= previous) r.fail(field + ".index", "tiles are not in ascending order");
    previous = index;
    const auto count = r.get_count(field + ".count", static_cast<std::uint32_t>(kTileCells));
    if (count == 0) r.fail(field + ".count", "a stored crack tile holds no crack");
    CrackTile& tile = cracks.ensure_tile(index);
    int previous_cell = -1;
    for (std::uint32_t j = 0; j < count; ++j) {
      const std::string cfield = field + ".cells[" + std::to_string(j) + "]";
      const int cell = r.get<std::uint16_t>(cfield + ".cell");
      if (cell >= kTileCells || cell <= previous_cell)
        r.fail(cfield + ".cell", "cell " + std::to_string(cell) + " is out of range or order");
      previous_cell = cell;
      CrackRecord& c = tile.cells[static_cast<std::size_t>(cell)];
      c.depth_mm = r.get<float>(cfield + ".depth_mm");
      if (!(c.depth_mm > 0.0f)) r.fail(cfield + ".depth_mm", "must be > 0 (and not NaN)");
      c.half_width_mm = r.get<float>(cfield + ".half_width_mm");
      c.shape = r.get<std::uint8_t>(cfield + ".shape");
      c.exposed_layer = r.get<std::uint8_t>(cfield + ".exposed_layer");
    }
  }
  try {
    // Any dry layer index is readable: undoing a drying removes a layer that a saved crack
    // may still name (the renderer then shows the paint around the crack).
    validate_cracks(cracks, canvas.width_cells(), canvas.height_cells(), kCrackExposesGround);
  } catch (const std::exception& e) {
    throw std::runtime_error(file + ": " + e.what());
  }
  return cracks;
}

template <typename W>
void write_dry_layer(W& w, const DryLayer& layer) {
  w.put(static_cast<std::uint32_t>(layer.tiles.size()));
  for (const DryTile& tile : layer.tiles) {
    w.put(static_cast<std::uint32_t>(tile.tile_index));
    w.put_floats(tile.volume_mm.data(), kTileCells);
    w.put(static_cast<std::uint8_t>(tile.slots.size()));
    for (std::uint8_t s : tile.slots) w.put(s);
    w.put_floats(tile.pigment_mm.data(), tile.pigment_mm.size());
  }
}

// A dry layer of a canvas of `tile_count` tiles and a painting of `slots` pigment slots.
inline DryLayer read_dry_layer(Reader& r, const std::string& lfield, int tile_count, int slots) {
  DryLayer layer;
  const auto count =
      r.get_count(lfield + ".tiles", static_cast<std::uint32_t>(tile_count), kMinDryTileBytes);
  int previous = -1;
  for (std::uint32_t k = 0; k < count; ++k) {
    const std::string field = lfield + ".tiles[" + std::to_string(k) + "]";
    DryTile tile;
    tile.tile_index =
        static_cast<int>(r.get_count(field + ".index", static_cast<std::uint32_t>(tile_count - 1)));
    if (tile.tile_index <= previous) r.fail(field + ".index", "tiles are not in ascending order");
    previous = tile.tile_index;
    tile.volume_mm.resize(kTileCells);
    r.get_amounts(tile.volume_mm.data(), kTileCells, field + ".volume");
    const auto nslots = r.get<std::uint8_t>(field + ".slot_count");
    if (nslots > slots) r.fail(field + ".slot_count", "more slots than the painting has");
    int last_slot = -1;
    for (int s = 0; s < nslots; ++s) {
      const auto slot = r.get<std::uint8_t>(field + ".slots");
      if (slot >= slots || slot <= last_slot)
        r.fail(field + ".slots", "slot " + std::to_string(slot) + " is invalid or out of order");
      last_slot = slot;
      tile.slots.push_back(slot);
    }
    tile.pigment_mm.resize(static_cast<std::size_t>(nslots) * kTileCells);
    r.get_amounts(tile.pigment_mm.data(), tile.pigment_mm.size(), field + ".pigment");
    repair_pigment(tile.volume_mm.data(), tile.pigment_mm.data(), nslots, kTileCells);
    layer.tiles.push_back(std::move(tile));
  }
  return layer;
}

// A sink of either kind behind one interface, so that a section can be written by code that
// is not a template (the undo history).
class ByteSink {
 public:
  virtual ~ByteSink() = default;
  virtual void write(const void* data, std::size_t size) = 0;
};

template <typename Sink>
class ByteSinkOf : public ByteSink {
 public:
  explicit ByteSinkOf(Sink& sink) : sink_(sink) {}
  void write(const void* data, std::size_t size) override { sink_.write(data, size); }

 private:
  Sink& sink_;
};

}  // namespace impasto::paintcore::file_io
