// The `impasto` Python module (pybind11): what the command line does, for scripts and tests —
// paintings opened, made and saved, brushes loaded, pen samples sent, stroke files replayed,
// state read and renders taken as numpy arrays, the pigment library listed. docs/python.md.
#include <dlfcn.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "comparison.hpp"
#include "impasto/data/ks_fit.hpp"
#include "impasto/data/pigments.hpp"
#include "impasto/input/stroke_import.hpp"
#include "impasto/paintcore/paint_body.hpp"
#include "impasto/paintcore/painting.hpp"
#include "impasto/paintcore/simulation_params.hpp"
#include "impasto/render/pigment_records.hpp"
#include "impasto/render/relief_maps.hpp"
#include "impasto/render/render_painting.hpp"
#include "impasto/session/replay.hpp"

namespace py = pybind11;
namespace pc = impasto::paintcore;

namespace {

// Where the bundled data lies for a module that is not the impasto executable: the source
// tree's data/ when the module is in this build folder, else the installed layout
// (<prefix>/lib/python3/dist-packages/ → <prefix>/share/impasto). $IMPASTO_DATA_DIR wins.
void find_data() {
  if (const char* set = std::getenv("IMPASTO_DATA_DIR"); set != nullptr && *set != '\0') return;
  Dl_info info{};
  if (dladdr(reinterpret_cast<void*>(&find_data), &info) == 0 || info.dli_fname == nullptr) return;
  const std::filesystem::path module = std::filesystem::weakly_canonical(info.dli_fname);
  const std::filesystem::path build = std::filesystem::weakly_canonical(IMPASTO_BUILD_DIR);
  const auto [end, ignored] =
      std::mismatch(build.begin(), build.end(), module.begin(), module.end());
  const std::filesystem::path data = end == build.end()
                                         ? std::filesystem::path(IMPASTO_SOURCE_DATA_DIR)
                                         : module.parent_path() / "../../../share/impasto";
  if (std::filesystem::is_directory(data)) ::setenv("IMPASTO_DATA_DIR", data.c_str(), 0);
}

// A canvas-sized float32 array (rows, columns) filled by `value(tile, cell)` over the painted
// tiles; bare tiles stay 0.
template <typename Value>
py::array_t<float> canvas_plane(const pc::Canvas& canvas, const Value& value) {
  const int width = canvas.width_cells(), height = canvas.height_cells();
  py::array_t<float> out({height, width});
  auto view = out.mutable_unchecked<2>();
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) view(y, x) = 0.0f;
  for (int index = 0; index < canvas.tile_count(); ++index) {
    const pc::Tile* tile = canvas.tile(index);
    if (tile == nullptr) continue;
    const pc::CellRect cells = canvas.tile_cells(index);
    for (int y = cells.y0; y < cells.y1; ++y)
      for (int x = cells.x0; x < cells.x1; ++x)
        view(y, x) = value(*tile, (y - cells.y0) * pc::kTileSize + (x - cells.x0));
  }
  return out;
}

py::dict totals_dict(const pc::PaintTotals& totals, const std::vector<std::string>& slots) {
  py::dict pigments;
  for (std::size_t s = 0; s < slots.size() && s < totals.pigment.size(); ++s)
    pigments[py::str(slots[s])] = totals.pigment[s];
  py::dict out;
  out["volume_mm3"] = totals.volume;
  out["pigments_mm3"] = pigments;
  return out;
}

impasto::render::RenderSettings render_settings(const std::string& light, int wavelengths,
                                                std::pair<double, double> light_dir) {
  impasto::render::RenderSettings settings;
  settings.light = light;
  settings.wavelengths = wavelengths;
  settings.light_azimuth_deg = light_dir.first;
  settings.light_elevation_deg = light_dir.second;
  impasto::render::validate(settings);
  return settings;
}

pc::PenSample pen_sample(double x_mm, double y_mm, double pressure, double time_s, double tilt_x,
                         double tilt_y, double rotation) {
  pc::PenSample sample;
  sample.x_mm = x_mm;
  sample.y_mm = y_mm;
  sample.pressure = static_cast<float>(pressure);
  sample.time_s = time_s;
  sample.tilt_x_deg = static_cast<float>(tilt_x);
  sample.tilt_y_deg = static_cast<float>(tilt_y);
  sample.rotation_deg = static_cast<float>(rotation);
  sample.buttons = pc::kPenInRange | (pressure > 0.0 ? pc::kPenTip : 0u);
  return sample;
}

// A numpy array of `shape` holding a copy of `values` (row-major; by default one row).
template <typename T>
py::array_t<T> to_array(const std::vector<T>& values, std::vector<py::ssize_t> shape = {}) {
  if (shape.empty()) shape = {static_cast<py::ssize_t>(values.size())};
  py::array_t<T> out(shape);
  std::copy(values.begin(), values.end(), out.mutable_data());
  return out;
}

// A pigment's name, K and S on their wavelengths (nm), and its file's metadata.
py::dict pigment_dict(const impasto::data::Pigment& pigment) {
  py::dict out;
  out["name"] = pigment.name;
  out["wavelength_nm"] = to_array(pigment.K.wavelengths_nm);
  out["K"] = to_array(pigment.K.values);
  out["S"] = to_array(pigment.S.resampled(pigment.K.wavelengths_nm).values);
  out["metadata"] = pigment.metadata;
  return out;
}

}  // namespace

PYBIND11_MODULE(impasto, m) {
  m.doc() =
      "Impasto: thick paint on a height field, coloured by measured pigment spectra "
      "(Kubelka-Munk). Paintings, brushes, strokes, replays and spectral renders.";
  find_data();
  impasto::render::install_pigment_records();  // saved paintings carry their pigments

  py::class_<pc::Painting>(m, "Painting",
                           "A painting: its canvas of wet and dry paint, brush "
                           "and undo history")
      .def(py::init([](int width, int height, double dpi, std::uint64_t seed, int threads) {
             pc::Painting p(pc::CanvasSpec{width, height, dpi, seed}, threads);
             // The brush a new painting in the window has, where the cells can hold it.
             try {
               p.set_brush(pc::BrushSettings{});
             } catch (const std::exception&) {
             }
             return p;
           }),
           py::arg("width"), py::arg("height"), py::arg("dpi") = 150.0, py::arg("seed") = 1,
           py::arg("threads") = 0,
           "A blank canvas of width x height cells at dpi cells an inch (threads 0: all "
           "cores), with the round 4 mm brush")
      .def_static("load", &pc::Painting::load, py::arg("path"), py::arg("threads") = 0,
                  py::arg("history") = true, "Opens a .impasto painting")
      .def("save", &pc::Painting::save, py::arg("path"), "Saves to a .impasto file (atomically)")
      .def_property_readonly("width",
                             [](const pc::Painting& p) { return p.canvas().width_cells(); })
      .def_property_readonly("height",
                             [](const pc::Painting& p) { return p.canvas().height_cells(); })
      .def_property_readonly("cell_mm", [](const pc::Painting& p) { return p.canvas().cell_mm(); })
      .def_property_readonly("dpi",
                             [](const pc::Painting& p) { return 25.4 / p.canvas().cell_mm(); })
      .def_property_readonly("pigments", &pc::Painting::pigment_slots,
                             "The pigment slots, in the order amounts are kept")
      .def_property_readonly("state_hash", &pc::Painting::state_hash,
                             "A hash of the whole state (equal states, equal hashes)")
      .def_property_readonly("undo_depth", &pc::Painting::undo_depth)
      .def_property_readonly("redo_depth", &pc::Painting::redo_depth)
      .def_property(
          "params",
          [](const pc::Painting& p) {
            py::dict out;
            for (const pc::NamedParam& row : pc::all_simulation_params())
              out[row.name] = p.params().*row.field;
            return out;
          },
          [](pc::Painting& p, const std::map<std::string, double>& values) {
            pc::SimulationParams params = p.params();
            for (const auto& [name, value] : values) {
              const pc::NamedParam* row = pc::find_simulation_param(name);
              if (!row)
                throw py::key_error("no paint model constant '" + name +
                                    "' (impasto help params lists them)");
              params.*(row->field) = value;
            }
            p.set_params(params);  // validated: a value out of its row's range raises
          },
          "The paint model's constants {name: value} (impasto help params); assign a dict "
          "of those to change")
      .def(
          "set_brush",
          [](pc::Painting& p, const std::string& head, double size_mm, double stiffness) {
            p.set_brush(pc::BrushSettings{head, size_mm, stiffness});
          },
          py::arg("head") = "round", py::arg("size_mm") = 4.0, py::arg("stiffness") = 0.5,
          "Chooses a brush head (data/brushes) at a size and stiffness")
      .def(
          "load_brush",
          [](pc::Painting& p, const std::map<std::string, double>& mix, double volume_mm3,
             const std::string& body) {
            // Each a paint of the library (its name as the library spells it), as replays check.
            std::vector<pc::PigmentMixPart> parts;
            for (const auto& [pigment, share] : mix)
              parts.push_back(
                  {impasto::data::PigmentDatabase::defaults().get(pigment).name, share});
            const std::optional<pc::PaintBody> named = pc::paint_body_from_name(body);
            if (!body.empty() && !named)
              throw py::value_error("load_brush: unknown paint body '" + body +
                                    "' (fluid, soft, heavy, paste)");
            p.load_brush(parts, volume_mm3, named.value_or(pc::kDefaultPaintBody));
          },
          py::arg("mix"), py::arg("volume_mm3"), py::arg("body") = "",
          "Loads the brush with volume_mm3 of a mix {pigment: parts}, of a paint body "
          "(fluid, soft, heavy, paste)")
      .def(
          "wipe_brush",
          [](pc::Painting& p) { return totals_dict(p.wipe_brush(), p.pigment_slots()); },
          "Takes all paint off the brush; returns what was taken")
      .def("begin_stroke", &pc::Painting::begin_stroke)
      .def(
          "stroke_to",
          [](pc::Painting& p, double x_mm, double y_mm, double pressure, double time_s,
             double tilt_x, double tilt_y, double rotation) {
            p.stroke_to(pen_sample(x_mm, y_mm, pressure, time_s, tilt_x, tilt_y, rotation));
          },
          py::arg("x_mm"), py::arg("y_mm"), py::arg("pressure") = 0.7, py::arg("time_s") = 0.0,
          py::arg("tilt_x") = 0.0, py::arg("tilt_y") = 0.0, py::arg("rotation") = 0.0,
          "One pen sample of the stroke begun (canvas mm, +y down)")
      .def("end_stroke", &pc::Painting::end_stroke)
      .def(
          "stroke",
          [](pc::Painting& p,
             const py::array_t<double, py::array::c_style | py::array::forcecast>& points) {
            if (points.ndim() != 2 || (points.shape(1) != 3 && points.shape(1) != 4))
              throw py::value_error("stroke: points are rows of (x_mm, y_mm, pressure[, time_s])");
            const auto rows = points.unchecked<2>();
            p.begin_stroke();
            for (py::ssize_t i = 0; i < rows.shape(0); ++i)
              p.stroke_to(pen_sample(rows(i, 0), rows(i, 1), rows(i, 2),
                                     rows.shape(1) == 4 ? rows(i, 3) : 0.01 * i, 0, 0, 0));
            p.end_stroke();
          },
          py::arg("points"),
          "A whole stroke: rows of (x_mm, y_mm, pressure[, time_s]); times 10 ms apart by "
          "default")
      .def("dry", &pc::Painting::dry, py::arg("fraction") = 1.0,
           "Dries the bottom fraction of the wet layer into a new dry layer")
      .def("undo", &pc::Painting::undo)
      .def("redo", &pc::Painting::redo)
      .def(
          "heights",
          [](const pc::Painting& p) {
            const impasto::render::HeightGrid grid = impasto::render::surface_heights(p.canvas());
            return to_array(grid.mm, {grid.height, grid.width});
          },
          "The surface's height in mm over the ground's base, (rows, columns), float32 (a copy)")
      .def(
          "wet",
          [](const pc::Painting& p) {
            return canvas_plane(p.canvas(), [](const pc::Tile& t, int c) {
              return t.wet_volume_mm[static_cast<std::size_t>(c)];
            });
          },
          "The wet paint's height in mm, (rows, columns), float32 (a copy)")
      .def(
          "pigment",
          [](const pc::Painting& p, const std::string& name) {
            const auto& slots = p.pigment_slots();
            const auto found = std::find(slots.begin(), slots.end(), name);
            if (found == slots.end()) throw py::key_error("no pigment slot '" + name + "'");
            const int slot = static_cast<int>(found - slots.begin());
            return canvas_plane(p.canvas(), [slot](const pc::Tile& t, int c) {
              const float* amounts = t.pigment(slot);
              return amounts != nullptr ? amounts[c] : 0.0f;
            });
          },
          py::arg("name"), "A pigment's wet amount in mm of paint, (rows, columns), float32")
      .def(
          "totals",
          [](const pc::Painting& p) {
            py::dict out;
            out["canvas"] = totals_dict(p.canvas_totals(), p.pigment_slots());
            out["brush"] = totals_dict(p.brush_totals(), p.pigment_slots());
            out["loaded"] = totals_dict(p.loaded_totals(), p.pigment_slots());
            out["wiped"] = totals_dict(p.wiped_totals(), p.pigment_slots());
            return out;
          },
          "The ledger: paint on the canvas and the brush, loaded and wiped (mm^3, per pigment)")
      .def(
          "render",
          [](const pc::Painting& p, const std::string& light, int wavelengths,
             std::pair<double, double> light_dir) {
            const impasto::render::Image image =
                impasto::render::render_painting(p, render_settings(light, wavelengths, light_dir));
            return to_array(image.rgb, {image.height, image.width, 3});
          },
          py::arg("light") = "D65",
          py::arg("wavelengths") = impasto::render::RenderSettings{}.wavelengths,
          py::arg("light_dir") = std::pair{225.0, 60.0},
          "The spectral render, sRGB-encoded floats in [0, 1], (rows, columns, 3)")
      .def(
          "render_to",
          [](const pc::Painting& p, const std::filesystem::path& path, const std::string& light,
             int wavelengths, std::pair<double, double> light_dir) {
            impasto::render::render_painting_to_file(
                p, render_settings(light, wavelengths, light_dir), path);
          },
          py::arg("path"), py::arg("light") = "D65",
          py::arg("wavelengths") = impasto::render::RenderSettings{}.wavelengths,
          py::arg("light_dir") = std::pair{225.0, 60.0},
          "Renders to FILE.png (sRGB) or FILE.exr (linear), as impasto render does");

  m.def(
      "replay",
      [](const std::filesystem::path& path, int threads) {
        impasto::session::ReplayOptions options;
        options.threads = threads;
        py::gil_scoped_release unlocked;
        return impasto::session::replay(impasto::input::load_strokes_any(path), options);
      },
      py::arg("path"), py::arg("threads") = 0,
      "Replays a stroke file (.strokes, libmypaint .dat, BDALab .svc) as impasto replay does");
  m.def(
      "compare",
      [](const pc::Painting& a, const pc::Painting& b, double threshold) {
        const impasto::app::Comparison c =
            impasto::app::compare_paintings(a, b, threshold, "first", "second");
        py::dict out;
        out["de00_mean"] = c.de00_mean;
        out["de00_p95"] = c.de00_p95;
        out["de00_max"] = c.de00_max;
        out["pixels_over"] = c.pixels_over;
        out["threshold"] = threshold;
        out["height_mm_mean"] = *c.height_mm_mean;
        out["height_mm_max"] = *c.height_mm_max;
        out["de00"] = to_array(c.de00, {c.height, c.width});
        return out;
      },
      py::arg("a"), py::arg("b"), py::arg("threshold") = 1.0,
      "How far two paintings are apart, as impasto compare says: dE00 per pixel under D65 "
      "(mean, p95, max, pixels over threshold, and the (rows, columns) array) and the surface "
      "height difference in mm");
  m.def(
      "pigment",
      [](const std::string& name) {
        return pigment_dict(impasto::data::PigmentDatabase::defaults().get(name));
      },
      py::arg("name"),
      "A paint of the library: name, wavelength_nm, K and S (numpy arrays) and metadata");
  m.def(
      "fit_pigments",
      [](const std::filesystem::path& measurements, const std::string& reference) {
        impasto::data::KsFitProblem problem = impasto::data::read_ks_measurements(measurements);
        if (!reference.empty()) problem.reference_pigment = reference;
        const impasto::data::KsFitResult fit = impasto::data::fit_kubelka_munk(problem);
        py::list pigments, residuals;
        for (const auto& pigment : fit.pigments) pigments.append(pigment_dict(pigment));
        for (const auto& r : fit.residuals) {
          py::dict row;
          row["name"] = r.name;
          row["rms_reflectance"] = r.rms_reflectance;
          row["max_reflectance"] = r.max_reflectance;
          residuals.append(row);
        }
        py::dict out;
        out["pigments"] = pigments;
        out["residuals"] = residuals;
        return out;
      },
      py::arg("measurements"), py::arg("reference") = "",
      "Fits K and S from a measurements CSV of masstones and mixtures (docs/pigments.md), as "
      "impasto pigments fit does: the pigments (as pigment() gives them) and each sample's "
      "reflectance residuals. reference: the pigment whose S is fixed to 1 (default: the "
      "file's '# reference:')");
  m.def(
      "pigments",
      [] {
        std::vector<std::string> names;
        for (const auto& pigment : impasto::data::PigmentDatabase::defaults().all())
          names.push_back(pigment.name);
        return names;
      },
      "The names of the pigment library's paints (bundled, user, add-ons)");
}
