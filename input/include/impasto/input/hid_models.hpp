#pragma once
// The tablet model table (data/tablets/models.tsv): for each USB VID:PID, the protocol its
// pen speaks, its active area, extents and pressure levels, and the initialisation it needs.
// Data, not code: new models are new rows.
#include <impasto/input/hid_init_exchange.hpp>
#include <impasto/input/hid_vendor_pen.hpp>

#include <cstdint>
#include <filesystem>
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

namespace impasto::input::hid {

enum class ModelProtocol { kHid, kUcLogic, kXpPen, kVeikkV1, kWacomVendorPage };
const char* model_protocol_name(ModelProtocol protocol);

struct InitStep {
  enum class Kind { kReadString, kSendOutput } kind = Kind::kReadString;
  std::uint8_t string_index = 0;     // kReadString
  std::vector<std::uint8_t> report;  // kSendOutput
  bool operator==(const InitStep&) const = default;
};

struct TabletModel {
  std::uint16_t vendor_id = 0;
  std::uint16_t product_id = 0;
  ModelProtocol protocol = ModelProtocol::kHid;
  bool tilt = false;
  double width_mm = 0.0;
  double height_mm = 0.0;
  std::uint32_t max_x = 0;
  std::uint32_t max_y = 0;
  std::uint32_t max_pressure = 0;
  std::vector<InitStep> init;
  // Told apart from models with the same ids by string descriptor `match_string` starting
  // with one of `match_prefixes` (none: any).
  std::optional<std::uint8_t> match_string;
  std::vector<std::string> match_prefixes;
  std::string name;
  std::string source;

  // The vendor report format this row describes (for uclogic, v2 when its init reads 0xC8).
  std::optional<VendorPenFormat> vendor_format() const;
};

// Parses the table; errors name the line. `source` names it in messages.
std::vector<TabletModel> parse_tablet_models(std::istream& in, const std::string& source);
std::vector<TabletModel> load_tablet_models(const std::filesystem::path& path);

// $IMPASTO_DATA_DIR/tablets/models.tsv, else the source tree's data/tablets/models.tsv.
std::filesystem::path default_tablet_models_path();
// The default table, read once (empty, with the reason in `error`, when it cannot be read).
const std::vector<TabletModel>& default_tablet_models(std::string* error = nullptr);

// The rows for these ids that the init exchange does not rule out: rows without a match
// string, and rows whose string is present and matches. Without any string in `init`,
// every row of the ids.
std::vector<TabletModel> find_tablet_models(const std::vector<TabletModel>& models,
                                            std::uint16_t vendor_id, std::uint16_t product_id,
                                            const InitExchange& init = {});

// Vendors whose unknown models are read through the UC-Logic handshake: Huion/Gaomon,
// XP-Pen/Ugee, UC-Logic.
bool is_uclogic_vendor(std::uint16_t vendor_id);

}  // namespace impasto::input::hid
