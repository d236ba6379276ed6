#include "impasto/render/color_accuracy.hpp"

#include <Imath/half.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <stdexcept>
#include <tuple>
#include <utility>

#include "impasto/data/colorimetry.hpp"
#include "impasto/render/kubelka_munk_cell.hpp"
#include "impasto/render/paint_layer.hpp"
#include "impasto/render/spectral_palette.hpp"
#include "spectral_kernels.hpp"

namespace impasto::render {
namespace {

constexpr float kOpaqueMm = 5.0f;
constexpr float kGlazeMm = 0.0005f;  // 0.1 units of optical thickness at the default scale
constexpr float kTintPigmentShare = 0.1f;

int index_of(const std::vector<data::Pigment>& pigments, const std::string& name) {
  for (std::size_t i = 0; i < pigments.size(); ++i) {
    if (pigments[i].name == name) return static_cast<int>(i);
  }
  throw std::runtime_error("colour accuracy: the pigment set lacks '" + name + "'");
}

const data::Pigment& find_pigment(const std::vector<data::Pigment>& pigments,
                                  const std::string& name) {
  return pigments[static_cast<std::size_t>(index_of(pigments, name))];
}

// Everything one node count needs: its palette and both grounds at its nodes.
struct SampledScene {
  SpectralPalette palette;
  std::vector<float> white_ground, black_ground;
};

SampledScene sample_scene(const data::Spectrum& light, int nodes, NodeWeights weights,
                          const std::vector<data::Pigment>& pigments) {
  RenderSettings settings;
  settings.wavelengths = nodes;
  settings.node_weights = weights;
  settings.adaptation = ChromaticAdaptation::none;  // Lab below is relative to own white
  const data::Spectrum white = hiding_reflectance(find_pigment(pigments, "White"));
  const data::Spectrum black = hiding_reflectance(find_pigment(pigments, "Black"));
  SpectralPalette palette(settings, light, pigments, white);
  std::vector<float> black_ground = sample_at_nodes(black, palette.sampling());
  std::vector<float> white_ground(palette.ground(), palette.ground() + palette.nodes());
  return {std::move(palette), std::move(white_ground), std::move(black_ground)};
}

float round_to_half(float value) {
  return static_cast<float>(Imath::half(value));
}

std::vector<PigmentShare> shares_of(const std::vector<std::pair<int, float>>& mix) {
  std::vector<PigmentShare> shares;
  for (const auto& [pigment, concentration] : mix) shares.push_back({pigment, concentration});
  return shares;
}

data::Lab render_sample(const SampledScene& scene, const ColorSample& sample,
                        ReflectanceStorage storage, double thickness_scale_mm) {
  const SpectralPalette& palette = scene.palette;
  // Up to one value per grid wavelength (the full spectrum), so on the heap.
  std::vector<float> reflectance(static_cast<std::size_t>(palette.nodes()));
  float* r = reflectance.data();
  const auto& ground = sample.over_black ? scene.black_ground : scene.white_ground;
  for (int i = 0; i < palette.nodes(); ++i) {
    const float g = ground[static_cast<std::size_t>(i)];
    r[i] = storage == ReflectanceStorage::float16 ? round_to_half(g) : g;
  }
  if (!sample.under_mix.empty()) {
    composite_paint_layer(palette, shares_of(sample.under_mix),
                          static_cast<float>(sample.under_mm / thickness_scale_mm), r);
    // The dry layers are baked into the substrate, stored as the renderer stores them.
    if (storage == ReflectanceStorage::float16)
      for (int i = 0; i < palette.nodes(); ++i) r[i] = round_to_half(r[i]);
  }
  if (!sample.mix.empty())
    composite_paint_layer(palette, shares_of(sample.mix),
                          static_cast<float>(sample.thickness_mm / thickness_scale_mm), r);
  if (sample.through_surface) {  // the interface RenderSettings has by default
    const auto k1 = static_cast<float>(data::kSaundersonK1);
    const auto k2 = static_cast<float>(data::kSaundersonK2);
    for (int i = 0; i < palette.nodes(); ++i) r[i] = k1 + km::saunderson(r[i], k1, k2);
  }
  float xyz[3];
  node_reflectance_to_xyz(palette, r, xyz);
  const auto& white = palette.white_xyz();
  return data::xyz_to_lab({xyz[0], xyz[1], xyz[2]}, {white[0], white[1], white[2]});
}

// CPU time of this thread (ns): unlike wall time, not inflated when the machine is busy.
double thread_cpu_ns() {
  timespec now{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &now);
  return static_cast<double>(now.tv_sec) * 1e9 + static_cast<double>(now.tv_nsec);
}

// Nanoseconds (thread CPU time) per cell of the per-frame work, through the tile renderer's
// spectral kernels (spectral_kernels.hpp) as it runs them, a row of 64 cells at a time:
// substrate load (float or half), a two-pigment wet layer, XYZ. Best of three runs. The full
// spectrum (more nodes than a kernel takes) is timed through the scalar reference.
std::pair<double, double> time_cells(const SampledScene& scene, ReflectanceStorage storage,
                                     int cells, double thickness_scale_mm) {
  const SpectralPalette& palette = scene.palette;
  const int nodes = palette.nodes();
  const auto count = static_cast<std::size_t>(cells);
  std::vector<float> substrate_f32(count * static_cast<std::size_t>(nodes));
  for (std::size_t k = 0; k < substrate_f32.size(); ++k) {
    substrate_f32[k] = scene.white_ground[k % static_cast<std::size_t>(nodes)] *
                       (0.5f + 0.5f * static_cast<float>(k % 7) / 7.0f);
  }
  std::vector<Imath::half> substrate_f16(substrate_f32.begin(), substrate_f32.end());
  const int pigments = palette.pigment_count();
  // Wet paint: 1 mm³/mm² scale volumes, 70/30 of two pigments (a pair per row of cells).
  std::vector<float> volume(count), first_amount(count), second_amount(count);
  for (std::size_t c = 0; c < count; ++c) {
    volume[c] = 0.005f + 0.001f * static_cast<float>(c % 100);
    first_amount[c] = 0.7f * volume[c];
    second_amount[c] = 0.3f * volume[c];
  }
  const auto optical_per_mm = static_cast<float>(1.0 / thickness_scale_mm);
  const bool kernels_take_it = nodes <= kMaxNodes;
  const kernels::PaddedPalette padded(palette, RenderSettings{});
  const auto stride = static_cast<std::size_t>(kernels_take_it ? padded.padded : nodes);
  constexpr std::size_t kRow = 64;
  std::vector<float> row(kRow * stride, 0.0f);
  std::vector<float> xyz(3 * kRow);
  double best = 1e300, worst = 0.0;
  for (int run = 0; run < 3; ++run) {
    float checksum = 0.0f;
    const double start = thread_cpu_ns();
    for (std::size_t first = 0; first < count; first += kRow) {
      const std::size_t n = std::min(kRow, count - first);
      for (std::size_t c = 0; c < n; ++c) {
        const std::size_t from = (first + c) * static_cast<std::size_t>(nodes);
        float* to = &row[c * stride];
        for (int i = 0; i < nodes; ++i) {
          const std::size_t k = from + static_cast<std::size_t>(i);
          to[i] = storage == ReflectanceStorage::float16 ? static_cast<float>(substrate_f16[k])
                                                         : substrate_f32[k];
        }
      }
      const int pair[2] = {
          static_cast<int>((first / kRow) % static_cast<std::size_t>(pigments)),
          static_cast<int>((first / kRow + 1) % static_cast<std::size_t>(pigments))};
      if (kernels_take_it) {
        const float* amounts[2] = {&first_amount[first], &second_amount[first]};
        kernels::composite_layer_cells(padded, {&volume[first], 2, pair, amounts},
                                       static_cast<int>(n), optical_per_mm, row.data());
        kernels::cells_to_xyz(padded, row.data(), static_cast<int>(n), xyz.data());
      } else {
        for (std::size_t c = 0; c < n; ++c) {
          const PigmentShare shares[2] = {{pair[0], 0.7f}, {pair[1], 0.3f}};
          composite_paint_layer(palette, shares, volume[first + c] * optical_per_mm,
                                &row[c * stride]);
          node_reflectance_to_xyz(palette, &row[c * stride], &xyz[3 * c]);
        }
      }
      for (std::size_t c = 0; c < n; ++c) checksum += xyz[3 * c + 1];
    }
    const double ns = (thread_cpu_ns() - start) / static_cast<double>(cells);
    best = std::min(best, ns);
    worst = std::max(worst, ns);
    if (!(checksum >= 0.0f)) throw std::runtime_error("colour timing: non-finite result");
  }
  return {best, worst - best};
}

// A sample of one layer over a ground (kind empty: the standard samples).
ColorSample layer_sample(std::string name, std::vector<std::pair<int, float>> mix,
                         float thickness_mm, bool over_black, std::string kind = {}) {
  ColorSample sample;
  sample.name = std::move(name);
  sample.mix = std::move(mix);
  sample.thickness_mm = thickness_mm;
  sample.over_black = over_black;
  sample.kind = std::move(kind);
  return sample;
}

}  // namespace

std::vector<ColorSample> standard_color_samples(const std::vector<data::Pigment>& pigments) {
  const int white = index_of(pigments, "White");
  index_of(pigments, "Black");
  std::vector<ColorSample> samples;
  const int count = static_cast<int>(pigments.size());
  for (int p = 0; p < count; ++p) {
    const std::string& name = pigments[static_cast<std::size_t>(p)].name;
    samples.push_back(layer_sample(name + " masstone", {{p, 1.0f}}, kOpaqueMm, false));
    if (p != white) {
      samples.push_back(layer_sample(name + " tint",
                                     {{p, kTintPigmentShare}, {white, 1.0f - kTintPigmentShare}},
                                     kOpaqueMm, false));
    }
    samples.push_back(layer_sample(name + " glaze over white", {{p, 1.0f}}, kGlazeMm, false));
    samples.push_back(layer_sample(name + " glaze over black", {{p, 1.0f}}, kGlazeMm, true));
  }
  for (int p = 0; p < count; ++p) {
    for (int q = p + 1; q < count; ++q) {
      samples.push_back(layer_sample(pigments[static_cast<std::size_t>(p)].name + " + " +
                                         pigments[static_cast<std::size_t>(q)].name,
                                     {{p, 0.5f}, {q, 0.5f}}, kOpaqueMm, false));
    }
  }
  return samples;
}

std::vector<ColorSample> painting_color_samples(const std::vector<data::Pigment>& pigments) {
  const int white = index_of(pigments, "White");
  index_of(pigments, "Black");
  const double scale = RenderSettings{}.thickness_scale_mm;
  const int count = static_cast<int>(pigments.size());
  const auto name_of = [&](int p) { return pigments[static_cast<std::size_t>(p)].name; };
  std::vector<ColorSample> samples;
  const auto add = [&](ColorSample sample) {
    sample.through_surface = true;
    samples.push_back(std::move(sample));
  };
  add(layer_sample("the bare ground", {}, 0.0f, false, "ground"));
  // Mixes: every pigment alone and every pair 50/50.
  std::vector<std::pair<std::string, std::vector<std::pair<int, float>>>> mixes;
  for (int p = 0; p < count; ++p) mixes.push_back({name_of(p), {{p, 1.0f}}});
  for (int p = 0; p < count; ++p)
    for (int q = p + 1; q < count; ++q)
      mixes.push_back({name_of(p) + " + " + name_of(q), {{p, 0.5f}, {q, 0.5f}}});
  for (const auto& [name, mix] : mixes)
    add(layer_sample(name + " masstone", mix, kOpaqueMm, false, "masstone"));
  for (int p = 0; p < count; ++p) {
    if (p == white) continue;
    for (const int parts : {1, 2, 5, 10, 20}) {
      const float share = 1.0f / static_cast<float>(1 + parts);
      add(layer_sample(name_of(p) + " tint 1:" + std::to_string(parts),
                       {{p, share}, {white, 1.0f - share}}, kOpaqueMm, false, "tint"));
    }
  }
  for (const auto& [name, mix] : mixes)
    for (const double units : {0.5, 1.0, 2.0, 5.0, 10.0, 20.0, 50.0})
      for (const bool black : {false, true}) {
        char label[32];
        std::snprintf(label, sizeof label, " glaze %g over %s", units, black ? "black" : "ground");
        add(layer_sample(name + label, mix, static_cast<float>(units * scale), black, "glaze"));
      }
  for (int p = 0; p < count; ++p)
    for (int q = 0; q < count; ++q) {
      if (p == q || q == white) continue;
      for (const double units : {2.0, 10.0}) {
        ColorSample sample =
            layer_sample(name_of(p) + " " + std::to_string(static_cast<int>(units)) + " over dry " +
                             name_of(q) + " tint 1:2",
                         {{p, 1.0f}}, static_cast<float>(units * scale), false, "stack");
        sample.under_mix = {{q, 1.0f / 3.0f}, {white, 2.0f / 3.0f}};
        sample.under_mm = kOpaqueMm;
        add(std::move(sample));
      }
    }
  return samples;
}

std::vector<bool> frontier_points(const std::vector<CostAndError>& points) {
  std::vector<bool> on(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    const CostAndError& p = points[i];
    on[i] = std::none_of(points.begin(), points.end(), [&](const CostAndError& other) {
      return other.group == p.group &&
             other.ns_per_cell <= p.ns_per_cell + std::max(p.ns_spread, other.ns_spread) &&
             other.error < p.error;
    });
  }
  return on;
}

ClassError summarise_errors(std::string kind,
                            const std::vector<std::pair<double, std::string>>& errors) {
  ClassError out;
  out.kind = std::move(kind);
  out.count = static_cast<int>(errors.size());
  if (errors.empty()) return out;
  std::vector<double> sorted;
  for (const auto& [de, name] : errors) {
    sorted.push_back(de);
    out.mean_de00 += de / static_cast<double>(errors.size());
    if (de > out.max_de00 || out.worst.empty()) out.max_de00 = de, out.worst = name;
  }
  std::sort(sorted.begin(), sorted.end());
  // The nearest rank: the smallest error that at least 95 % of the samples do not exceed.
  const auto rank = static_cast<std::size_t>(std::ceil(0.95 * static_cast<double>(sorted.size())));
  out.p95_de00 = sorted[std::max<std::size_t>(rank, 1) - 1];
  return out;
}

AccuracyResult evaluate_color_accuracy(const data::Spectrum& light, const std::string& light_name,
                                       int nodes, const std::vector<data::Pigment>& pigments,
                                       const std::vector<ColorSample>& samples,
                                       ReflectanceStorage storage, NodeWeights weights,
                                       int timing_cells) {
  if (samples.empty()) throw std::runtime_error("colour accuracy: no samples");
  const double thickness_scale_mm = RenderSettings{}.thickness_scale_mm;
  const SampledScene reference = sample_scene(light, 0, weights, pigments);
  const SampledScene scene = nodes == 0 ? reference : sample_scene(light, nodes, weights, pigments);

  AccuracyResult result;
  result.nodes = nodes;
  result.light = light_name;
  result.storage = storage;
  double sum = 0.0;
  std::vector<std::string> kinds;
  std::vector<std::vector<std::pair<double, std::string>>> by_kind;
  for (const ColorSample& sample : samples) {
    const data::Lab expected =
        render_sample(reference, sample, ReflectanceStorage::float32, thickness_scale_mm);
    const data::Lab got = render_sample(scene, sample, storage, thickness_scale_mm);
    const double difference = data::ciede2000(expected, got);
    sum += difference;
    if (!sample.kind.empty()) {
      const auto at = std::find(kinds.begin(), kinds.end(), sample.kind) - kinds.begin();
      if (at == static_cast<std::ptrdiff_t>(kinds.size())) {
        kinds.push_back(sample.kind);
        by_kind.emplace_back();
      }
      by_kind[static_cast<std::size_t>(at)].push_back({difference, sample.name});
    }
    if (difference > result.max_de00) {  // stays empty when every sample is exact
      result.max_de00 = difference;
      result.worst_sample = sample.name;
    }
  }
  result.mean_de00 = sum / static_cast<double>(samples.size());
  for (std::size_t k = 0; k < kinds.size(); ++k)
    result.classes.push_back(summarise_errors(kinds[k], by_kind[k]));
  if (timing_cells > 0) {
    std::tie(result.ns_per_cell, result.ns_per_cell_spread) =
        time_cells(scene, storage, timing_cells, thickness_scale_mm);
  }
  return result;
}

}  // namespace impasto::render
