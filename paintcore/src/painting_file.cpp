// The native painting file (.impasto), described in docs/painting-format.md:
//   "IMPASTO\0", u32 version, then (version 8) the payload as a compressed section
//   (painting_file_codec.hpp: u64 stored size, u64 size, zstd frame, u64 checksum) and,
//   optionally, the undo history as a second one. Versions 1 to 7 stored the payload as it is
//   (u64 size, payload, u64 checksum; from version 5 an optional history section the same way).
// Little-endian, as the machines Impasto runs on are.

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <future>
#include <limits>
#include <map>
#include <stdexcept>

#include "brush_head_file.hpp"
#include "hasher.hpp"
#include "impasto/files/atomic_file.hpp"
#include "impasto/files/input_file.hpp"
#include "impasto/files/memory_budget.hpp"
#include "painting_file.hpp"
#include "painting_file_tiles.hpp"
#include "painting_history_file.hpp"
#include "painting_impl.hpp"
#include "painting_surface_file.hpp"

namespace impasto::paintcore {
using namespace file_io;  // NOLINT: the file's own building blocks

namespace {

// Reads a history section's steps with `read_steps()`, then the checksum stored after them
// against `digest()` of what was read. Returns why the history was dropped, or "" (then the
// painting holds it). A step that fails in a damaged section is reported as the damage.
template <typename ReadSteps, typename Digest>
std::string read_checked_history(files::InputFile& in, Reader& h, const ReadSteps& read_steps,
                                 const Digest& digest) {
  std::string problem;
  try {
    read_steps();
  } catch (const std::runtime_error& e) {
    problem = e.what();
    h.skip_rest();  // the checksum says whether this is damage
  } catch (const std::bad_alloc&) {
    return "not enough memory for it";
  }
  std::uint64_t stored;
  in.read_exact(&stored, 8);
  if (stored != digest()) return "field 'history_checksum' does not match (it is corrupt)";
  return problem;
}

// The history section after the payload's checksum (versions 5 to 7): its size field, its
// steps (checked against the painting) and its own checksum, hashed as the steps are read.
std::string read_history_section(files::InputFile& in, std::uint64_t section_bytes,
                                 std::uint64_t offset, const std::string& name,
                                 const Canvas& canvas, UndoHistory& history,
                                 std::uint32_t version) {
  if (section_bytes < 16) return "the section is truncated";
  std::uint64_t size = 0;
  in.read_exact(&size, 8);
  if (size != section_bytes - 16)
    return "field 'history_size' says " + std::to_string(size) + " bytes but " +
           std::to_string(section_bytes - 16) + " follow";
  StreamHasher checksum;
  Reader h(in, size, offset + 8, name);
  h.hash_into(&checksum);
  return read_checked_history(
      in, h, [&] { read_history(canvas, history, h, name, version); },
      [&] { return checksum.digest(); });
}

// The same from version 8, compressed (painting_file_codec.hpp).
std::string read_compressed_history_section(files::InputFile& in, std::uint64_t section_bytes,
                                            const std::string& name, const Canvas& canvas,
                                            UndoHistory& history) {
  if (section_bytes < 24) return "the section is truncated";
  std::uint64_t sizes[2] = {};  // stored, decompressed
  in.read_exact(sizes, sizeof sizes);
  if (sizes[0] != section_bytes - 24)
    return "field 'history_stored_size' says " + std::to_string(sizes[0]) + " bytes but " +
           std::to_string(section_bytes - 24) + " follow";
  if (sizes[1] > kMaxSectionBytes)
    return "field 'history_size' says " + std::to_string(sizes[1]) + " bytes (absurd)";
  DecompressingSource source(in, sizes[0], name, "undo history");
  Reader h(source, sizes[1], name);
  return read_checked_history(
      in, h,
      [&] {
        read_history(canvas, history, h, name, kCompressedVersion);
        source.expect_end();
      },
      [&] { return source.digest(); });
}

// Reads the payload's fields with `read_fields()`, then the checksum stored after them against
// `digest()` of what was read, before anything is returned. A field that fails in a damaged
// file is reported as the damage: the rest is read and a checksum that does not match is what
// is thrown.
template <typename ReadFields, typename Digest>
auto read_checked_payload(files::InputFile& in, const Reader& header, Reader& r,
                          const ReadFields& read_fields, const Digest& digest) {
  const auto check_checksum = [&] {
    std::uint64_t stored;
    in.read_exact(&stored, 8);
    if (stored != digest())
      header.fail("checksum", "does not match the contents (the file is corrupt)");
  };
  decltype(read_fields()) p;
  try {
    p = read_fields();
  } catch (const std::runtime_error&) {
    r.skip_rest();
    check_checksum();
    throw;
  }
  check_checksum();
  return p;
}

}  // namespace

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
  w.put(spec.weave_origin_x_cells);
  w.put(spec.weave_origin_y_cells);
  const SimulationParams& q = p.params;
  for (const NamedParam& param : simulation_param_fields(kVersion)) w.put(q.*param.field);
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
  for (const DryLayer& layer : p.canvas.dry_layers()) write_dry_layer(w, layer);
  const Brush& brush = p.brush;
  w.put(static_cast<std::uint8_t>(brush.empty() ? 0 : 1));
  if (!brush.empty()) {
    write_brush_head(w, brush.head());
    write_brush_settings(w, brush.settings());
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
    w.put(static_cast<std::uint8_t>(brush.body()));
    write_bristles(w, brush.head());
  }
  w.put(static_cast<std::uint32_t>(records.size()));
  for (const auto& [name, record] : records) {
    w.put_string(name);
    w.put_string(record);
  }
  // Version 6: media and varnish (painting_surface_file.hpp).
  write_surfaces(w, p.canvas, p.brush);
}

namespace {

// Writes a compressed section (painting_file_codec.hpp) whose bytes `write(writer)` produces,
// in one pass: its sizes are known at its end and written back in place.
template <typename Write>
void put_section(files::AtomicFile& out, const Write& write) {
  const std::uint64_t sizes_at = out.bytes_written();
  const std::uint64_t unknown[2] = {0, 0};
  out.write(unknown, sizeof unknown);
  CompressingSink sink(out);
  ByteSinkOf<CompressingSink> bytes(sink);
  Writer<ByteSink> w(bytes);
  write(w);
  sink.finish();
  const std::uint64_t sizes[2] = {sink.stored_bytes(), sink.section_bytes()};
  out.write_at(sizes_at, sizes, sizeof sizes);
  Writer<files::AtomicFile>(out).put(sink.digest());
}

}  // namespace

void PaintingFile::save(const Painting::Impl& p, const std::filesystem::path& file) {
  const Records records = records_to_save(p);
  files::AtomicFile out(file);
  Writer<files::AtomicFile> header(out);
  for (char c : kMagic) header.put(c);
  header.put(kVersion);
  put_section(out, [&](Writer<ByteSink>& w) { write_payload(p, records, w); });
  // The undo history, after the painting's checksum with one of its own: a damaged history
  // costs only itself (load drops it and says so).
  const SavedSteps steps = steps_to_save(p.history, p.saved_history_bytes);
  if (!steps.empty())
    put_section(out, [&](Writer<ByteSink>& w) { write_history(p.canvas, p.history, steps, w); });
  out.commit();
}

std::unique_ptr<Painting::Impl> PaintingFile::load(const std::filesystem::path& file, int threads,
                                                   bool with_history) {
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
  auto p = version >= kCompressedVersion
               ? load_compressed(in, header, version, threads, with_history)
               : load_uncompressed(in, header, version, threads, with_history);
  for (int index = 0; index < p->canvas.tile_count(); ++index)
    if (p->canvas.tile(index) || p->canvas.cracks().tile(index)) p->canvas.mark_dirty(index);
  return p;
}

std::unique_ptr<Painting::Impl> PaintingFile::load_compressed(files::InputFile& in, Reader& header,
                                                              std::uint32_t version, int threads,
                                                              bool with_history) {
  const std::string name = in.path().string();
  const auto stored = header.get<std::uint64_t>("payload_stored_size");
  constexpr std::uint64_t kSizesEnd = kHeaderBytes + 8;
  if (in.size() < kSizesEnd + 8 || stored > in.size() - kSizesEnd - 8)
    header.fail("payload_stored_size", "says " + std::to_string(stored) +
                                           " bytes but the file has " + std::to_string(in.size()) +
                                           " in all (a truncated file)");
  std::uint64_t size = 0;
  in.read_exact(&size, 8);
  if (size > kMaxSectionBytes)
    header.fail("payload_size", "says " + std::to_string(size) + " bytes (absurd)");
  DecompressingSource source(in, stored, name, "payload");
  Reader r(source, size, name);
  auto p = read_checked_payload(
      in, header, r,
      [&] {
        auto read = read_payload(r, version, name, threads);
        source.expect_end();
        return read;
      },
      [&] { return source.digest(); });
  const std::uint64_t history_bytes = with_history ? in.size() - kSizesEnd - stored - 8 : 0;
  if (history_bytes > 0) {
    std::string problem =
        read_compressed_history_section(in, history_bytes, name, p->canvas, p->history);
    drop_history_if(*p, problem, name);
  }
  return p;
}

std::unique_ptr<Painting::Impl> PaintingFile::load_uncompressed(files::InputFile& in,
                                                                Reader& header,
                                                                std::uint32_t version, int threads,
                                                                bool with_history) {
  const std::string name = in.path().string();
  const auto payload_size = header.get<std::uint64_t>("payload_size");
  // From version 5 an undo history section may follow the payload's checksum.
  if (in.size() < kHeaderBytes + 8 || payload_size > in.size() - kHeaderBytes - 8 ||
      (version < 5 && payload_size != in.size() - kHeaderBytes - 8))
    header.fail("payload_size", "says " + std::to_string(payload_size) +
                                    " bytes but the file has " + std::to_string(in.size()) +
                                    " in all (truncated or padded file)");
  const std::uint64_t history_bytes =
      with_history ? in.size() - kHeaderBytes - 8 - payload_size : 0;
  // One pass: the payload is hashed as it is read, and the stored checksum decides before
  // anything is returned. A field that fails in a damaged file is reported as the damage.
  StreamHasher checksum;
  Reader r(in, payload_size, kHeaderBytes, name);
  r.hash_into(&checksum);
  auto p = read_checked_payload(
      in, header, r, [&] { return read_payload(r, version, name, threads); },
      [&] { return checksum.digest(); });
  if (history_bytes > 0) {
    std::string problem = read_history_section(in, history_bytes, kHeaderBytes + payload_size + 8,
                                               name, p->canvas, p->history, version);
    drop_history_if(*p, problem, name);
  }
  return p;
}

void PaintingFile::drop_history_if(Painting::Impl& p, const std::string& problem,
                                   const std::string& name) {
  if (problem.empty()) return;
  p.history = UndoHistory{};
  p.load_warning =
      name + ": the undo history was dropped (" + problem + "); the painting itself loaded";
}

std::unique_ptr<Painting::Impl> PaintingFile::read_payload(Reader& r, std::uint32_t version,
                                                           const std::string& name, int threads) {
  CanvasSpec spec;
  spec.width_cells = r.get<std::int32_t>("canvas.width_cells");
  spec.height_cells = r.get<std::int32_t>("canvas.height_cells");
  spec.dpi = r.get<double>("canvas.dpi");
  spec.weave_seed = r.get<std::uint64_t>("canvas.weave_seed");
  if (version >= 5) {
    spec.weave_origin_x_cells = r.get<std::int64_t>("canvas.weave_origin_x_cells");
    spec.weave_origin_y_cells = r.get<std::int64_t>("canvas.weave_origin_y_cells");
  }
  try {
    validate(spec);
  } catch (const std::exception& e) {
    throw std::runtime_error(name + ": " + e.what());
  }
  auto p = std::make_unique<Painting::Impl>(spec, threads);
  SimulationParams& q = p->params;
  if (version >= 3) {
    // Those the file's version holds; the rest keep their defaults.
    for (const NamedParam& param : simulation_param_fields(version))
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
  read_wet_tiles(r, p->canvas, slots, tiles, p->arena);
  const auto layers = r.get_count("dry_layers.count", 1u << 24, 4);
  for (std::uint32_t l = 0; l < layers; ++l)
    p->canvas.dry_layers().push_back(
        read_dry_layer(r, "dry_layers[" + std::to_string(l) + "]", tile_count, slots));
  if (r.get<std::uint8_t>("brush.present") != 0) {
    const BrushHead head = read_brush_head(r, "brush.head");
    const BrushSettings settings = read_brush_settings(r, "brush.settings");
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
    read_bristles(r, "brush.head", head);
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
  if (version >= kSurfaceVersion) read_surfaces(r, p->canvas, p->brush);
  if (!r.at_end()) r.fail("end", "unexpected bytes after the last field");
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

Painting Painting::load(const std::filesystem::path& file, int threads, bool with_history) {
  // Declared sizes are checked against the file before anything is allocated; what is left
  // (the canvas's tile table, the tiles a file really holds) can still exceed the machine.
  try {
    return Painting(PaintingFile::load(file, threads, with_history));
  } catch (const std::bad_alloc&) {
    throw std::runtime_error(
        files::out_of_memory_message(file.string(), "the painting's canvas and tiles"));
  }
}

}  // namespace impasto::paintcore
