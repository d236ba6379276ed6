// The native painting file (.impasto), described in docs/painting-format.md:
//   "IMPASTO\0", u32 version, u64 payload size, payload, u64 checksum of the payload.
// Little-endian, as the machines Impasto runs on are.
#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>
#include <iterator>
#include <stdexcept>

#include "hasher.hpp"
#include "painting_impl.hpp"

namespace impasto::paintcore {
namespace {

constexpr char kMagic[8] = {'I', 'M', 'P', 'A', 'S', 'T', 'O', '\0'};
// Version 2 added the cracks section; version 3 the physical transfer parameters (replacing
// IMPaSTo's per-step ones, which older files' readers skip), the paint body on the brush and
// the head's bristles. Versions 1 and 2 still load, with today's default parameters.
constexpr std::uint32_t kVersion = 3;
constexpr std::uint32_t kOldestVersion = 1;
constexpr std::size_t kHeaderBytes = sizeof(kMagic) + 4 + 8;
constexpr std::uint32_t kMaxStringBytes = 4096;

class Writer {
 public:
  template <typename T>
  void put(const T& value) {
    const auto* p = reinterpret_cast<const unsigned char*>(&value);
    bytes_.insert(bytes_.end(), p, p + sizeof(T));
  }
  void put_floats(const float* values, std::size_t count) {
    const auto* p = reinterpret_cast<const unsigned char*>(values);
    bytes_.insert(bytes_.end(), p, p + count * sizeof(float));
  }
  void put_zeros(std::size_t count) { bytes_.insert(bytes_.end(), count * sizeof(float), 0); }
  void put_string(const std::string& s) {
    put(static_cast<std::uint32_t>(s.size()));
    bytes_.insert(bytes_.end(), s.begin(), s.end());
  }
  std::vector<unsigned char>& bytes() { return bytes_; }

 private:
  std::vector<unsigned char> bytes_;
};

class Reader {
 public:
  Reader(const unsigned char* data, std::size_t size, std::string file)
      : data_(data), size_(size), file_(std::move(file)) {}

  [[noreturn]] void fail(const std::string& field, const std::string& why) const {
    throw std::runtime_error(file_ + ": field '" + field + "': " + why);
  }
  template <typename T>
  T get(const std::string& field) {
    need(sizeof(T), field);
    T value;
    std::memcpy(&value, data_ + pos_, sizeof(T));
    pos_ += sizeof(T);
    return value;
  }
  double get_finite(const std::string& field) {
    const auto value = get<double>(field);
    if (!std::isfinite(value)) fail(field, "is not a finite number");
    return value;
  }
  // Reads count floats into out, which must all be finite and >= 0.
  void get_amounts(float* out, std::size_t count, const std::string& field) {
    need(count * sizeof(float), field);
    std::memcpy(out, data_ + pos_, count * sizeof(float));
    pos_ += count * sizeof(float);
    for (std::size_t i = 0; i < count; ++i)
      if (!std::isfinite(out[i]) || out[i] < 0.0f)
        fail(field, "value " + std::to_string(i) + " is negative or not finite");
  }
  std::string get_string(const std::string& field) {
    const auto size = get<std::uint32_t>(field + " length");
    if (size > kMaxStringBytes) fail(field, "length " + std::to_string(size) + " is absurd");
    need(size, field);
    std::string s(reinterpret_cast<const char*>(data_ + pos_), size);
    pos_ += size;
    return s;
  }
  std::uint32_t get_count(const std::string& field, std::uint32_t max) {
    const auto n = get<std::uint32_t>(field);
    if (n > max) fail(field, std::to_string(n) + " exceeds the limit " + std::to_string(max));
    return n;
  }
  bool at_end() const { return pos_ == size_; }

 private:
  void need(std::size_t bytes, const std::string& field) const {
    if (size_ - pos_ < bytes)
      fail(field, "the file is truncated (needs " + std::to_string(bytes) + " bytes at offset " +
                      std::to_string(kHeaderBytes + pos_) + ", " + std::to_string(size_ - pos_) +
                      " left)");
  }
  const unsigned char* data_;
  std::size_t size_;
  std::size_t pos_ = 0;
  std::string file_;
};

void write_quadric(Writer& w, const Quadric2& q) {
  for (double c : {q.uu, q.vv, q.uv, q.u_lin, q.v_lin, q.constant}) w.put(c);
}

Quadric2 read_quadric(Reader& r, const std::string& field) {
  Quadric2 q;
  for (double* c : {&q.uu, &q.vv, &q.uv, &q.u_lin, &q.v_lin, &q.constant}) *c = r.get_finite(field);
  return q;
}

void write_totals(Writer& w, const PaintTotals& t, int slots) {
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
void write_cracks(Writer& w, const CrackLayer& cracks) {
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

void write_file_atomically(const std::filesystem::path& file,
                           const std::vector<unsigned char>& bytes) {
  const std::string target = file.string();
  const std::string temp = target + ".tmp." + std::to_string(::getpid());
  const auto fail = [&](const std::string& what) {
    const std::string why = std::strerror(errno);
    ::unlink(temp.c_str());
    throw std::runtime_error(target + ": cannot save (" + what + ": " + why + ")");
  };
  const int fd = ::open(temp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) fail("open " + temp);
  std::size_t written = 0;
  while (written < bytes.size()) {
    const ssize_t n = ::write(fd, bytes.data() + written, bytes.size() - written);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      ::close(fd);
      fail("write");
    }
    written += static_cast<std::size_t>(n);
  }
  if (::fsync(fd) != 0) {
    ::close(fd);
    fail("fsync");
  }
  if (::close(fd) != 0) fail("close");
  if (::rename(temp.c_str(), target.c_str()) != 0) fail("rename");
  // Make the rename itself durable.
  const std::filesystem::path dir = file.has_parent_path() ? file.parent_path() : ".";
  if (const int dfd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC); dfd >= 0) {
    ::fsync(dfd);
    ::close(dfd);
  }
}

}  // namespace

struct PaintingFile {
  static void save(const Painting::Impl& p, const std::filesystem::path& file);
  static std::unique_ptr<Painting::Impl> load(const std::filesystem::path& file, int threads);
};

void PaintingFile::save(const Painting::Impl& p, const std::filesystem::path& file) {
  Writer w;
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

  Hasher checksum;
  checksum.bytes(w.bytes().data(), w.bytes().size());
  Writer out;
  for (char c : kMagic) out.put(c);
  out.put(kVersion);
  out.put(static_cast<std::uint64_t>(w.bytes().size()));
  out.bytes().insert(out.bytes().end(), w.bytes().begin(), w.bytes().end());
  out.put(checksum.digest());
  write_file_atomically(file, out.bytes());
}

std::unique_ptr<Painting::Impl> PaintingFile::load(const std::filesystem::path& file, int threads) {
  const std::string name = file.string();
  std::ifstream in(file, std::ios::binary);
  if (!in) throw std::runtime_error(name + ": cannot open painting file");
  const std::vector<unsigned char> bytes((std::istreambuf_iterator<char>(in)),
                                         std::istreambuf_iterator<char>());
  if (in.bad()) throw std::runtime_error(name + ": read error");
  Reader header(bytes.data(), bytes.size(), name);
  for (char c : kMagic)
    if (header.get<char>("magic") != c) header.fail("magic", "not an Impasto painting file");
  const auto version = header.get<std::uint32_t>("version");
  if (version < kOldestVersion || version > kVersion)
    header.fail("version", "unknown version " + std::to_string(version) + " (this program reads " +
                               std::to_string(kOldestVersion) + " to " + std::to_string(kVersion) +
                               ")");
  const auto payload_size = header.get<std::uint64_t>("payload_size");
  if (payload_size != bytes.size() - kHeaderBytes - 8 || bytes.size() < kHeaderBytes + 8)
    header.fail("payload_size", "says " + std::to_string(payload_size) +
                                    " bytes but the file has " + std::to_string(bytes.size()) +
                                    " in all (truncated or padded file)");
  const unsigned char* payload = bytes.data() + kHeaderBytes;
  Hasher checksum;
  checksum.bytes(payload, payload_size);
  std::uint64_t stored;
  std::memcpy(&stored, payload + payload_size, 8);
  if (stored != checksum.digest())
    header.fail("checksum", "does not match the contents (the file is corrupt)");

  Reader r(payload, payload_size, name);
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
  const auto tiles = r.get_count("tiles.count", static_cast<std::uint32_t>(tile_count));
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
    if (slots > 0)
      r.get_amounts(tile.pigment_mm.data(), tile.pigment_mm.size(), field + ".pigment");
  }
  const auto layers = r.get_count("dry_layers.count", 1u << 24);
  for (std::uint32_t l = 0; l < layers; ++l) {
    DryLayer layer;
    const std::string lfield = "dry_layers[" + std::to_string(l) + "]";
    const auto count = r.get_count(lfield + ".tiles", static_cast<std::uint32_t>(tile_count));
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
    if (slots > 0)
      r.get_amounts(p->brush.pigment_mm().data(), p->brush.pigment_mm().size(), "brush.pigment");
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
  if (!r.at_end()) r.fail("end", "unexpected bytes after the last field");
  for (int index = 0; index < tile_count; ++index)
    if (p->canvas.tile(index) || p->canvas.cracks().tile(index)) p->canvas.mark_dirty(index);
  return p;
}

void Painting::save(const std::filesystem::path& file) const {
  if (impl_->in_stroke)
    throw std::runtime_error(file.string() + ": cannot save during a stroke (call end_stroke)");
  PaintingFile::save(*impl_, file);
}

Painting Painting::load(const std::filesystem::path& file, int threads) {
  return Painting(PaintingFile::load(file, threads));
}

}  // namespace impasto::paintcore
