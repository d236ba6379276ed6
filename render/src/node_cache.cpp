// The trained rules kept in memory and on disk, and built in the background for a window
// (node_cache.hpp); make_palette_sampling (node_optimisation.hpp) is their entrance.
#include "impasto/render/node_cache.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <cinttypes>
#include <cmath>
#include <condition_variable>
#include <cstdio>
#include <exception>
#include <future>
#include <iostream>
#include <map>
#include <mutex>
#include <stdexcept>
#include <system_error>
#include <thread>
#include <vector>

#include "impasto/files/atomic_file.hpp"
#include "impasto/files/cache_dir.hpp"
#include "impasto/files/input_file.hpp"
#include "impasto/render/node_optimisation.hpp"
#include "impasto/util/fnv1a.hpp"

namespace impasto::render {
namespace {

constexpr std::string_view kHeader = "impasto node rule 1";
// Part of every key: bump it when the optimiser or the training paints change, so rules
// built by an older one are not reused.
constexpr double kOptimiserVersion = 2.0;
constexpr std::uint64_t kMaxRuleFileBytes = 16 << 10;
constexpr double kMaxWeight = 1e3;  // a readout weight far beyond any fitted one

// --- the file format ---

std::string hex(std::uint64_t value) {
  char text[17];
  std::snprintf(text, sizeof text, "%016" PRIx64, value);
  return text;
}

std::string exact(double value) {
  char text[64];
  const auto [end, error] = std::to_chars(text, text + sizeof text, value, std::chars_format::hex);
  return error == std::errc{} ? std::string(text, end) : std::string("nan");
}

double read_exact(std::string_view word, const std::string& what) {
  double value = 0.0;
  const auto [end, error] =
      std::from_chars(word.data(), word.data() + word.size(), value, std::chars_format::hex);
  if (error != std::errc{} || end != word.data() + word.size() || !std::isfinite(value)) {
    throw std::runtime_error(what + " is not a finite number");
  }
  return value;
}

std::vector<std::string_view> words_of(std::string_view line) {
  std::vector<std::string_view> words;
  std::size_t at = 0;
  while (at < line.size()) {
    const std::size_t end = std::min(line.find(' ', at), line.size());
    words.push_back(line.substr(at, end - at));
    at = end + 1;
  }
  return words;
}

std::uint64_t checksum(std::string_view text) {
  return util::fnv1a(text);
}

// --- the content key ---

// FNV-1a over everything a palette sampling depends on.
class ContentHash {
 public:
  void add_bytes(const void* data, std::size_t size) { hash_.add(data, size); }
  void add(double x) { add_bytes(&x, sizeof x); }
  void add(const std::string& text) {
    add(static_cast<double>(text.size()));
    add_bytes(text.data(), text.size());
  }
  void add(const data::Spectrum& spectrum) {
    add(static_cast<double>(spectrum.values.size()));
    for (double x : spectrum.wavelengths_nm) add(x);
    for (double x : spectrum.values) add(x);
  }
  std::uint64_t value() const { return hash_.value(); }

 private:
  util::Fnv1a hash_;
};

}  // namespace

NodeRuleKey palette_rule_key(const data::Spectrum& light, const data::ColorMatchingFunctions& cmf,
                             int nodes, const WavelengthRange& range, NodeWeights weights,
                             const std::vector<data::Pigment>& pigments,
                             const data::Spectrum& ground) {
  ContentHash hash;
  hash.add(kOptimiserVersion);
  hash.add(static_cast<double>(nodes));
  hash.add(static_cast<double>(weights));
  hash.add(range.first_nm);
  hash.add(range.last_nm);
  hash.add(range.step_nm);
  hash.add(light);
  hash.add(cmf.x);
  hash.add(cmf.y);
  hash.add(cmf.z);
  hash.add(ground);
  for (const auto& pigment : pigments) {
    hash.add(pigment.name);
    hash.add(pigment.K);
    hash.add(pigment.S);
  }
  return {hash.value(), weights, nodes};
}

SpectralSampling build_palette_rule(const data::Spectrum& light,
                                    const data::ColorMatchingFunctions& cmf, int nodes,
                                    const WavelengthRange& range, NodeWeights weights,
                                    const std::vector<data::Pigment>& pigments,
                                    const data::Spectrum& ground) {
  const PaletteTrainingSet training(light, cmf, range, pigments, ground);
  SpectralSampling sampling;
  RuleError estimate;
  if (weights == NodeWeights::fitted) {
    sampling = make_spectral_sampling(light, cmf, nodes, range, NodeWeights::interpolatory);
    training.fit_readout(sampling);
    estimate = training.error_of(sampling);
  } else {
    OptimisedRule optimised = optimise_nodes(training, light, cmf, nodes, range);
    sampling = std::move(optimised.sampling);
    estimate = optimised.training;
  }
  sampling.rule = util::name_of(kNodeWeightsNames, weights);
  sampling.estimated_mean_de00 = estimate.mean_de00;
  sampling.estimated_max_de00 = estimate.max_de00;
  return sampling;
}

namespace {

// --- the rules of this process ---

thread_local BackgroundPaletteRules* background_scope = nullptr;

struct Registry {
  std::mutex mutex;
  std::map<std::uint64_t, SpectralSampling> built;
  std::map<std::uint64_t, std::shared_future<SpectralSampling>> building;
  std::map<std::uint64_t, bool> failed;  // background builds that threw: not retried there
  std::uint64_t finished = 0;
  std::condition_variable idle;  // no background build in flight
  int in_flight = 0;
  std::vector<std::thread> threads;  // declared last: joined before the maps go

  ~Registry() {
    for (std::thread& thread : threads) thread.join();
  }
};

Registry& registry() {
  static Registry instance;
  return instance;
}

}  // namespace

std::string format_node_rule(const NodeRuleKey& key, const SpectralSampling& sampling) {
  std::string text(kHeader);
  text += "\nkey " + hex(key.hash) + "\nweights " +
          std::string(util::name_of(kNodeWeightsNames, key.weights)) + "\nnodes " +
          std::to_string(sampling.size()) + "\n";
  for (int i = 0; i < sampling.size(); ++i) {
    const auto k = static_cast<std::size_t>(i);
    text += "node " + exact(sampling.wavelengths_nm[k]);
    for (float w : sampling.to_xyz[k]) text += " " + exact(w);
    text += "\n";
  }
  text += "white";
  for (double w : sampling.white_xyz) text += " " + exact(w);
  text += "\n";
  // Optional (a file without it, from before, still reads): the training paints' error.
  if (sampling.estimated_mean_de00 >= 0.0)
    text += "estimate " + exact(sampling.estimated_mean_de00) + " " +
            exact(sampling.estimated_max_de00) + "\n";
  return text + "check " + hex(checksum(text)) + "\n";
}

SpectralSampling parse_node_rule(std::string_view text, const NodeRuleKey& key,
                                 const WavelengthRange& range) {
  const std::size_t check_at = text.rfind("check ");
  if (check_at == std::string_view::npos || (check_at > 0 && text[check_at - 1] != '\n')) {
    throw std::runtime_error("no checksum line");
  }
  if (text.substr(check_at) != "check " + hex(checksum(text.substr(0, check_at))) + "\n") {
    throw std::runtime_error("the checksum does not match the contents");
  }
  std::vector<std::string_view> lines;
  for (std::size_t at = 0; at < check_at;) {
    const std::size_t end = text.find('\n', at);
    lines.push_back(text.substr(at, end - at));
    at = end + 1;
  }
  const auto expect = [&](std::size_t line, const std::string& wanted, const std::string& what) {
    if (line >= lines.size() || lines[line] != wanted) {
      throw std::runtime_error("line " + std::to_string(line + 1) + ": " + what);
    }
  };
  expect(0, std::string(kHeader), "not an Impasto node rule of version 1");
  expect(1, "key " + hex(key.hash), "made for other inputs (key)");
  expect(2, "weights " + std::string(util::name_of(kNodeWeightsNames, key.weights)),
         "another rule");
  expect(3, "nodes " + std::to_string(key.nodes), "another node count");
  const std::size_t rule_lines = 5 + static_cast<std::size_t>(key.nodes);
  if (lines.size() != rule_lines && lines.size() != rule_lines + 1) {
    throw std::runtime_error("has " + std::to_string(lines.size()) +
                             " lines before the checksum, " + "not " +
                             std::to_string(5 + key.nodes) + " (or one more, the estimate)");
  }
  SpectralSampling sampling;
  std::array<double, 3> sum{0.0, 0.0, 0.0};
  for (int i = 0; i < key.nodes; ++i) {
    const std::size_t line = 4 + static_cast<std::size_t>(i);
    const std::string where = "line " + std::to_string(line + 1);
    const std::vector<std::string_view> words = words_of(lines[line]);
    if (words.size() != 5 || words[0] != "node") {
      throw std::runtime_error(where + ": not 'node NM X Y Z'");
    }
    const double nm = read_exact(words[1], where + ": the wavelength");
    const double previous =
        sampling.wavelengths_nm.empty() ? -1e300 : sampling.wavelengths_nm.back();
    if (nm < range.first_nm || nm > range.last_nm || !(nm > previous)) {
      throw std::runtime_error(where + ": wavelength " + std::to_string(nm) +
                               " nm is outside the range or out of order");
    }
    std::array<float, 3> weights{};
    for (std::size_t c = 0; c < 3; ++c) {
      const double w = read_exact(words[c + 2], where + ": a weight");
      if (std::abs(w) > kMaxWeight) throw std::runtime_error(where + ": a weight is out of range");
      weights[c] = static_cast<float>(w);
      sum[c] += weights[c];
    }
    sampling.wavelengths_nm.push_back(static_cast<float>(nm));
    sampling.to_xyz.push_back(weights);
  }
  const std::size_t white_line = 4 + static_cast<std::size_t>(key.nodes);
  const std::vector<std::string_view> white = words_of(lines[white_line]);
  if (white.size() != 4 || white[0] != "white") {
    throw std::runtime_error("line " + std::to_string(white_line + 1) + ": not 'white X Y Z'");
  }
  for (std::size_t c = 0; c < 3; ++c) {
    sampling.white_xyz[c] = read_exact(white[c + 1], "the white");
    if (std::abs(sampling.white_xyz[c] - sum[c]) > 1e-6 * std::max(1.0, std::abs(sum[c]))) {
      throw std::runtime_error("the white is not the sum of the weights");
    }
  }
  if (!(sampling.white_xyz[1] > 0.0)) throw std::runtime_error("the white has no luminance");
  if (lines.size() == rule_lines + 1) {
    const std::vector<std::string_view> estimate = words_of(lines[rule_lines]);
    const std::string where = "line " + std::to_string(rule_lines + 1);
    if (estimate.size() != 3 || estimate[0] != "estimate")
      throw std::runtime_error(where + ": not 'estimate MEAN MAX'");
    sampling.estimated_mean_de00 = read_exact(estimate[1], where + ": the mean");
    sampling.estimated_max_de00 = read_exact(estimate[2], where + ": the max");
    if (!(sampling.estimated_mean_de00 >= 0.0 && sampling.estimated_max_de00 >= 0.0 &&
          sampling.estimated_max_de00 < 1000.0))
      throw std::runtime_error(where + ": an estimate out of range");
  }
  return sampling;
}

std::filesystem::path node_rule_file(const NodeRuleKey& key) {
  return files::cache_dir("node-rules") /
         (std::string(util::name_of(kNodeWeightsNames, key.weights)) + "-" +
          std::to_string(key.nodes) + "-" + hex(key.hash) + ".txt");
}

std::optional<SpectralSampling> load_node_rule(const NodeRuleKey& key,
                                               const WavelengthRange& range) {
  const std::filesystem::path path = node_rule_file(key);
  std::error_code missing;
  if (!std::filesystem::exists(path, missing)) return std::nullopt;
  try {
    files::InputFile file(path, "node rule", kMaxRuleFileBytes);
    std::string text(static_cast<std::size_t>(file.size()), '\0');
    file.read_exact(text.data(), text.size());
    SpectralSampling sampling = parse_node_rule(text, key, range);
    sampling.rule = util::name_of(kNodeWeightsNames, key.weights);
    return sampling;
  } catch (const std::exception& error) {
    std::cerr << "impasto: warning: ignoring the cached node rule " << path.string() << ": "
              << error.what() << "; building it again\n";
    return std::nullopt;
  }
}

void store_node_rule(const NodeRuleKey& key, const SpectralSampling& sampling) {
  const std::filesystem::path path = node_rule_file(key);
  try {
    std::filesystem::create_directories(path.parent_path());
    // A link planted where the rule goes is replaced, never followed to the file it names.
    if (std::filesystem::is_symlink(path)) std::filesystem::remove(path);
    files::write_file_atomically(path, format_node_rule(key, sampling));
  } catch (const std::exception& error) {
    std::cerr << "impasto: warning: cannot keep the node rule in " << path.string() << ": "
              << error.what() << "\n";
  }
}

BackgroundPaletteRules::BackgroundPaletteRules() {
  background_scope = this;
}
BackgroundPaletteRules::~BackgroundPaletteRules() {
  background_scope = nullptr;
}

std::uint64_t palette_rules_finished() {
  Registry& r = registry();
  const std::lock_guard<std::mutex> lock(r.mutex);
  return r.finished;
}

void wait_for_palette_rules() {
  Registry& r = registry();
  std::unique_lock<std::mutex> lock(r.mutex);
  r.idle.wait(lock, [&] { return r.in_flight == 0; });
}

void forget_palette_rules_in_memory() {
  Registry& r = registry();
  const std::lock_guard<std::mutex> lock(r.mutex);
  r.built.clear();
}

SpectralSampling make_palette_sampling(const data::Spectrum& light,
                                       const data::ColorMatchingFunctions& cmf, int nodes,
                                       const WavelengthRange& range, NodeWeights weights,
                                       const std::vector<data::Pigment>& pigments,
                                       const data::Spectrum& ground) {
  const bool trained = weights == NodeWeights::fitted || weights == NodeWeights::optimised;
  // The Gaussian rule, which needs no paints: what serves until (or instead of) a trained one.
  SpectralSampling stand_in = make_spectral_sampling(
      light, cmf, nodes, range, trained ? NodeWeights::interpolatory : weights);
  // A light's own few lines are exact already. Too few training paints for the readout's
  // 3(N − 1) free weights: a rule fitted to them would fit those paints and little else (a
  // single pigment's four glazes), so the Gaussian rule serves, saying why.
  if (!trained || nodes == 0 || stand_in.light_lines) return stand_in;
  if (const std::size_t paints = training_paints(pigments).size();
      paints < kMinTrainingPaintsPerNode * static_cast<std::size_t>(nodes)) {
    stand_in.rule = "interpolatory: the " + std::string(util::name_of(kNodeWeightsNames, weights)) +
                    " rule trains on at least " +
                    std::to_string(kMinTrainingPaintsPerNode * static_cast<std::size_t>(nodes)) +
                    " paints for " + std::to_string(nodes) + " wavelengths; this palette gives " +
                    std::to_string(paints);
    return stand_in;
  }
  const NodeRuleKey key = palette_rule_key(light, cmf, nodes, range, weights, pigments, ground);

  Registry& r = registry();
  std::unique_lock<std::mutex> lock(r.mutex);
  if (const auto found = r.built.find(key.hash); found != r.built.end()) return found->second;
  if (background_scope && r.failed.count(key.hash) != 0) return stand_in;
  if (const auto found = r.building.find(key.hash); found != r.building.end()) {
    if (background_scope) {
      background_scope->note_stand_in();
      return stand_in;
    }
    const std::shared_future<SpectralSampling> pending = found->second;
    lock.unlock();
    return pending.get();
  }
  lock.unlock();
  if (std::optional<SpectralSampling> cached = load_node_rule(key, range)) {
    lock.lock();
    return r.built.emplace(key.hash, std::move(*cached)).first->second;
  }

  // Build it here, or on a thread of its own when the caller must not wait.
  auto promise = std::make_shared<std::promise<SpectralSampling>>();
  lock.lock();
  if (r.building.count(key.hash) == 0) {
    r.building.emplace(key.hash, promise->get_future().share());
  } else {
    promise.reset();  // another caller started it while the disk was read
  }
  const std::shared_future<SpectralSampling> pending = r.building.at(key.hash);
  lock.unlock();
  auto build = [=, &r] {
    try {
      SpectralSampling sampling =
          build_palette_rule(light, cmf, nodes, range, weights, pigments, ground);
      store_node_rule(key, sampling);
      const std::lock_guard<std::mutex> guard(r.mutex);
      r.built.emplace(key.hash, sampling);
      r.building.erase(key.hash);
      promise->set_value(std::move(sampling));
    } catch (...) {
      const std::lock_guard<std::mutex> guard(r.mutex);
      r.building.erase(key.hash);
      promise->set_exception(std::current_exception());
    }
  };
  if (!background_scope) {
    if (promise) build();
    return pending.get();
  }
  background_scope->note_stand_in();
  if (promise) {
    lock.lock();
    ++r.in_flight;
    r.threads.emplace_back([build, pending, key, &r] {
      build();
      try {
        pending.get();
      } catch (const std::exception& error) {
        std::cerr << "impasto: warning: the " << util::name_of(kNodeWeightsNames, key.weights)
                  << " rule could not be built (" << error.what()
                  << "); the interpolatory rule stays\n";
        const std::lock_guard<std::mutex> guard(r.mutex);
        r.failed[key.hash] = true;
      }
      const std::lock_guard<std::mutex> guard(r.mutex);
      ++r.finished;
      --r.in_flight;
      r.idle.notify_all();
    });
  }
  return stand_in;
}

}  // namespace impasto::render
