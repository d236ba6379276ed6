// The native painting file (.impasto), described in docs/painting-format.md:
//   "IMPASTO\0", u32 version, u64 payload size, payload, u64 checksum of the payload.
// Little-endian, as the machines Impasto runs on are.

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <map>
#include <stdexcept>

#include "hasher.hpp"
#include "impasto/files/atomic_file.hpp"
#include "impasto/files/input_file.hpp"
#include "impasto/files/memory_budget.hpp"
#include "painting_impl.hpp"

namespace impasto::paintcore {
namespace {

constexpr char kMagic[8] = {'I', 'M', 'P', 'A', 'S', 'T', 'O', '\0'};
// Version 2 added the cracks section; version 3 the physical transfer parameters (replacing
// IMPaSTo's per-step ones, which older files' readers skip), the paint body on the brush and
// the head's bristles; version 4 the pigments' records (their spectra, so the painting renders
// the same without the library). Versions 1 and 2 still load, with today's default parameters;
// files before version 4 render with the library's pigments.
constexpr std::uint32_t kVersion = 4;
constexpr std::uint32_t kOldestVersion = 1;
constexpr std::size_t kHeaderBytes = sizeof(kMagic) + 4 + 8;
constexpr std::uint32_t kMaxStringBytes = 4096;
// A pigment record is a spectral CSV with its flake data: kilobytes; 16 MB is far beyond any.
constexpr std::uint32_t kMaxRecordBytes = 16u << 20;
constexpr std::uint32_t kMaxPigmentRecords = 4 * kMaxPigmentSlots;
// No cell holds a metre of paint: larger amounts (FLT_MAX in a crafted file) are refused.
constexpr float kMaxAmountMm = 1000.0f;
// Pigment beyond kMaxPigmentRatio times a cell's paint plus kPigmentSlackMm cannot come from
// painting (real cells hold pigment = paint, to rounding); pigment in less paint than
// kMinPaintedVolumeMm (a denormal, where 1 / volume overflows) is dropped with it.
constexpr double kMaxPigmentRatio = 4.0;
constexpr double kPigmentSlackMm = 1e-6;
constexpr float kMinPaintedVolumeMm = std::numeric_limits<float>::min();
// The smallest stored wet tile (index and two planes) and dry tile (index, volume, count).
constexpr std::uint64_t kMinWetTileBytes = 4 + 2 * kTileCells * sizeof(float);
constexpr std::uint64_t kMinDryTileBytes = 4 + kTileCells * sizeof(float) + 1;

// Where the payload goes: counted first (the header holds its size), then hashed and written
// to the file as it is produced, tile by tile, so saving never builds a copy of the painting.
class CountingSink {
 public:
  void write(const void*, std::size_t size) { bytes_ += size; }
  std::uint64_t bytes() const { return bytes_; }

 private:
  std::uint64_t bytes_ = 0;
};

class HashingFileSink {
 public:
  explicit HashingFileSink(files::AtomicFile& file) : file_(file) {}
  void write(const void* data, std::size_t size) {
    hasher_.bytes(data, size);
    file_.write(data, size);
    bytes_ += size;
  }
  std::uint64_t bytes() const { return bytes_; }
  std::uint64_t digest() const { return hasher_.digest(); }

 private:
  files::AtomicFile& file_;
  StreamHasher hasher_;
  std::uint64_t bytes_ = 0;
};

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
      : in_(in), size_(size), offset_(offset), file_(std::move(file)) {}

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
  void get_amounts(float* out, std::size_t count, const std::string& field) {
    need(count * sizeof(float), field);
    read(out, count * sizeof(float));
    for (std::size_t i = 0; i < count; ++i)
      if (!std::isfinite(out[i]) || out[i] < 0.0f || out[i] > kMaxAmountMm) {
        char why[96];
        std::snprintf(why, sizeof why, " (%g) is negative, not finite or above %g mm",
                      static_cast<double>(out[i]), static_cast<double>(kMaxAmountMm));
        fail(field, "value " + std::to_string(i) + why);
      }
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
                      std::to_string(offset_ + pos_) + ", " + std::to_string(left()) + " left)");
  }
  void read(void* out, std::size_t bytes) {
    in_.read_exact(out, bytes);
    pos_ += bytes;
  }
  files::InputFile& in_;
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
void repair_pigment(const float* volume, float* pigment, int slots, std::size_t cells) {
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

Quadric2 read_quadric(Reader& r, const std::string& field) {
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

PaintTotals read_totals(Reader& r, int slots, const std::string& field) {
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

CrackLayer read_cracks(Reader& r, const Canvas& canvas, const std::string& file) {
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

}  // namespace

struct PaintingFile {
  using Records = std::map<std::string, std::string>;
  template <typename W>
  static void write_payload(const Painting::Impl& p, const Records& records, W& w);
  // The painting's records, and the record source's for slots that have none.
  static Records records_to_save(const Painting::Impl& p);
  static void save(const Painting::Impl& p, const std::filesystem::path& file);
  static std::unique_ptr<Painting::Impl> load(const std::filesystem::path& file, int threads);
};

PaintingFile::Records PaintingFile::records_to_save(const Painting::Impl& p) {
  Records records = p.pigment_records;
  if (const auto& source = Painting::pigment_record_source()) {
    for (const std::string& slot : p.slots) {
      if (records.count(slot)) continue;
      for (auto& [name, record] : source(slot)) records.try_emplace(name, record);
    }
  }
  return records;
}

template <typename W>
void PaintingFile::write_payload(const Painting::Impl& p, const Records& records, W& w) {
  const CanvasSpec& spec = p.canvas.spec();
  w.put(static_cast<std::int32_t>(spec.width_cells));
  w.put(static_cast<std::int32_t>(spec.height_cells));
  w.put(spec.dpi);
  w.put(spec.weave_seed);
  const SimulationParams& q = p.params;
  for (const NamedParam& param : simulation_param_fields()) w.put(q.*param.field);
  const int slots = static_cast<int>(p.slots.size());
  w.put(static_cast<std::uint32_t>(slots));
  for (const std::string& name : p.slots) w.put_string(name);
  // Wet layer: every tile that exists (the weave is recomputed from the seed).
  w.put(static_cast<std::uint32_t>(p.canvas.allocated_tiles()));
  for (int index = 0; index < p.canvas.tile_count(); ++index) {
    const Tile* tile = p.canvas.tile(index);
    if (!tile) continue;
    w.put(static_cast<std::uint32_t>(index));
    w.put_floats(tile->dry_height_mm.data(), kTileCells);
    w.put_floats(tile->wet_volume_mm.data(), kTileCells);
    for (int s = 0; s < slots; ++s) {
      if (const float* values = tile->pigment(s))
        w.put_floats(values, kTileCells);
      else
        w.put_zeros(kTileCells);
    }
  }
  w.put(static_cast<std::uint32_t>(p.canvas.dry_layers().size()));
  for (const DryLayer& layer : p.canvas.dry_layers()) {
    w.put(static_cast<std::uint32_t>(layer.tiles.size()));
    for (const DryTile& tile : layer.tiles) {
      w.put(static_cast<std::uint32_t>(tile.tile_index));
      w.put_floats(tile.volume_mm.data(), kTileCells);
      w.put(static_cast<std::uint8_t>(tile.slots.size()));
      for (std::uint8_t s : tile.slots) w.put(s);
      w.put_floats(tile.pigment_mm.data(), tile.pigment_mm.size());
    }
  }
  const Brush& brush = p.brush;
  w.put(static_cast<std::uint8_t>(brush.empty() ? 0 : 1));
  if (!brush.empty()) {
    const BrushHead& head = brush.head();
    w.put_string(head.name);
    w.put_string(head.description);
    w.put(head.rise);
    write_quadric(w, head.base);
    w.put(static_cast<std::uint32_t>(head.perturbations.size()));
    for (const Perturbation& pt : head.perturbations) {
      w.put(pt.factor);
      write_quadric(w, pt.shape);
    }
    w.put_string(brush.settings().head);
    w.put(brush.settings().size_mm);
    w.put(brush.settings().stiffness);
    w.put(static_cast<std::uint32_t>(brush.cells_across()));
    w.put_floats(brush.volume_mm().data(), brush.cell_count());
    for (int s = 0; s < slots; ++s) {
      if (s < brush.slot_count())
        w.put_floats(brush.pigment_mm().data() + static_cast<std::size_t>(s) * brush.cell_count(),
                     brush.cell_count());
      else
        w.put_zeros(brush.cell_count());
    }
  }
  write_totals(w, p.ledger.loaded, slots);
  write_totals(w, p.ledger.wiped, slots);
  w.put(p.steps);
  w.put(p.cells_updated);
  write_cracks(w, p.canvas.cracks());
  if (!brush.empty()) {
    const BrushHead& head = brush.head();
    w.put(static_cast<std::uint8_t>(brush.body()));
    for (double v :
         {head.bristles.spacing_mm, head.bristles.depth_mm, head.bristles.jitter, head.splay})
      w.put(v);
  }
  w.put(static_cast<std::uint32_t>(records.size()));
  for (const auto& [name, record] : records) {
    w.put_string(name);
    w.put_string(record);
  }
}

void PaintingFile::save(const Painting::Impl& p, const std::filesystem::path& file) {
  const Records records = records_to_save(p);
  CountingSink counter;
  Writer<CountingSink> count(counter);
  write_payload(p, records, count);
  files::AtomicFile out(file);
  Writer<files::AtomicFile> header(out);
  for (char c : kMagic) header.put(c);
  header.put(kVersion);
  header.put(counter.bytes());
  HashingFileSink sink(out);
  Writer<HashingFileSink> payload(sink);
  write_payload(p, records, payload);
  if (sink.bytes() != counter.bytes())
    throw std::logic_error("painting save: the payload changed size between passes");
  header.put(sink.digest());
  out.commit();
}

std::unique_ptr<Painting::Impl> PaintingFile::load(const std::filesystem::path& file, int threads) {
  const std::string name = file.string();
  files::InputFile in(file, "painting", files::kMaxPaintingBytes);
  Reader header(in, std::min<std::uint64_t>(in.size(), kHeaderBytes), 0, name);
  for (char c : kMagic)
    if (header.get<char>("magic") != c) header.fail("magic", "not an Impasto painting file");
  const auto version = header.get<std::uint32_t>("version");
  if (version < kOldestVersion || version > kVersion)
    header.fail("version", "unknown version " + std::to_string(version) + " (this program reads " +
                               std::to_string(kOldestVersion) + " to " + std::to_string(kVersion) +
                               ")");
  const auto payload_size = header.get<std::uint64_t>("payload_size");
  if (in.size() < kHeaderBytes + 8 || payload_size != in.size() - kHeaderBytes - 8)
    header.fail("payload_size", "says " + std::to_string(payload_size) +
                                    " bytes but the file has " + std::to_string(in.size()) +
                                    " in all (truncated or padded file)");
  // First pass: the checksum, in chunks; nothing is built from a corrupt file.
  {
    StreamHasher checksum;
    std::vector<unsigned char> chunk(std::min<std::uint64_t>(payload_size, 1 << 20));
    for (std::uint64_t left = payload_size; left > 0;) {
      const auto n = static_cast<std::size_t>(std::min<std::uint64_t>(left, chunk.size()));
      in.read_exact(chunk.data(), n);
      checksum.bytes(chunk.data(), n);
      left -= n;
    }
    std::uint64_t stored;
    in.read_exact(&stored, 8);
    if (stored != checksum.digest())
      header.fail("checksum", "does not match the contents (the file is corrupt)");
  }
  in.rewind();
  std::array<unsigned char, kHeaderBytes> skipped;
  in.read_exact(skipped.data(), skipped.size());

  Reader r(in, payload_size, kHeaderBytes, name);
  CanvasSpec spec;
  spec.width_cells = r.get<std::int32_t>("canvas.width_cells");
  spec.height_cells = r.get<std::int32_t>("canvas.height_cells");
  spec.dpi = r.get<double>("canvas.dpi");
  spec.weave_seed = r.get<std::uint64_t>("canvas.weave_seed");
  try {
    validate(spec);
  } catch (const std::exception& e) {
    throw std::runtime_error(name + ": " + e.what());
  }
  auto p = std::make_unique<Painting::Impl>(spec, threads);
  SimulationParams& q = p->params;
  if (version >= 3) {
    for (const NamedParam& param : simulation_param_fields())
      q.*param.field = r.get_finite(std::string("params.") + param.name);
  } else {
    // IMPaSTo's per-step constants: xfer_fraction, equal_paint_cutoff, max_xfer, the two
    // velocity cut-offs and pressure_coeff are dropped; the adhesion film is kept.
    for (int k = 0; k < 6; ++k) r.get_finite("params");
    q.min_film_mm = r.get_finite("params");
  }
  try {
    validate(q);
  } catch (const std::exception& e) {
    throw std::runtime_error(name + ": " + e.what());
  }
  const int slots = static_cast<int>(r.get_count("slots.count", kMaxPigmentSlots));
  for (int s = 0; s < slots; ++s) {
    p->slots.push_back(r.get_string("slots[" + std::to_string(s) + "]"));
    if (p->slots.back().empty()) r.fail("slots[" + std::to_string(s) + "]", "empty pigment name");
  }
  const int tile_count = p->canvas.tile_count();
  const auto tiles = r.get_count("tiles.count", static_cast<std::uint32_t>(tile_count),
                                 kMinWetTileBytes + slots * kTileCells * sizeof(float));
  int previous = -1;
  for (std::uint32_t k = 0; k < tiles; ++k) {
    const std::string field = "tiles[" + std::to_string(k) + "]";
    const auto index =
        static_cast<int>(r.get_count(field + ".index", static_cast<std::uint32_t>(tile_count - 1)));
    if (index <= previous) r.fail(field + ".index", "tiles are not in ascending order");
    previous = index;
    Tile& tile = p->canvas.ensure_tile(index, slots);
    r.get_amounts(tile.dry_height_mm.data(), kTileCells, field + ".dry_height");
    r.get_amounts(tile.wet_volume_mm.data(), kTileCells, field + ".wet_volume");
    if (slots > 0) {
      r.get_amounts(tile.pigment_mm.data(), tile.pigment_mm.size(), field + ".pigment");
      repair_pigment(tile.wet_volume_mm.data(), tile.pigment_mm.data(), slots, kTileCells);
    }
  }
  const auto layers = r.get_count("dry_layers.count", 1u << 24, 4);
  for (std::uint32_t l = 0; l < layers; ++l) {
    DryLayer layer;
    const std::string lfield = "dry_layers[" + std::to_string(l) + "]";
    const auto count =
        r.get_count(lfield + ".tiles", static_cast<std::uint32_t>(tile_count), kMinDryTileBytes);
    previous = -1;
    for (std::uint32_t k = 0; k < count; ++k) {
      const std::string field = lfield + ".tiles[" + std::to_string(k) + "]";
      DryTile tile;
      tile.tile_index = static_cast<int>(
          r.get_count(field + ".index", static_cast<std::uint32_t>(tile_count - 1)));
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
    p->canvas.dry_layers().push_back(std::move(layer));
  }
  if (r.get<std::uint8_t>("brush.present") != 0) {
    BrushHead head;
    head.name = r.get_string("brush.head.name");
    head.description = r.get_string("brush.head.description");
    head.rise = r.get_finite("brush.head.rise");
    if (head.rise < 0.0 || head.rise > 100.0) r.fail("brush.head.rise", "must be in 0..100");
    head.base = read_quadric(r, "brush.head.base");
    const auto perturbations =
        r.get_count("brush.head.perturbations", static_cast<std::uint32_t>(kMaxPerturbations));
    for (std::uint32_t k = 0; k < perturbations; ++k) {
      Perturbation pt;
      pt.factor = r.get_finite("brush.head.perturbations.factor");
      pt.shape = read_quadric(r, "brush.head.perturbations.shape");
      head.perturbations.push_back(pt);
    }
    BrushSettings settings;
    settings.head = r.get_string("brush.settings.head");
    settings.size_mm = r.get_finite("brush.settings.size_mm");
    settings.stiffness = r.get_finite("brush.settings.stiffness");
    try {
      p->brush = Brush(head, settings, spec.cell_mm(), slots);
    } catch (const std::exception& e) {
      throw std::runtime_error(name + ": " + e.what());
    }
    const auto across = r.get<std::uint32_t>("brush.cells_across");
    if (across != static_cast<std::uint32_t>(p->brush.cells_across()))
      r.fail("brush.cells_across", std::to_string(across) + " does not match the brush size (" +
                                       std::to_string(p->brush.cells_across()) + " cells)");
    r.get_amounts(p->brush.volume_mm().data(), p->brush.cell_count(), "brush.volume");
    if (slots > 0) {
      r.get_amounts(p->brush.pigment_mm().data(), p->brush.pigment_mm().size(), "brush.pigment");
      repair_pigment(p->brush.volume_mm().data(), p->brush.pigment_mm().data(), slots,
                     static_cast<std::size_t>(p->brush.cell_count()));
    }
  }
  p->ledger.loaded = read_totals(r, slots, "ledger.loaded");
  p->ledger.wiped = read_totals(r, slots, "ledger.wiped");
  p->steps = r.get<std::uint64_t>("counters.steps");
  p->cells_updated = r.get<std::uint64_t>("counters.cells_updated");
  if (version >= 2) p->canvas.cracks() = read_cracks(r, p->canvas, name);
  if (version >= 3 && !p->brush.empty()) {
    const auto body = r.get<std::uint8_t>("brush.body");
    if (body >= kPaintBodies.size())
      r.fail("brush.body", "unknown paint body " + std::to_string(body));
    BrushHead head = p->brush.head();
    head.bristles.spacing_mm = r.get_finite("brush.head.bristles.spacing_mm");
    head.bristles.depth_mm = r.get_finite("brush.head.bristles.depth_mm");
    head.bristles.jitter = r.get_finite("brush.head.bristles.jitter");
    head.splay = r.get_finite("brush.head.splay");
    const Bristles& b = head.bristles;
    if (!(b.spacing_mm >= 0 && b.spacing_mm <= 100 && b.depth_mm >= 0 && b.depth_mm <= 100 &&
          b.jitter >= 0 && b.jitter <= 1 && head.splay >= 0 && head.splay <= 1))
      r.fail("brush.head.bristles", "out of range");
    // The footprint depends on the bristles: rebuild the brush, keeping its paint.
    Brush rebuilt(head, p->brush.settings(), spec.cell_mm(), slots);
    rebuilt.volume_mm() = p->brush.volume_mm();
    rebuilt.pigment_mm() = p->brush.pigment_mm();
    rebuilt.set_body(static_cast<PaintBody>(body));
    p->brush = std::move(rebuilt);
  }
  if (version >= 4) {
    const auto records = r.get_count("pigments.count", kMaxPigmentRecords, 8);
    for (std::uint32_t k = 0; k < records; ++k) {
      const std::string field = "pigments[" + std::to_string(k) + "]";
      std::string pigment = r.get_string(field + ".name");
      if (pigment.empty()) r.fail(field + ".name", "empty pigment name");
      std::string record = r.get_string(field + ".record", kMaxRecordBytes);
      if (!p->pigment_records.emplace(std::move(pigment), std::move(record)).second)
        r.fail(field + ".name", "a pigment's record appears twice");
    }
  }
  if (!r.at_end()) r.fail("end", "unexpected bytes after the last field");
  for (int index = 0; index < tile_count; ++index)
    if (p->canvas.tile(index) || p->canvas.cracks().tile(index)) p->canvas.mark_dirty(index);
  return p;
}

void Painting::save(const std::filesystem::path& file) const {
  if (impl_->in_stroke)
    throw std::runtime_error(file.string() + ": cannot save during a stroke (call end_stroke)");
  try {
    PaintingFile::save(*impl_, file);
  } catch (const std::bad_alloc&) {
    throw std::runtime_error(
        files::out_of_memory_message(file.string(), "the save's 1 MB write buffer"));
  }
}

Painting Painting::load(const std::filesystem::path& file, int threads) {
  // Declared sizes are checked against the file before anything is allocated; what is left
  // (the canvas's tile table, the tiles a file really holds) can still exceed the machine.
  try {
    return Painting(PaintingFile::load(file, threads));
  } catch (const std::bad_alloc&) {
    throw std::runtime_error(
        files::out_of_memory_message(file.string(), "the painting's canvas and tiles"));
  }
}

}  // namespace impasto::paintcore
