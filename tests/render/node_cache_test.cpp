// The trained rules kept in memory and on disk, and built in the background (node_cache.hpp).
#include "impasto/render/node_cache.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>

#include "../files/temp_folder.hpp"
#include "impasto/data/cie.hpp"
#include "impasto/data/lights.hpp"
#include "impasto/data/pigments.hpp"
#include "impasto/render/node_optimisation.hpp"
#include "impasto/render/render_settings.hpp"
#include "impasto/render/spectral_palette.hpp"

using namespace impasto;
using namespace impasto::render;

namespace {

// A 10-nm grid and three pigments: a build takes milliseconds, even under the sanitizers.
const WavelengthRange kCoarse{380.0, 730.0, 10.0};

std::vector<data::Pigment> three_pigments() {
  const auto& db = data::PigmentDatabase::defaults();
  return {db.get("White"), db.get("Red"), db.get("Blue Green Shade")};
}

// Every test gets an empty cache folder of its own, and starts with nothing in memory.
class NodeCache : public ::testing::Test {
 protected:
  void SetUp() override {
    const char* old = std::getenv("XDG_CACHE_HOME");
    had_old_ = old != nullptr;
    if (had_old_) old_ = old;
    setenv("XDG_CACHE_HOME", (folder_ / "cache").c_str(), 1);
    forget_palette_rules_in_memory();
  }
  void TearDown() override {
    wait_for_palette_rules();
    forget_palette_rules_in_memory();
    if (had_old_) {
      setenv("XDG_CACHE_HOME", old_.c_str(), 1);
    } else {
      unsetenv("XDG_CACHE_HOME");
    }
  }

  SpectralSampling rule(const std::string& light_name, int nodes = 4) const {
    const auto pigments = three_pigments();
    return make_palette_sampling(data::light_from_spec(light_name), data::cie1931_2deg(), nodes,
                                 kCoarse, NodeWeights::optimised, pigments,
                                 hiding_reflectance(pigments[0]));
  }
  std::filesystem::path only_rule_file() const {
    std::filesystem::path found;
    for (const auto& entry :
         std::filesystem::directory_iterator(folder_ / "cache" / "impasto" / "node-rules")) {
      EXPECT_TRUE(found.empty()) << "more than one rule file";
      found = entry.path();
    }
    return found;
  }
  static std::string read(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
  }

  test::TempFolder folder_;
  bool had_old_ = false;
  std::string old_;
};

void expect_same(const SpectralSampling& a, const SpectralSampling& b) {
  EXPECT_EQ(a.wavelengths_nm, b.wavelengths_nm);
  EXPECT_EQ(a.to_xyz, b.to_xyz);
  EXPECT_EQ(a.white_xyz, b.white_xyz);
}

SpectralSampling example_rule() {
  SpectralSampling s;
  s.wavelengths_nm = {430.0f, 531.0f, 602.0f};
  s.to_xyz = {{0.1f, 0.05f, 0.9f}, {0.3f, 0.7f, 0.1f}, {0.55f, 0.25f, -0.001f}};
  for (const auto& w : s.to_xyz) {
    for (std::size_t c = 0; c < 3; ++c) s.white_xyz[c] += w[c];
  }
  return s;
}

const NodeRuleKey kExampleKey{0x0123456789abcdefull, NodeWeights::optimised, 3};

TEST(NodeRuleFile, RoundTripsExactly) {
  const SpectralSampling rule = example_rule();
  expect_same(parse_node_rule(format_node_rule(kExampleKey, rule), kExampleKey, {}), rule);
}

// A trained rule keeps its error on the training paints; a file from before the estimate (no
// such line) still reads, with the estimate unknown.
TEST(NodeRuleFile, KeepsTheEstimateAndReadsFilesWithoutIt) {
  SpectralSampling rule = example_rule();
  const std::string without = format_node_rule(kExampleKey, rule);
  EXPECT_EQ(without.find("estimate"), std::string::npos);
  EXPECT_LT(parse_node_rule(without, kExampleKey, {}).estimated_mean_de00, 0.0);
  rule.estimated_mean_de00 = 0.36;
  rule.estimated_max_de00 = 2.03;
  const SpectralSampling back =
      parse_node_rule(format_node_rule(kExampleKey, rule), kExampleKey, {});
  EXPECT_EQ(back.estimated_mean_de00, 0.36);
  EXPECT_EQ(back.estimated_max_de00, 2.03);
  rule.estimated_max_de00 = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(parse_node_rule(format_node_rule(kExampleKey, rule), kExampleKey, {}),
               std::runtime_error);
  rule.estimated_max_de00 = 2.03;
  EXPECT_NE(describe_rule(back).find("0.36 mean, 2.03 max"), std::string::npos)
      << describe_rule(back);
}

TEST(NodeRuleFile, RefusesDamagedForeignAndHostileFiles) {
  const std::string good = format_node_rule(kExampleKey, example_rule());
  const auto refused = [&](const std::string& text, const NodeRuleKey& key) {
    EXPECT_THROW(parse_node_rule(text, key, {}), std::runtime_error) << text;
  };
  std::string flipped = good;
  flipped[good.find("node ") + 6] ^= 1;  // one bit of a wavelength
  refused(flipped, kExampleKey);
  refused(good.substr(0, good.size() / 2), kExampleKey);  // cut short
  refused("", kExampleKey);
  NodeRuleKey other = kExampleKey;
  other.hash ^= 1;  // made for another palette or light
  refused(good, other);
  other = kExampleKey;
  other.nodes = 4;
  refused(good, other);
  other = kExampleKey;
  other.weights = NodeWeights::fitted;
  refused(good, other);

  // Hostile: well formed, with a checksum that matches, but values no rule has.
  const auto with_checksum = [](const SpectralSampling& s) {
    return format_node_rule(kExampleKey, s);
  };
  SpectralSampling bad = example_rule();
  bad.to_xyz[1][0] = std::numeric_limits<float>::quiet_NaN();
  refused(with_checksum(bad), kExampleKey);
  bad = example_rule();
  bad.wavelengths_nm[0] = 200.0f;  // outside the range
  refused(with_checksum(bad), kExampleKey);
  bad = example_rule();
  std::swap(bad.wavelengths_nm[0], bad.wavelengths_nm[1]);  // out of order
  refused(with_checksum(bad), kExampleKey);
  bad = example_rule();
  bad.white_xyz[1] += 0.5;  // not the weights' white
  refused(with_checksum(bad), kExampleKey);
}

TEST_F(NodeCache, BuildsOnceAndReadsTheFileBack) {
  const SpectralSampling built = rule("D65");
  EXPECT_GT(built.estimated_mean_de00, 0.0) << "a trained rule knows its error";
  EXPECT_GE(built.estimated_max_de00, built.estimated_mean_de00);
  const std::filesystem::path file = only_rule_file();
  ASSERT_FALSE(file.empty());
  const auto written = std::filesystem::last_write_time(file);
  forget_palette_rules_in_memory();
  const SpectralSampling read = rule("D65");  // from the file
  expect_same(read, built);
  EXPECT_EQ(read.estimated_mean_de00, built.estimated_mean_de00);
  EXPECT_EQ(std::filesystem::last_write_time(file), written);
}

TEST_F(NodeCache, ADamagedFileIsIgnoredAndRebuilt) {
  const SpectralSampling built = rule("D65");
  const std::filesystem::path file = only_rule_file();
  const std::string good = read(file);
  std::string damaged = good;
  damaged[damaged.find("node ") + 8] ^= 4;
  {
    std::ofstream out(file, std::ios::binary | std::ios::trunc);
    out << damaged;
  }
  forget_palette_rules_in_memory();
  testing::internal::CaptureStderr();
  expect_same(rule("D65"), built);
  const std::string warning = testing::internal::GetCapturedStderr();
  EXPECT_NE(warning.find("ignoring the cached node rule"), std::string::npos) << warning;
  EXPECT_NE(warning.find(file.string()), std::string::npos) << warning;
  EXPECT_EQ(read(file), good);  // written again
}

TEST_F(NodeCache, ALinkWhereTheRuleGoesIsReplacedNotFollowed) {
  const SpectralSampling built = rule("D65");
  const std::filesystem::path file = only_rule_file();
  const std::filesystem::path victim = folder_ / "victim.txt";
  { std::ofstream(victim) << "keep me\n"; }
  std::filesystem::remove(file);
  std::filesystem::create_symlink(victim, file);
  forget_palette_rules_in_memory();
  testing::internal::CaptureStderr();
  expect_same(rule("D65"), built);  // the link's target is no rule: ignored, rebuilt
  testing::internal::GetCapturedStderr();
  EXPECT_EQ(read(victim), "keep me\n");
  EXPECT_FALSE(std::filesystem::is_symlink(file));
  EXPECT_EQ(read(file),
            format_node_rule(palette_rule_key(data::light_from_spec("D65"), data::cie1931_2deg(), 4,
                                              kCoarse, NodeWeights::optimised, three_pigments(),
                                              hiding_reflectance(three_pigments()[0])),
                             built));
}

TEST_F(NodeCache, KeysByLightAndNodeCount) {
  const SpectralSampling d65 = rule("D65");
  const SpectralSampling a = rule("A");
  const SpectralSampling d65_6 = rule("D65", 6);
  EXPECT_NE(d65.to_xyz, a.to_xyz);
  EXPECT_EQ(d65_6.size(), 6);
  expect_same(rule("D65"), d65);  // from memory
  expect_same(rule("A"), a);
}

TEST_F(NodeCache, InTheBackgroundTheInterpolatoryRuleStandsIn) {
  const auto pigments = three_pigments();
  const data::Spectrum light = data::light_from_spec("F11");
  const std::uint64_t finished = palette_rules_finished();
  SpectralSampling first;
  bool stood_in = false;
  {
    const BackgroundPaletteRules background;
    first = rule("F11");
    stood_in = background.stood_in();
  }
  EXPECT_TRUE(stood_in);
  expect_same(first, make_spectral_sampling(light, data::cie1931_2deg(), 4, kCoarse,
                                            NodeWeights::interpolatory));
  wait_for_palette_rules();
  EXPECT_GT(palette_rules_finished(), finished);
  const SpectralSampling optimised = rule("F11");
  EXPECT_NE(optimised.to_xyz, first.to_xyz);
  {
    const BackgroundPaletteRules background;
    expect_same(rule("F11"), optimised);  // built: no stand-in now
    EXPECT_FALSE(background.stood_in());
  }
}
TEST_F(NodeCache, APaletteTooSmallToTrainOnGetsTheGaussianRule) {
  const auto& db = data::PigmentDatabase::defaults();
  const std::vector<data::Pigment> one{db.get("Red Oxide")};  // four training paints
  const data::Spectrum light = data::light_from_spec("D65");
  const SpectralSampling rule =
      make_palette_sampling(light, data::cie1931_2deg(), 8, kCoarse, NodeWeights::optimised, one,
                            hiding_reflectance(db.get("White")));
  expect_same(rule, make_spectral_sampling(light, data::cie1931_2deg(), 8, kCoarse,
                                           NodeWeights::interpolatory));
  EXPECT_LT(training_paints(one).size(), 8 * kMinTrainingPaintsPerNode);
  // And says so: `render` prints the rule with its reason.
  EXPECT_EQ(rule.rule,
            "interpolatory: the optimised rule trains on at least 32 paints for 8 wavelengths; "
            "this palette gives " +
                std::to_string(training_paints(one).size()));
}

// A light of fewer lines than nodes is rendered exactly by its own lines: no palette rule is
// trained for it, and the rule says so.
TEST_F(NodeCache, ALightOfFewLinesIsItsOwnRuleWhateverThePalette) {
  const auto& db = data::PigmentDatabase::defaults();
  std::vector<data::Pigment> palette;
  for (const char* name : {"Red Oxide", "Blue Red Shade", "Red", "Cold Yellow", "White", "Black",
                           "Magenta", "Green", "Yellow Oxide"})
    palette.push_back(db.get(name));
  data::Spectrum lines{"lines", {}, {}};
  for (int nm = 360; nm <= 830; ++nm) {
    lines.wavelengths_nm.push_back(nm);
    lines.values.push_back(nm == 460 || nm == 550 || nm == 620 ? 1.0 : 0.0);
  }
  const SpectralSampling rule =
      make_palette_sampling(lines, data::cie1931_2deg(), 8, kCoarse, NodeWeights::optimised,
                            palette, hiding_reflectance(db.get("White")));
  EXPECT_TRUE(rule.light_lines);
  EXPECT_EQ(rule.rule, "the light's own 3 lines (exact)");
  EXPECT_EQ(rule.size(), 8);
}

TEST(RenderDefaults, TheOptimisedRuleIsTheDefault) {
  EXPECT_EQ(RenderSettings{}.node_weights, NodeWeights::optimised);
}

}  // namespace
