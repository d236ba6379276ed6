#pragma once
// The trained rules (fitted and optimised samplings, node_optimisation.hpp) built once per
// palette, light, observer and node count, and kept: in memory for the process, and on disk
// (files::cache_dir("node-rules")) for later runs. A rule file is small text in a versioned
// format with a checksum; one that is damaged, foreign or hostile is ignored with a warning
// and the rule rebuilt and written again (atomically, files/atomic_file.hpp).
//
// A window must never wait for a build: on a thread holding a BackgroundPaletteRules, a rule
// not yet built is built on a thread of its own and the interpolatory rule (microseconds)
// stands in; palette_rules_finished() tells the window when to ask again.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "impasto/data/pigments.hpp"
#include "impasto/data/spectrum.hpp"
#include "impasto/render/spectral_sampling.hpp"

namespace impasto::render {

// What a rule file is for: the content hash of everything the rule depends on (light,
// observer, range, node count, rule, pigments' names, K and S, ground, and the version of
// the optimiser), and the two figures a reader checks before trusting it.
struct NodeRuleKey {
  std::uint64_t hash = 0;
  NodeWeights weights = NodeWeights::optimised;
  int nodes = 0;
};

// A palette with fewer training paints (node_optimisation.hpp) than this many per node gets
// the interpolatory rule in place of a trained one: with a handful of paints (one pigment
// has four) the fitted readout reproduces them and little else. Measured at N = 8 on
// palettes of White, Black and others: 3 pigments (21 paints) max ΔE00 7.2
// trained against 3.1 interpolatory; 4 pigments (34 paints) 1.5 against 5.1.
inline constexpr std::size_t kMinTrainingPaintsPerNode = 4;

// The key of a palette's rule (what make_palette_sampling looks it up by), and the rule built
// from scratch, neither looked up nor kept (benchmarks time it).
NodeRuleKey palette_rule_key(const data::Spectrum& light, const data::ColorMatchingFunctions& cmf,
                             int nodes, const WavelengthRange& range, NodeWeights weights,
                             const std::vector<data::Pigment>& pigments,
                             const data::Spectrum& ground);
SpectralSampling build_palette_rule(const data::Spectrum& light,
                                    const data::ColorMatchingFunctions& cmf, int nodes,
                                    const WavelengthRange& range, NodeWeights weights,
                                    const std::vector<data::Pigment>& pigments,
                                    const data::Spectrum& ground);

// The rule file's text, and back. parse_node_rule throws std::runtime_error saying what is
// wrong (a wrong header, version, key or checksum; a node outside `range`, out of order or
// not finite; weights not finite or a white that is not theirs).
std::string format_node_rule(const NodeRuleKey& key, const SpectralSampling& sampling);
SpectralSampling parse_node_rule(std::string_view text, const NodeRuleKey& key,
                                 const WavelengthRange& range);

// The file of a key in the cache folder (read at each call: XDG_CACHE_HOME may change).
std::filesystem::path node_rule_file(const NodeRuleKey& key);
// The cached rule, or nothing: absent, or ignored with a warning on stderr when unreadable
// or damaged.
std::optional<SpectralSampling> load_node_rule(const NodeRuleKey& key,
                                               const WavelengthRange& range);
// Best effort: a cache that cannot be written is warned about and otherwise ignored.
void store_node_rule(const NodeRuleKey& key, const SpectralSampling& sampling);

// While one lives on a thread, make_palette_sampling on that thread does not wait for a
// rule that is neither in memory nor on disk: it starts its build in the background (once
// per key) and returns the interpolatory rule. Not nestable.
class BackgroundPaletteRules {
 public:
  BackgroundPaletteRules();
  ~BackgroundPaletteRules();
  BackgroundPaletteRules(const BackgroundPaletteRules&) = delete;
  BackgroundPaletteRules& operator=(const BackgroundPaletteRules&) = delete;

  // Whether a stand-in was returned while this lived.
  bool stood_in() const { return stood_in_; }
  void note_stand_in() { stood_in_ = true; }

 private:
  bool stood_in_ = false;
};

// How many background builds have finished (or failed) in this process: a caller that got a
// stand-in asks again when this changes.
std::uint64_t palette_rules_finished();
// Waits for the background builds in flight (tests; the process's exit waits too).
void wait_for_palette_rules();
// Forgets the rules held in memory, not those on disk (tests of the disk cache).
void forget_palette_rules_in_memory();

}  // namespace impasto::render
