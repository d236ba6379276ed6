#include <impasto/input/hid_models.hpp>

#include <impasto/input/hid_recording.hpp>

#include <cstdlib>
#include <fstream>
#include <mutex>

#include "impasto/files/data_dir.hpp"
#include "impasto/files/message_text.hpp"
#include "recording_input.hpp"
#include "text_fields.hpp"

namespace impasto::input::hid {

namespace {

std::uint32_t parse_hex(std::string_view text, const detail::LineContext& where,
                        const std::string& field, std::uint32_t max) {
  if (text.empty() || text.size() > 8) where.fail(field, "expected a hex number");
  std::uint32_t value = 0;
  for (char c : text) {
    int d = -1;
    if (c >= '0' && c <= '9') d = c - '0';
    if (c >= 'a' && c <= 'f') d = c - 'a' + 10;
    if (c >= 'A' && c <= 'F') d = c - 'A' + 10;
    if (d < 0) where.fail(field, "expected a hex number, found " + files::excerpt(text));
    value = value * 16 + static_cast<std::uint32_t>(d);
  }
  if (value > max) where.fail(field, "out of range");
  return value;
}

std::uint32_t parse_count(std::string_view text, const detail::LineContext& where,
                          const std::string& field) {
  const std::int64_t v = detail::parse_integer(text, where, field);
  if (v < 0 || v > 0xFFFFFF) where.fail(field, "outside 0..16777215");
  return static_cast<std::uint32_t>(v);
}

ModelProtocol parse_protocol(std::string_view text, const detail::LineContext& where) {
  if (text == "hid") return ModelProtocol::kHid;
  if (text == "uclogic") return ModelProtocol::kUcLogic;
  if (text == "xp-pen") return ModelProtocol::kXpPen;
  if (text == "veikk-v1") return ModelProtocol::kVeikkV1;
  if (text == "wacom-ff0d") return ModelProtocol::kWacomVendorPage;
  where.fail("protocol", "unknown protocol " + files::excerpt(text));
}

std::vector<InitStep> parse_init(std::string_view text, const detail::LineContext& where) {
  std::vector<InitStep> steps;
  if (text == "-") return steps;
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t end = std::min(text.find(',', start), text.size());
    const std::string_view step = text.substr(start, end - start);
    InitStep s;
    if (step.starts_with("string:")) {
      s.kind = InitStep::Kind::kReadString;
      s.string_index = static_cast<std::uint8_t>(parse_hex(step.substr(7), where, "init", 0xFF));
    } else if (step.starts_with("output:") && step.size() % 2 == 1 && step.size() > 7) {
      s.kind = InitStep::Kind::kSendOutput;
      for (std::size_t i = 7; i + 1 < step.size(); i += 2) {
        s.report.push_back(
            static_cast<std::uint8_t>(parse_hex(step.substr(i, 2), where, "init", 0xFF)));
      }
    } else {
      where.fail("init", "expected string:IDX or output:HEX, found " + files::excerpt(step));
    }
    steps.push_back(std::move(s));
    start = end + 1;
  }
  return steps;
}

double parse_mm(std::string_view text, const detail::LineContext& where, const std::string& f) {
  const double v = detail::parse_double(text, where, f);
  if (!(v > 0.0) || v > 10000.0) where.fail(f, "must be in 0..10000 mm");
  return v;
}

}  // namespace

const char* model_protocol_name(ModelProtocol protocol) {
  switch (protocol) {
    case ModelProtocol::kHid:
      return "HID descriptor";
    case ModelProtocol::kUcLogic:
      return "UC-Logic";
    case ModelProtocol::kXpPen:
      return "XP-Pen";
    case ModelProtocol::kVeikkV1:
      return "Veikk v1";
    case ModelProtocol::kWacomVendorPage:
      return "Wacom vendor page 0xFF0D";
  }
  return "unknown";
}

std::optional<VendorPenFormat> TabletModel::vendor_format() const {
  VendorPenFormat f;
  switch (protocol) {
    case ModelProtocol::kHid:
      return std::nullopt;
    case ModelProtocol::kWacomVendorPage:
      f.protocol = VendorProtocol::kWacomIntuosV2;  // for a descriptor that lacks the pen
      break;
    case ModelProtocol::kUcLogic: {
      f.protocol = VendorProtocol::kUcLogicV1;
      for (const InitStep& s : init) {
        if (s.kind == InitStep::Kind::kReadString && s.string_index == kUcLogicParamsV2) {
          f.protocol = VendorProtocol::kUcLogicV2;
        }
      }
      break;
    }
    case ModelProtocol::kXpPen:
      f.protocol = VendorProtocol::kXpPen;
      break;
    case ModelProtocol::kVeikkV1:
      f.protocol = VendorProtocol::kVeikkV1;
      break;
  }
  f.max_x = max_x;
  f.max_y = max_y;
  f.max_pressure = max_pressure;
  f.width_mm = width_mm;
  f.height_mm = height_mm;
  f.tilt = tilt;
  return f;
}

std::vector<TabletModel> parse_tablet_models(std::istream& in, const std::string& source) {
  std::vector<TabletModel> models;
  std::string line;
  int line_number = 0;
  while (std::getline(in, line)) {
    ++line_number;
    const detail::LineContext where{source, line_number};
    const auto f = detail::split_fields(line, where);
    if (f.empty()) continue;
    if (f.size() != 13) {
      where.fail("", "expected 13 columns (see the header), found " + std::to_string(f.size()));
    }
    TabletModel m;
    m.vendor_id = static_cast<std::uint16_t>(parse_hex(f[0], where, "vendor_id", 0xFFFF));
    m.product_id = static_cast<std::uint16_t>(parse_hex(f[1], where, "product_id", 0xFFFF));
    m.protocol = parse_protocol(f[2], where);
    if (f[3] != "yes" && f[3] != "no") where.fail("tilt", "expected yes or no");
    m.tilt = f[3] == "yes";
    m.width_mm = parse_mm(f[4], where, "width_mm");
    m.height_mm = parse_mm(f[5], where, "height_mm");
    m.max_x = parse_count(f[6], where, "max_x");
    m.max_y = parse_count(f[7], where, "max_y");
    m.max_pressure = parse_count(f[8], where, "max_pressure");
    if (m.max_x == 0 || m.max_y == 0 || m.max_pressure == 0) {
      where.fail("max_x", "extents and pressure maximum must be positive");
    }
    m.init = parse_init(f[9], where);
    if (f[10] != "-") {
      const std::string_view match = f[10];
      const std::size_t eq = match.find('=');
      if (!match.starts_with("string:") || eq == std::string_view::npos || eq + 1 >= match.size()) {
        where.fail("match", "expected string:IDX=PREFIX");
      }
      m.match_string =
          static_cast<std::uint8_t>(parse_hex(match.substr(7, eq - 7), where, "match", 0xFF));
      std::string_view prefixes = match.substr(eq + 1);
      while (!prefixes.empty()) {
        const std::size_t bar = std::min(prefixes.find('|'), prefixes.size());
        if (bar > 0) m.match_prefixes.emplace_back(prefixes.substr(0, bar));
        prefixes.remove_prefix(std::min(bar + 1, prefixes.size()));
      }
    }
    m.name = std::string(detail::is_quoted(f[11]) ? detail::unquote(f[11]) : f[11]);
    m.source = std::string(f[12]);
    models.push_back(std::move(m));
  }
  return models;
}

std::vector<TabletModel> load_tablet_models(const std::filesystem::path& path) {
  const auto in = detail::open_recording(path, "tablet model table");
  return parse_tablet_models(in->stream(), path.string());
}

std::filesystem::path default_tablet_models_path() {
  return files::data_dir() / "tablets" / "models.tsv";
}

const std::vector<TabletModel>& default_tablet_models(std::string* error) {
  static std::once_flag once;
  static std::vector<TabletModel> models;
  static std::string failure;
  std::call_once(once, [] {
    try {
      models = load_tablet_models(default_tablet_models_path());
    } catch (const std::exception& e) {
      failure = e.what();
    }
  });
  if (error != nullptr) *error = failure;
  return models;
}

std::vector<TabletModel> find_tablet_models(const std::vector<TabletModel>& models,
                                            std::uint16_t vendor_id, std::uint16_t product_id,
                                            const InitExchange& init) {
  std::vector<TabletModel> found;
  for (const TabletModel& m : models) {
    if (m.vendor_id != vendor_id || m.product_id != product_id) continue;
    if (m.match_string && !init.strings.empty()) {
      const auto* bytes = init.string(*m.match_string);
      if (bytes == nullptr) continue;
      const std::string text = string_descriptor_text(*bytes);
      bool matches = false;
      for (const std::string& prefix : m.match_prefixes) matches |= text.starts_with(prefix);
      if (!matches) continue;
    }
    found.push_back(m);
  }
  return found;
}

bool is_uclogic_vendor(std::uint16_t vendor_id) {
  return vendor_id == 0x256C || vendor_id == 0x28BD || vendor_id == 0x5543;
}

}  // namespace impasto::input::hid
