#pragma once
// Crafted painting files, as a hostile tester makes them: valid checksums around contents that
// declare too much, or amounts no painting holds. Built from a real painting's bytes so that
// they follow the format of the program under test. Used by the paintcore and render tests.
#include <unistd.h>

#include <cfloat>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "hasher.hpp"
#include "impasto/paintcore/painting.hpp"
#include "impasto/paintcore/painting_file_header.hpp"
#include "impasto/paintcore/simulation_params.hpp"
#include "painting_file_sections.hpp"

namespace impasto::paintcore::test {

// What loading `file` throws, or "no error".
inline std::string load_error(const std::filesystem::path& file) {
  try {
    Painting::load(file, 1);
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "no error";
}

inline std::vector<unsigned char> file_bytes(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  const std::string s = text.str();
  return {s.begin(), s.end()};
}

inline void write_bytes(const std::filesystem::path& file, const std::vector<unsigned char>& b) {
  std::ofstream(file, std::ios::binary)
      .write(reinterpret_cast<const char*>(b.data()), static_cast<std::streamsize>(b.size()));
}

// The bytes `painting` saves to.
inline std::vector<unsigned char> saved_bytes(const Painting& painting) {
  const auto file = std::filesystem::temp_directory_path() /
                    ("impasto-hostile-" + std::to_string(::getpid()) + ".impasto");
  painting.save(file);
  auto bytes = file_bytes(file);
  std::filesystem::remove(file);
  return bytes;
}

// Puts `value` at `offset` of the (decompressed) payload; sizes and checksums match again.
template <typename T>
void patch_payload(std::vector<unsigned char>& file, std::size_t offset, const T& value) {
  FileSections sections = sections_of(file);
  if (offset + sizeof(T) > sections.payload.size())
    throw std::out_of_range("patch_payload: offset past the payload");
  std::memcpy(sections.payload.data() + offset, &value, sizeof(T));
  file = file_of(sections);
}

// Payload offsets of a painting with slots named `slots`.
inline std::size_t slots_offset() {
  // spec, weave origin, the parameters
  return 4 + 4 + 8 + 8 + 2 * 8 + 8 * simulation_param_fields(kPaintingFileVersion).size();
}
inline std::size_t tiles_count_offset(const std::vector<std::string>& slots) {
  std::size_t offset = slots_offset() + 4;
  for (const auto& s : slots) offset += 4 + s.size();
  return offset;
}
// Tile k's wet volume (k-th stored tile), then its pigment planes.
inline std::size_t wet_volume_offset(const std::vector<std::string>& slots, int k = 0) {
  const std::size_t tile_bytes = 4 + (2 + slots.size()) * kTileCells * sizeof(float);
  return tiles_count_offset(slots) + 4 + k * tile_bytes + 4 + kTileCells * sizeof(float);
}

// An empty canvas (no tiles, no brush): under 200 bytes.
inline Painting empty_painting() {
  return Painting(CanvasSpec{64, 64, 254.0, 1}, 1);
}

// The pigments of painted_tile(): names the renderer's database knows.
inline const std::vector<std::string>& hostile_slots() {
  static const std::vector<std::string> slots = {"White", "Blue Red Shade"};
  return slots;
}

// One tile of paint: a brush loaded with two pigments, one dab.
inline Painting painted_tile() {
  Painting p(CanvasSpec{64, 64, 254.0, 1}, 1);
  BrushSettings brush;
  brush.head = "round";
  brush.size_mm = 1.0;
  brush.stiffness = 0.5;
  p.set_brush(brush);
  p.load_brush({{hostile_slots()[0], 1.0}, {hostile_slots()[1], 1.0}}, 3.0);
  p.begin_stroke();
  for (int i = 0; i < 8; ++i) {
    PenSample s;
    s.x_mm = 2.0 + 0.3 * i;
    s.y_mm = 3.0;
    s.pressure = 0.8f;
    s.buttons = kPenTip;
    p.stroke_to(s);
  }
  p.end_stroke();
  return p;
}

struct HostilePainting {
  std::string name;
  std::vector<unsigned char> bytes;
  std::string field;  // the field the loader's or renderer's message names; empty: it loads
};

// The set: each is small, and each once made a reader allocate without bound or a render NaN.
inline std::vector<HostilePainting> hostile_paintings() {
  std::vector<HostilePainting> out;
  const auto empty = saved_bytes(empty_painting());
  {
    auto b = empty;  // 193 bytes declaring the largest canvas: loads, but cannot be rendered
    patch_payload(b, 0, std::int32_t{1 << 17});
    patch_payload(b, 4, std::int32_t{1 << 17});
    out.push_back({"huge_canvas", b, "canvas.width_cells"});
  }
  {
    auto b = empty;  // a large canvas declaring every tile stored in a file of none
    patch_payload(b, 0, std::int32_t{1 << 17});
    patch_payload(b, 4, std::int32_t{1 << 17});
    patch_payload(b, tiles_count_offset({}), std::uint32_t{1u << 22});
    out.push_back({"huge_tile_count", b, "tiles.count"});
  }
  {
    auto b = empty;
    patch_payload(b, tiles_count_offset({}) + 4, std::uint32_t{1u << 24});
    out.push_back({"huge_dry_layer_count", b, "dry_layers.count"});
  }
  const std::vector<std::string>& slots = hostile_slots();
  const auto painted = saved_bytes(painted_tile());
  {
    auto b = painted;
    patch_payload(b, wet_volume_offset(slots) + 4 * 100, FLT_MAX);
    out.push_back({"flt_max_amount", b, "tiles[0].wet_volume"});
  }
  {
    auto b = painted;  // pigment in a cell with almost no paint: repaired on load
    const std::size_t cell = 64 * 63 + 63;
    patch_payload(b, wet_volume_offset(slots) + 4 * cell, 1e-40f);  // a denormal
    patch_payload(b, wet_volume_offset(slots) + 4 * (kTileCells + cell), 1.0f);
    patch_payload(b, wet_volume_offset(slots) + 4 * (2 * kTileCells + cell), 1e-38f);
    out.push_back({"pigment_without_paint", b, ""});
  }
  {
    auto b = painted;  // more pigment than paint in a cell: repaired on load
    const std::size_t cell = 64 * 10 + 5;
    patch_payload(b, wet_volume_offset(slots) + 4 * cell, 1e-37f);
    patch_payload(b, wet_volume_offset(slots) + 4 * (kTileCells + cell), 900.0f);
    out.push_back({"pigment_over_volume", b, ""});
  }
  {
    auto b = painted;  // the largest amounts a cell may hold: a metre of paint, all pigment
    const std::size_t cell = 64 * 20 + 20;
    patch_payload(b, wet_volume_offset(slots) - 4 * (kTileCells - cell), 1000.0f);  // dry height
    patch_payload(b, wet_volume_offset(slots) + 4 * cell, 1000.0f);
    patch_payload(b, wet_volume_offset(slots) + 4 * (kTileCells + cell), 1000.0f);
    out.push_back({"largest_amounts", b, ""});
  }
  return out;
}

}  // namespace impasto::paintcore::test
