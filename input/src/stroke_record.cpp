#include "stroke_record.hpp"

#include <cstdint>
#include <limits>

#include <impasto/paintcore/brush.hpp>
#include <impasto/paintcore/brush_head.hpp>
#include <impasto/paintcore/paint_body.hpp>
#include <impasto/paintcore/paint_surface.hpp>
#include <impasto/util/text.hpp>

namespace impasto::input::detail {

namespace {

using Fields = std::vector<std::string_view>;

void expect_count(const Fields& fields, std::size_t count, const LineContext& where,
                  const char* usage) {
  if (fields.size() != count) {
    where.fail("", "'" + std::string(fields[0]) + "' takes " + std::to_string(count - 1) +
                       " field(s): " + usage + ", found " + std::to_string(fields.size() - 1));
  }
}

double in_range(double value, double lo, double hi, const LineContext& where,
                const std::string& field) {
  if (value < lo || value > hi) {
    where.fail(field, shortest(value) + " is outside " + shortest(lo) + ".." + shortest(hi));
  }
  return value;
}

// Names of tools, brush heads and parameters: letters, digits, '_', '-', '.'.
std::string identifier(std::string_view text, const LineContext& where, const std::string& field) {
  if (text.empty()) where.fail(field, "empty name");
  for (char c : text) {
    const bool ok = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
                    c == '_' || c == '-' || c == '.';
    if (!ok) where.fail(field, "a name may hold only letters, digits, '_', '-' and '.'");
  }
  return std::string(text);
}

SampleEvent parse_pen(const Fields& f, const LineContext& where) {
  expect_count(f, 9, where, "time x y pressure tilt_x tilt_y rotation buttons");
  paintcore::PenSample s;
  s.time_s = parse_double(f[1], where, "time");
  s.x_mm = parse_double(f[2], where, "x");
  s.y_mm = parse_double(f[3], where, "y");
  s.pressure = parse_float(f[4], where, "pressure");
  in_range(s.pressure, 0.0, 1.0, where, "pressure");
  s.tilt_x_deg = parse_float(f[5], where, "tilt_x");
  in_range(s.tilt_x_deg, -90.0, 90.0, where, "tilt_x");
  s.tilt_y_deg = parse_float(f[6], where, "tilt_y");
  in_range(s.tilt_y_deg, -90.0, 90.0, where, "tilt_y");
  s.rotation_deg = parse_float(f[7], where, "rotation");
  in_range(s.rotation_deg, 0.0, 360.0, where, "rotation");
  const std::int64_t buttons = parse_integer(f[8], where, "buttons");
  if (buttons < 0 || buttons > std::numeric_limits<std::uint32_t>::max()) {
    where.fail("buttons", "must be an unsigned 32-bit bit set");
  }
  s.buttons = static_cast<std::uint32_t>(buttons);
  return SampleEvent{s};
}

CanvasEvent parse_canvas(const Fields& f, const LineContext& where) {
  expect_count(f, 4, where, "width_cells height_cells dpi");
  constexpr std::int64_t kMaxCells = 1 << 16;
  CanvasEvent canvas;
  const auto cells = [&](std::string_view text, const char* field) {
    const std::int64_t n = parse_integer(text, where, field);
    if (n < 1 || n > kMaxCells) {
      where.fail(field, std::to_string(n) + " is outside 1.." + std::to_string(kMaxCells));
    }
    return static_cast<int>(n);
  };
  canvas.width_cells = cells(f[1], "width");
  canvas.height_cells = cells(f[2], "height");
  canvas.dpi = parse_double(f[3], where, "dpi");
  if (!(canvas.dpi > 0.0)) where.fail("dpi", "must be positive");
  in_range(canvas.dpi, 0.0, 100000.0, where, "dpi");
  return canvas;
}

BrushEvent parse_brush(const Fields& f, const LineContext& where) {
  if (f.size() < 2) where.fail("head", "'brush' needs a head name, size=MM and stiffness=X");
  BrushEvent brush;
  brush.head = identifier(f[1], where, "head");
  bool has_size = false;
  bool has_stiffness = false;
  for (std::size_t i = 2; i < f.size(); ++i) {
    const std::size_t eq = f[i].find('=');
    if (eq == std::string_view::npos) where.fail(std::string(f[i]), "expected key=value");
    const std::string key = identifier(f[i].substr(0, eq), where, "key");
    const double value = parse_double(f[i].substr(eq + 1), where, key);
    const auto seen = [&] {
      for (const BrushParam& p : brush.params) {
        if (p.key == key) return true;
      }
      return (key == "size" && has_size) || (key == "stiffness" && has_stiffness);
    };
    if (seen()) where.fail(key, "given twice");
    if (key == "size") {
      if (!(value > 0.0 && value <= paintcore::kMaxBrushSizeMm))
        where.fail(key, "must be in (0, " + util::number_text(paintcore::kMaxBrushSizeMm) + "] mm");
      brush.size_mm = value;
      has_size = true;
    } else if (key == "stiffness") {
      brush.stiffness = in_range(value, 0.0, 1.0, where, key);
      has_stiffness = true;
    } else {
      // A head's bristle setting (paintcore::kBristleSettings) in its range; other keys are
      // kept for the writer and ignored, with a warning (parse_strokes).
      const paintcore::BristleSetting* setting = paintcore::find_bristle_setting(key);
      if (setting && !setting->holds(value)) where.fail(key, "must be in " + setting->range_text());
      brush.params.push_back({key, value});
    }
  }
  if (!has_size) where.fail("size", "missing (size=MM)");
  if (!has_stiffness) where.fail("stiffness", "missing (stiffness=X)");
  return brush;
}

LoadEvent parse_load(Fields f, const LineContext& where) {
  LoadEvent load;
  // Optional last fields, in any order: body=NAME gives the paint's body, medium=FINISH[:AMOUNT]
  // its medium (paint_surface.hpp).
  while (f.size() > 1 && !is_quoted(f.back()) &&
         (f.back().starts_with("body=") || f.back().starts_with("medium="))) {
    if (f.back().starts_with("medium=")) {
      if (!load.medium.empty()) where.fail("medium", "given twice");
      load.medium = std::string(f.back().substr(7));
      try {
        paintcore::parse_medium(load.medium);
      } catch (const std::runtime_error& e) {
        where.fail("medium", e.what());
      }
    } else {
      if (!load.body.empty()) where.fail("body", "given twice");
      load.body = std::string(f.back().substr(5));
      if (!paintcore::paint_body_from_name(load.body))
        where.fail("body", "unknown paint body '" + load.body.substr(0, 32) +
                               "' (known: " + paintcore::paint_body_names() + ")");
    }
    f.pop_back();
  }
  if (f.size() < 4 || f.size() % 2 != 0) {
    where.fail("", "'load' takes a volume in mm^3 then \"pigment name\" parts pairs");
  }
  load.volume_mm3 = parse_double(f[1], where, "volume");
  if (!(load.volume_mm3 >= 0.0 && load.volume_mm3 <= paintcore::kMaxLoadMm3))
    where.fail("volume", "must be in [0, " + util::number_text(paintcore::kMaxLoadMm3) + "] mm^3");
  for (std::size_t i = 2; i < f.size(); i += 2) {
    if (!is_quoted(f[i])) where.fail("pigment", "pigment names are written in double quotes");
    const std::string_view name = unquote(f[i]);
    if (name.empty()) where.fail("pigment", "empty pigment name");
    for (char c : name) {
      if (static_cast<unsigned char>(c) < 0x20) where.fail("pigment", "control character in name");
    }
    PigmentPart part{std::string(name), parse_double(f[i + 1], where, "parts")};
    if (!(part.parts > 0.0)) where.fail("parts", "must be positive");
    load.mix.push_back(std::move(part));
  }
  return load;
}

// varnish FINISH THICKNESS_MM [X Y W H]: the region in cells, as `impasto edit --region`.
VarnishEvent parse_varnish(const Fields& f, const LineContext& where) {
  if (f.size() != 3 && f.size() != 7)
    where.fail("",
               "'varnish' takes a finish and a thickness in mm, then optionally a region "
               "x y width height in cells; found " +
                   std::to_string(f.size() - 1) + " field(s)");
  VarnishEvent varnish;
  const std::optional<paintcore::Finish> finish = paintcore::finish_from_name(f[1]);
  if (!finish) {
    std::string shown;
    for (char c : f[1].substr(0, 32)) shown += (c >= 0x20 && c < 0x7f) ? c : '?';
    where.fail("finish", "unknown finish '" + shown + "' (known: gloss, satin, matte)");
  }
  varnish.finish = *finish;
  varnish.thickness_mm = parse_double(f[2], where, "thickness");
  if (!(varnish.thickness_mm >= paintcore::kMinVarnishMm &&
        varnish.thickness_mm <= paintcore::kMaxVarnishMm))
    where.fail("thickness", shortest(varnish.thickness_mm) + " mm is outside [" +
                                shortest(paintcore::kMinVarnishMm) + ", " +
                                shortest(paintcore::kMaxVarnishMm) + "]");
  if (f.size() == 7) {
    constexpr std::int64_t kMaxCells = 1 << 16;
    const auto number = [&](std::size_t i, const char* field, std::int64_t lo) {
      const std::int64_t n = parse_integer(f[i], where, field);
      if (n < lo || n > kMaxCells)
        where.fail(field, std::to_string(n) + " is outside " + std::to_string(lo) + ".." +
                              std::to_string(kMaxCells));
      return static_cast<int>(n);
    };
    const int x = number(3, "x", 0), y = number(4, "y", 0);
    const int w = number(5, "width", 1), h = number(6, "height", 1);
    varnish.region = paintcore::CellRect{x, y, x + w, y + h};
  }
  return varnish;
}

// A file path in a record: in double quotes, with '"', '%' and control characters written
// as %XX, so that any path fits on one line and reads back the same.
std::string quoted_path(const std::string& path) {
  static constexpr char kHex[] = "0123456789abcdef";
  std::string out = "\"";
  for (char c : path) {
    const auto u = static_cast<unsigned char>(c);
    if (c == '"' || c == '%' || u < 0x20 || u == 0x7f) {
      out += '%';
      out += kHex[u >> 4];
      out += kHex[u & 15];
    } else {
      out += c;
    }
  }
  return out + "\"";
}

std::string parse_path(std::string_view field, const LineContext& where) {
  if (!is_quoted(field)) where.fail("path", "a path is written in double quotes");
  const std::string_view text = unquote(field);
  if (text.empty()) where.fail("path", "empty path");
  const auto hex = [&](char c) -> int {
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    if (c >= 'A' && c <= 'F') return c - 'A' + 10;
    where.fail("path", "'%' must be followed by two hex digits");
  };
  std::string path;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] != '%') {
      path += text[i];
      continue;
    }
    if (i + 2 >= text.size()) {
      where.fail("path", "'%' must be followed by two hex digits");
    }
    path += static_cast<char>(hex(text[i + 1]) * 16 + hex(text[i + 2]));
    i += 2;
  }
  if (path.find('\0') != std::string::npos) where.fail("path", "NUL in path");
  return path;
}

std::string hash_text(std::uint64_t hash) {
  static constexpr char kHex[] = "0123456789abcdef";
  std::string text(16, '0');
  for (int i = 15; i >= 0; --i, hash >>= 4) text[static_cast<std::size_t>(i)] = kHex[hash & 15];
  return text;
}

std::uint64_t parse_hash(std::string_view text, const LineContext& where) {
  if (text.size() != 16) where.fail("state_hash", "expected 16 hex digits");
  std::uint64_t hash = 0;
  for (char c : text) {
    int digit = -1;
    if (c >= '0' && c <= '9') digit = c - '0';
    if (c >= 'a' && c <= 'f') digit = c - 'a' + 10;
    if (digit < 0) where.fail("state_hash", "expected 16 lower-case hex digits");
    hash = hash * 16 + static_cast<std::uint64_t>(digit);
  }
  return hash;
}

OriginEvent parse_origin(const Fields& f, const LineContext& where) {
  if (f.size() == 2 && f[1] == "new") return OriginEvent{};
  if (f.size() != 3) where.fail("", "'from' takes 'new' or a \"path\" and its state hash");
  return OriginEvent{false, parse_path(f[1], where), parse_hash(f[2], where)};
}

struct RecordLine {
  std::string text;
  void add(std::string_view field) {
    if (!text.empty()) text += ' ';
    text += field;
  }
};

struct LineWriter {
  std::string operator()(const SampleEvent& e) const {
    const paintcore::PenSample& s = e.sample;
    RecordLine line;
    line.add("pen");
    line.add(shortest(s.time_s));
    line.add(shortest(s.x_mm));
    line.add(shortest(s.y_mm));
    line.add(shortest(s.pressure));
    line.add(shortest(s.tilt_x_deg));
    line.add(shortest(s.tilt_y_deg));
    line.add(shortest(s.rotation_deg));
    line.add(std::to_string(s.buttons));
    return line.text;
  }
  std::string operator()(const CanvasEvent& e) const {
    return "canvas " + std::to_string(e.width_cells) + " " + std::to_string(e.height_cells) + " " +
           shortest(e.dpi);
  }
  std::string operator()(const ToolEvent& e) const { return "tool " + e.name; }
  std::string operator()(const BrushEvent& e) const {
    RecordLine line;
    line.add("brush");
    line.add(e.head);
    line.add("size=" + shortest(e.size_mm));
    line.add("stiffness=" + shortest(e.stiffness));
    for (const BrushParam& p : e.params) line.add(p.key + "=" + shortest(p.value));
    return line.text;
  }
  std::string operator()(const LoadEvent& e) const {
    RecordLine line;
    line.add("load");
    line.add(shortest(e.volume_mm3));
    for (const PigmentPart& p : e.mix) {
      line.add("\"" + p.pigment + "\"");
      line.add(shortest(p.parts));
    }
    if (!e.body.empty()) line.add("body=" + e.body);
    if (!e.medium.empty()) line.add("medium=" + e.medium);
    return line.text;
  }
  std::string operator()(const WipeEvent&) const { return "wipe"; }
  std::string operator()(const DryEvent& e) const { return "dry " + shortest(e.fraction); }
  std::string operator()(const QualityEvent& e) const {
    return "quality " + std::string(util::name_of(paintcore::kStepQualityNames, e.quality));
  }
  std::string operator()(const VarnishEvent& e) const {
    RecordLine line;
    line.add("varnish");
    line.add(std::string(paintcore::finish_name(e.finish)));
    line.add(shortest(e.thickness_mm));
    if (e.region) {
      const paintcore::CellRect& r = *e.region;
      for (const int n : {r.x0, r.y0, r.x1 - r.x0, r.y1 - r.y0}) line.add(std::to_string(n));
    }
    return line.text;
  }
  std::string operator()(const UndoEvent&) const { return "undo"; }
  std::string operator()(const RedoEvent&) const { return "redo"; }
  std::string operator()(const OriginEvent& e) const {
    if (e.new_canvas) return "from new";
    return "from " + quoted_path(e.painting) + " " + hash_text(e.state_hash);
  }
  std::string operator()(const SavedEvent& e) const {
    return "saved " + quoted_path(e.painting) + " " + hash_text(e.state_hash);
  }
};

}  // namespace

StrokeEvent parse_record(const Fields& f, const LineContext& where) {
  const std::string_view kind = f.at(0);
  if (kind == "pen") return parse_pen(f, where);
  if (kind == "canvas") return parse_canvas(f, where);
  if (kind == "tool") {
    expect_count(f, 2, where, "name");
    return ToolEvent{identifier(f[1], where, "name")};
  }
  if (kind == "brush") return parse_brush(f, where);
  if (kind == "load") return parse_load(f, where);
  if (kind == "wipe") {
    expect_count(f, 1, where, "none");
    return WipeEvent{};
  }
  if (kind == "dry") {
    expect_count(f, 2, where, "fraction");
    return DryEvent{in_range(parse_double(f[1], where, "fraction"), 0.0, 1.0, where, "fraction")};
  }
  if (kind == "varnish") return parse_varnish(f, where);
  if (kind == "quality") {
    expect_count(f, 2, where, "level");
    try {
      return QualityEvent{
          util::parse_name(paintcore::kStepQualityNames, f[1].substr(0, 40), "quality")};
    } catch (const std::runtime_error& error) {
      where.fail("level", error.what());
    }
  }
  if (kind == "undo") {
    expect_count(f, 1, where, "none");
    return UndoEvent{};
  }
  if (kind == "redo") {
    expect_count(f, 1, where, "none");
    return RedoEvent{};
  }
  if (kind == "from") return parse_origin(f, where);
  if (kind == "saved") {
    expect_count(f, 3, where, "\"path\" state_hash");
    return SavedEvent{parse_path(f[1], where), parse_hash(f[2], where)};
  }
  std::string shown;
  for (char c : kind.substr(0, 40)) shown += (c >= 0x20 && c < 0x7f) ? c : '?';
  where.fail("", "unknown record '" + shown + "'");
}

std::string record_line(const StrokeEvent& event) {
  return std::visit(LineWriter{}, event);
}

}  // namespace impasto::input::detail
