#pragma once
// The brush's records as the painting (painting_file.cpp) and its undo history
// (painting_history_file.cpp) both store them (docs/painting-format.md): one writer and one
// reader for each, so the two files cannot drift. What only one of them stores (the paint
// grid, body, slot count) stays with its writer.
#include <iterator>

#include "painting_file_io.hpp"

namespace impasto::paintcore::file_io {

// The head's shape: name, description, rise, base quadric, perturbations.
template <typename W>
void write_brush_head(W& w, const BrushHead& head) {
  w.put_string(head.name);
  w.put_string(head.description);
  w.put(head.rise);
  write_quadric(w, head.base);
  w.put(static_cast<std::uint32_t>(head.perturbations.size()));
  for (const Perturbation& pt : head.perturbations) {
    w.put(pt.factor);
    write_quadric(w, pt.shape);
  }
}

// `field` names the record in errors ("brush.head"); bristles and splay are left default.
inline BrushHead read_brush_head(Reader& r, const std::string& field) {
  BrushHead head;
  head.name = r.get_string(field + ".name");
  head.description = r.get_string(field + ".description");
  head.rise = r.get_finite(field + ".rise");
  if (head.rise < 0.0 || head.rise > 100.0) r.fail(field + ".rise", "must be in 0..100");
  head.base = read_quadric(r, field + ".base");
  const auto perturbations =
      r.get_count(field + ".perturbations", static_cast<std::uint32_t>(kMaxPerturbations));
  for (std::uint32_t k = 0; k < perturbations; ++k) {
    Perturbation pt;
    pt.factor = r.get_finite(field + ".perturbations.factor");
    pt.shape = read_quadric(r, field + ".perturbations.shape");
    head.perturbations.push_back(pt);
  }
  return head;
}

// The head's bristles and splay (version 3; docs/brushes.md): 4 × f64.
template <typename W>
void write_bristles(W& w, const BrushHead& head) {
  for (double v :
       {head.bristles.spacing_mm, head.bristles.depth_mm, head.bristles.jitter, head.splay})
    w.put(v);
}

// Into `head`; `field` as read_brush_head's.
inline void read_bristles(Reader& r, const std::string& field, BrushHead& head) {
  // In the file's order, which is kBristleSettings' (the ranges are its).
  static constexpr const char* kNames[] = {"bristles.spacing_mm", "bristles.depth_mm",
                                           "bristles.jitter", "splay"};
  static_assert(std::size(kNames) == kBristleSettings.size());
  for (std::size_t i = 0; i < kBristleSettings.size(); ++i) {
    const std::string name = field + "." + kNames[i];
    const double value = r.get_finite(name);
    if (!kBristleSettings[i].holds(value))
      r.fail(name, "must be in " + kBristleSettings[i].range_text());
    kBristleSettings[i].of(head) = value;
  }
}

// The brush settings: head file name, size, stiffness.
template <typename W>
void write_brush_settings(W& w, const BrushSettings& settings) {
  w.put_string(settings.head);
  w.put(settings.size_mm);
  w.put(settings.stiffness);
}

// `field` names the record in errors ("brush.settings").
inline BrushSettings read_brush_settings(Reader& r, const std::string& field) {
  BrushSettings settings;
  settings.head = r.get_string(field + ".head");
  settings.size_mm = r.get_finite(field + ".size_mm");
  settings.stiffness = r.get_finite(field + ".stiffness");
  return settings;
}

}  // namespace impasto::paintcore::file_io
