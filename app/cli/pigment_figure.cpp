#include "pigment_figure.hpp"

#include <impasto/files/atomic_file.hpp>
#include <impasto/render/image.hpp>
#include <impasto/render/pigment_swatches.hpp>
#include <impasto/util/text.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "pigment_curves.hpp"
#include "plot_ticks.hpp"
#include "window_services.hpp"

namespace impasto::app {
namespace {

constexpr Figure::Rgb kInk{0.1, 0.1, 0.1}, kGrid{0.85, 0.85, 0.85}, kWhite{1, 1, 1};
constexpr Figure::Rgb kKColour{0.80, 0.20, 0.15}, kSColour{0.15, 0.35, 0.80},
    kRatioColour{0.45, 0.25, 0.60}, kRColour{0.10, 0.50, 0.25};

struct Series {
  std::string name;
  std::vector<double> x, y;
  Figure::Rgb colour;
};

// One plot: frame, ticks and labels, curves, legend at its top right.
void add_plot(Figure& f, double left, double top, double w, double h, const std::string& title,
              const std::vector<Series>& series, double y_min_hint = 0.0) {
  double x0 = HUGE_VAL, x1 = -HUGE_VAL, y0 = y_min_hint, y1 = -HUGE_VAL;
  for (const auto& s : series) {
    for (std::size_t i = 0; i < s.x.size(); ++i) {
      if (!std::isfinite(s.y[i])) continue;
      x0 = std::min(x0, s.x[i]);
      x1 = std::max(x1, s.x[i]);
      y0 = std::min(y0, s.y[i]);
      y1 = std::max(y1, s.y[i]);
    }
  }
  if (!(x1 > x0)) x1 = x0 + 1;
  if (!(y1 > y0)) y1 = y0 + 1;
  y1 += (y1 - y0) * 0.05;
  const double pl = left + 48, pr = left + w - 26, pt = top + 24, pb = top + h - 34;
  auto px = [&](double x) { return pl + (x - x0) / (x1 - x0) * (pr - pl); };
  auto py = [&](double y) { return pb - (y - y0) / (y1 - y0) * (pb - pt); };
  f.texts.push_back({(pl + pr) / 2, top + 14, title, kInk, true});
  for (double t : nice_ticks(x0, x1, 6)) {
    f.lines.push_back({{{px(t), pt}, {px(t), pb}}, kGrid, 1});
    f.texts.push_back({px(t), pb + 14, tick_label(t), kInk, true});
  }
  f.texts.push_back({(pl + pr) / 2, pb + 28, "wavelength (nm)", kInk, true});
  for (double t : nice_ticks(y0, y1, 5)) {
    f.lines.push_back({{{pl, py(t)}, {pr, py(t)}}, kGrid, 1});
    f.texts.push_back({left + 2, py(t) + 4, tick_label(t), kInk, false});
  }
  f.lines.push_back({{{pl, pt}, {pl, pb}, {pr, pb}, {pr, pt}, {pl, pt}}, kInk, 1});
  double legend_y = pt + 14;
  for (const auto& s : series) {
    Figure::Line line{{}, s.colour, 2};
    for (std::size_t i = 0; i < s.x.size(); ++i) {
      if (std::isfinite(s.y[i])) line.points.push_back({px(s.x[i]), py(s.y[i])});
    }
    f.lines.push_back(std::move(line));
    if (series.size() > 1) {
      f.lines.push_back({{{pr - 70, legend_y - 4}, {pr - 52, legend_y - 4}}, s.colour, 2});
      f.texts.push_back({pr - 48, legend_y, s.name, kInk, false});
      legend_y += 16;
    }
  }
}

}  // namespace

Figure pigment_figure(const data::Pigment& pigment, const std::string& subtitle,
                      const data::Pigment& white, const data::Spectrum& light,
                      const std::string& light_name) {
  Figure f;
  f.width = 1200;
  f.height = 470;
  f.boxes.push_back({0, 0, double(f.width), double(f.height), kWhite, false});
  f.texts.push_back(
      {16, 22, pigment.name + (subtitle.empty() ? "" : "  -  " + subtitle), kInk, false});
  const PigmentCurves c = pigment_curves(pigment);
  const Series k{"K", c.nm, c.k, kKColour}, s{"S", c.nm, c.s, kSColour};
  const Series ratio{"K/S", c.nm, c.k_over_s, kRatioColour}, r{"R", c.nm, c.r_infinite, kRColour};
  add_plot(f, 8, 32, 395, 290, "K and S (S of white = 1)", {k, s});
  add_plot(f, 403, 32, 395, 290, "K/S", {ratio});
  add_plot(f, 798, 32, 395, 290, "R (opaque layer, R-infinity)", {r});

  const auto swatches = render::standard_swatches(pigment, white, light);
  const double chip_w = 180, gap = (f.width - 16 - chip_w * double(swatches.size())) /
                                   double(swatches.size() - 1);
  for (std::size_t i = 0; i < swatches.size(); ++i) {
    const double x = 8 + double(i) * (chip_w + gap), y = 350;
    const auto& c = swatches[i];
    f.boxes.push_back({x, y, chip_w, 70, {c.srgb[0], c.srgb[1], c.srgb[2]}, true});
    char lab[64];
    std::snprintf(lab, sizeof lab, "L*%.1f a*%.1f b*%.1f", c.lab.L, c.lab.a, c.lab.b);
    f.texts.push_back({x + chip_w / 2, y + 86, c.label, kInk, true});
    f.texts.push_back({x + chip_w / 2, y + 102, lab, kInk, true});
  }
  f.texts.push_back({f.width - 16.0, 22, "swatches under " + light_name + ", sRGB", kInk, false});
  f.texts.back().x -= 8.0 * double(f.texts.back().text.size());
  return f;
}

std::string figure_svg(const Figure& f) {
  auto colour = [](const Figure::Rgb& c) {
    char text[16];
    std::snprintf(text, sizeof text, "#%02x%02x%02x",
                  int(std::lround(std::clamp(c[0], 0.0, 1.0) * 255)),
                  int(std::lround(std::clamp(c[1], 0.0, 1.0) * 255)),
                  int(std::lround(std::clamp(c[2], 0.0, 1.0) * 255)));
    return std::string(text);
  };
  auto escape = [](const std::string& s) {
    std::string out;
    for (char c : s) {
      if (c == '<')
        out += "&lt;";
      else if (c == '>')
        out += "&gt;";
      else if (c == '&')
        out += "&amp;";
      else
        out += c;
    }
    return out;
  };
  std::string svg = "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + std::to_string(f.width) +
                    "\" height=\"" + std::to_string(f.height) +
                    "\" font-family=\"sans-serif\" font-size=\"12\">\n";
  char buf[256];
  for (const auto& b : f.boxes) {
    std::snprintf(buf, sizeof buf,
                  "<rect x=\"%.1f\" y=\"%.1f\" width=\"%.1f\" height=\"%.1f\" fill=\"%s\"%s/>\n",
                  b.x, b.y, b.w, b.h, colour(b.fill).c_str(), b.outline ? " stroke=\"#444\"" : "");
    svg += buf;
  }
  for (const auto& l : f.lines) {
    svg += "<polyline fill=\"none\" stroke=\"" + colour(l.colour) + "\" stroke-width=\"" +
           tick_label(l.width) + "\" points=\"";
    for (const auto& p : l.points) {
      std::snprintf(buf, sizeof buf, "%.1f,%.1f ", p[0], p[1]);
      svg += buf;
    }
    svg += "\"/>\n";
  }
  for (const auto& t : f.texts) {
    std::snprintf(buf, sizeof buf, "<text x=\"%.1f\" y=\"%.1f\" fill=\"%s\"%s>", t.x, t.y,
                  colour(t.colour).c_str(), t.centred ? " text-anchor=\"middle\"" : "");
    svg += buf + escape(t.text) + "</text>\n";
  }
  return svg + "</svg>\n";
}

namespace {

void blend(render::Image& image, int x, int y, const Figure::Rgb& c, double alpha) {
  if (x < 0 || y < 0 || x >= image.width || y >= image.height || alpha <= 0) return;
  float* p = image.pixel(x, y);
  for (int i = 0; i < 3; ++i)
    p[i] = static_cast<float>(p[i] * (1 - alpha) + c[static_cast<std::size_t>(i)] * alpha);
}

void draw_segment(render::Image& image, std::array<double, 2> a, std::array<double, 2> b,
                  const Figure::Rgb& c, double width) {
  const double r = width / 2;
  const int xs = int(std::floor(std::min(a[0], b[0]) - r - 1)),
            xe = int(std::ceil(std::max(a[0], b[0]) + r + 1));
  const int ys = int(std::floor(std::min(a[1], b[1]) - r - 1)),
            ye = int(std::ceil(std::max(a[1], b[1]) + r + 1));
  const double dx = b[0] - a[0], dy = b[1] - a[1], len2 = dx * dx + dy * dy;
  for (int y = ys; y <= ye; ++y) {
    for (int x = xs; x <= xe; ++x) {
      const double qx = x + 0.5 - a[0], qy = y + 0.5 - a[1];
      const double t = len2 > 0 ? std::clamp((qx * dx + qy * dy) / len2, 0.0, 1.0) : 0.0;
      const double d = std::hypot(qx - t * dx, qy - t * dy);
      blend(image, x, y, c, std::clamp(r + 0.5 - d, 0.0, 1.0));
    }
  }
}

}  // namespace

void write_figure(const std::filesystem::path& path, const Figure& f) {
  const std::string extension = util::ascii_lowercase(path.extension().string());
  if (extension == ".svg") {
    files::write_file_atomically(path, figure_svg(f));
    return;
  }
  if (extension != ".png") {
    throw std::runtime_error(path.string() + ": a plot is written as .png or .svg");
  }
  render::Image image{f.width, f.height,
                      std::vector<float>(3u * std::size_t(f.width) * std::size_t(f.height), 1.0f)};
  for (const auto& b : f.boxes) {
    for (int y = int(b.y); y < int(b.y + b.h); ++y) {
      for (int x = int(b.x); x < int(b.x + b.w); ++x) {
        const bool edge = b.outline && (y == int(b.y) || x == int(b.x) || y == int(b.y + b.h) - 1 ||
                                        x == int(b.x + b.w) - 1);
        blend(image, x, y, edge ? Figure::Rgb{0.27, 0.27, 0.27} : b.fill, 1.0);
      }
    }
  }
  for (const auto& l : f.lines) {
    for (std::size_t i = 1; i < l.points.size(); ++i)
      draw_segment(image, l.points[i - 1], l.points[i], l.colour, l.width);
  }
  // Labels where the window's font is at hand (the SVG carries them always).
  if (const WindowServices* services = window_services(); services && services->text_pixels)
    for (const auto& t : f.texts)
      services->text_pixels(t.text, t.x, t.y, t.centred,
                            [&](int x, int y, double a) { blend(image, x, y, t.colour, a); });
  render::write_png(path, image);
}

}  // namespace impasto::app
