#include "impasto/render/relief_solid.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <stdexcept>
#include <string>

#include "impasto/files/atomic_file.hpp"
#include "impasto/util/text.hpp"

namespace impasto::render {
namespace {

// The grid of cell corners: (width + 1) x (height + 1) heights, row-major, top row first.
struct CornerGrid {
  int width = 0, height = 0;  // in cells
  std::vector<float> z;

  float at(int x, int y) const {
    return z[static_cast<std::size_t>(y) * static_cast<std::size_t>(width + 1) +
             static_cast<std::size_t>(x)];
  }
};

// A corner's height: the mean of the (up to four) cells that share it.
CornerGrid corner_heights(const HeightGrid& cells, double relief_scale) {
  CornerGrid grid{cells.width, cells.height, {}};
  grid.z.resize(static_cast<std::size_t>(cells.width + 1) *
                static_cast<std::size_t>(cells.height + 1));
  for (int y = 0; y <= cells.height; ++y) {
    for (int x = 0; x <= cells.width; ++x) {
      double sum = 0.0;
      int count = 0;
      for (int cy = std::max(y - 1, 0); cy <= std::min(y, cells.height - 1); ++cy) {
        for (int cx = std::max(x - 1, 0); cx <= std::min(x, cells.width - 1); ++cx) {
          sum += cells.at(cx, cy);
          ++count;
        }
      }
      grid.z[static_cast<std::size_t>(y) * static_cast<std::size_t>(cells.width + 1) +
             static_cast<std::size_t>(x)] = static_cast<float>(relief_scale * sum / count);
    }
  }
  return grid;
}

struct Leaf {
  int x, y, size;  // its corners span [x, x + size] x [y, y + size]
};

// Whether a fan of four triangles from the node's centre follows every corner inside it
// within `tolerance`.
bool fan_fits(const CornerGrid& g, const Leaf& n, double tolerance) {
  const int s = n.size;
  const double a = g.at(n.x, n.y), b = g.at(n.x + s, n.y), c = g.at(n.x, n.y + s),
               d = g.at(n.x + s, n.y + s), m = g.at(n.x + s / 2, n.y + s / 2);
  for (int j = 0; j <= s; ++j) {
    for (int i = 0; i <= s; ++i) {
      const double u = static_cast<double>(i) / s, v = static_cast<double>(j) / s;
      const double du = u - 0.5, dv = v - 0.5;
      double fan = 0.0;  // barycentric in the triangle of the centre and one side
      if (std::abs(dv) >= std::abs(du)) {
        fan = dv <= 0.0 ? 2 * v * m + (u - v) * b + (1 - u - v) * a
                        : 2 * (1 - v) * m + (u - (1 - v)) * d + (v - u) * c;
      } else {
        fan = du < 0.0 ? 2 * u * m + (v - u) * c + (1 - v - u) * a
                       : 2 * (1 - u) * m + (v - (1 - u)) * d + (u - v) * b;
      }
      if (std::abs(g.at(n.x + i, n.y + j) - fan) > tolerance) return false;
    }
  }
  return true;
}

void split(const CornerGrid& g, const Leaf& n, double tolerance, std::vector<Leaf>& leaves) {
  if (n.x >= g.width || n.y >= g.height) return;  // outside the canvas
  const bool partial = n.x + n.size > g.width || n.y + n.size > g.height;
  if (n.size == 1 || (!partial && fan_fits(g, n, tolerance))) {
    leaves.push_back(n);
    return;
  }
  const int h = n.size / 2;
  for (const Leaf child :
       {Leaf{n.x, n.y, h}, Leaf{n.x + h, n.y, h}, Leaf{n.x, n.y + h, h}, Leaf{n.x + h, n.y + h, h}})
    split(g, child, tolerance, leaves);
}

using Vec3 = std::array<float, 3>;

Vec3 cross_of(const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 u{b[0] - a[0], b[1] - a[1], b[2] - a[2]};
  const Vec3 v{c[0] - a[0], c[1] - a[1], c[2] - a[2]};
  return {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
}

// Builds the mesh: vertices are added once, triangles wound to face `outward`.
class SolidBuilder {
 public:
  explicit SolidBuilder(SolidMesh& mesh) : mesh_(mesh) {}
  std::uint32_t vertex(float x, float y, float z) {
    mesh_.vertices.push_back({x, y, z});
    return static_cast<std::uint32_t>(mesh_.vertices.size() - 1);
  }
  void triangle(std::uint32_t a, std::uint32_t b, std::uint32_t c, const Vec3& outward) {
    const Vec3 n = cross_of(mesh_.vertices[a], mesh_.vertices[b], mesh_.vertices[c]);
    if (n[0] * outward[0] + n[1] * outward[1] + n[2] * outward[2] < 0.0f) std::swap(b, c);
    mesh_.triangles.push_back({a, b, c});
  }

 private:
  SolidMesh& mesh_;
};

// The solid whose top follows the corners within `max_error_mm`.
SolidMesh build_solid(const CornerGrid& g, double cell_mm, double base_mm, double max_error_mm) {
  const int W = g.width, H = g.height;
  const auto cell = static_cast<float>(cell_mm);

  std::vector<Leaf> leaves;
  const int root = static_cast<int>(std::bit_ceil(static_cast<unsigned>(std::max(W, H))));
  split(g, {0, 0, root}, 0.5 * max_error_mm, leaves);

  SolidMesh mesh;
  SolidBuilder build(mesh);
  // The top's vertices: every leaf's corners, and the centre of each leaf wider than a cell.
  std::vector<std::int64_t> id(static_cast<std::size_t>(W + 1) * static_cast<std::size_t>(H + 1),
                               -1);
  const auto id_at = [&](int x, int y) -> std::int64_t& {
    return id[static_cast<std::size_t>(y) * static_cast<std::size_t>(W + 1) +
              static_cast<std::size_t>(x)];
  };
  const auto top_vertex = [&](int x, int y) {
    std::int64_t& v = id_at(x, y);
    if (v < 0) v = build.vertex(x * cell, (H - y) * cell, g.at(x, y));
    return static_cast<std::uint32_t>(v);
  };
  // Appends the vertex at corner (x, y) to `list` when the top has one there.
  const auto add_if_vertex = [&](std::vector<std::uint32_t>& list, int x, int y) {
    if (const std::int64_t v = id_at(x, y); v >= 0) list.push_back(static_cast<std::uint32_t>(v));
  };
  for (const Leaf& n : leaves) {
    for (const auto& [x, y] : {std::pair{n.x, n.y}, std::pair{n.x + n.size, n.y},
                               std::pair{n.x, n.y + n.size}, std::pair{n.x + n.size, n.y + n.size}})
      top_vertex(x, y);
  }
  const Vec3 up{0.0f, 0.0f, 1.0f};
  std::vector<std::uint32_t> ring;
  for (const Leaf& n : leaves) {
    const int s = n.size;
    if (s == 1) {
      const auto a = top_vertex(n.x, n.y), b = top_vertex(n.x + 1, n.y),
                 c = top_vertex(n.x + 1, n.y + 1), d = top_vertex(n.x, n.y + 1);
      build.triangle(a, b, c, up);
      build.triangle(a, c, d, up);
      continue;
    }
    // Around the leaf, every vertex on its edges (its corners and its finer neighbours').
    ring.clear();
    const auto on_edge = [&](int x, int y) { add_if_vertex(ring, x, y); };
    for (int i = 0; i < s; ++i) on_edge(n.x + i, n.y);
    for (int i = 0; i < s; ++i) on_edge(n.x + s, n.y + i);
    for (int i = s; i > 0; --i) on_edge(n.x + i, n.y + s);
    for (int i = s; i > 0; --i) on_edge(n.x, n.y + i);
    const auto centre = top_vertex(n.x + s / 2, n.y + s / 2);
    for (std::size_t k = 0; k < ring.size(); ++k)
      build.triangle(centre, ring[k], ring[(k + 1) % ring.size()], up);
  }

  // The border of the top, once around, and the sides down to the back.
  std::vector<std::uint32_t> border;
  const auto on_border = [&](int x, int y) { add_if_vertex(border, x, y); };
  for (int x = 0; x < W; ++x) on_border(x, 0);
  for (int y = 0; y < H; ++y) on_border(W, y);
  for (int x = W; x > 0; --x) on_border(x, H);
  for (int y = H; y > 0; --y) on_border(0, y);
  const float lowest = *std::min_element(g.z.begin(), g.z.end());
  const float back = std::min(lowest, 0.0f) - static_cast<float>(base_mm);
  std::vector<std::uint32_t> under(border.size());
  for (std::size_t k = 0; k < border.size(); ++k) {
    const Vec3 p = mesh.vertices[border[k]];
    under[k] = build.vertex(p[0], p[1], back);
  }
  const float cx = 0.5f * W * cell, cy = 0.5f * H * cell;
  for (std::size_t k = 0; k < border.size(); ++k) {
    const std::size_t next = (k + 1) % border.size();
    const Vec3 &a = mesh.vertices[border[k]], &b = mesh.vertices[border[next]];
    const Vec3 outward{0.5f * (a[0] + b[0]) - cx, 0.5f * (a[1] + b[1]) - cy, 0.0f};
    build.triangle(border[k], border[next], under[next], outward);
    build.triangle(border[k], under[next], under[k], outward);
  }
  const auto middle = build.vertex(cx, cy, back);
  for (std::size_t k = 0; k < under.size(); ++k)
    build.triangle(middle, under[k], under[(k + 1) % under.size()], {0.0f, 0.0f, -1.0f});
  return mesh;
}

}  // namespace

SolidMesh relief_solid(const HeightGrid& heights, const SolidOptions& options) {
  if (heights.width < 1 || heights.height < 1 ||
      heights.mm.size() !=
          static_cast<std::size_t>(heights.width) * static_cast<std::size_t>(heights.height))
    throw std::invalid_argument("relief_solid: an empty or inconsistent height grid");
  if (!(options.base_mm > 0.0) || !(options.relief_scale > 0.0) || !(options.max_error_mm >= 0.0) ||
      !std::isfinite(options.base_mm + options.relief_scale + options.max_error_mm))
    throw std::invalid_argument(
        "relief_solid: base_mm and relief_scale must be > 0 and max_error_mm >= 0");
  const CornerGrid g = corner_heights(heights, options.relief_scale);
  SolidMesh mesh = build_solid(g, heights.cell_mm, options.base_mm, options.max_error_mm);
  mesh.max_error_mm = options.max_error_mm;
  if (options.max_triangles == 0 || mesh.triangles.size() <= options.max_triangles) return mesh;
  // Too many: the smallest error whose mesh fits, found by halving the interval between the
  // asked error and the relief's whole range (where one fan spans the top), in log steps.
  const auto [low_z, high_z] = std::minmax_element(g.z.begin(), g.z.end());
  double fits = std::max(2.0 * (*high_z - *low_z), 1e-6);  // the fewest triangles
  SolidMesh best = build_solid(g, heights.cell_mm, options.base_mm, fits);
  best.max_error_mm = fits;
  if (best.triangles.size() > options.max_triangles) return best;  // nothing fewer exists
  double too_fine = std::max(options.max_error_mm, 1e-6);
  for (int k = 0; k < 14 && fits / too_fine > 1.02; ++k) {
    const double error = std::sqrt(fits * too_fine);
    SolidMesh trial = build_solid(g, heights.cell_mm, options.base_mm, error);
    if (trial.triangles.size() <= options.max_triangles) {
      fits = error;
      best = std::move(trial);
      best.max_error_mm = error;
    } else {
      too_fine = error;
    }
  }
  return best;
}

void colour_solid(SolidMesh& mesh, const Image& display, double cell_mm) {
  mesh.colours.assign(mesh.vertices.size(), {128, 128, 128});
  if (display.width < 1 || display.height < 1) return;
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
    const Vec3& p = mesh.vertices[i];
    const int x = std::clamp(static_cast<int>(std::floor(p[0] / cell_mm)), 0, display.width - 1);
    const int y = std::clamp(display.height - 1 - static_cast<int>(std::floor(p[1] / cell_mm)), 0,
                             display.height - 1);
    const float* rgb = display.pixel(x, y);
    for (int c = 0; c < 3; ++c) {
      mesh.colours[i][static_cast<std::size_t>(c)] =
          static_cast<std::uint8_t>(std::lround(255.0f * std::clamp(rgb[c], 0.0f, 1.0f)));
    }
  }
}

namespace {

static_assert(std::endian::native == std::endian::little, "STL and PLY are written little-endian");

template <typename T>
void put(std::string& out, T value) {
  char bytes[sizeof(T)];
  std::memcpy(bytes, &value, sizeof(T));
  out.append(bytes, sizeof(T));
}

std::string stl_bytes(const SolidMesh& mesh) {
  std::string out(80, ' ');
  out.replace(0, 33, "impasto relief solid, millimetres");
  put(out, static_cast<std::uint32_t>(mesh.triangles.size()));
  for (const auto& t : mesh.triangles) {
    Vec3 n = cross_of(mesh.vertices[t[0]], mesh.vertices[t[1]], mesh.vertices[t[2]]);
    const float length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    for (float& c : n) c = length > 0.0f ? c / length : 0.0f;
    for (const float c : n) put(out, c);
    for (const std::uint32_t v : t)
      for (const float c : mesh.vertices[v]) put(out, c);
    put(out, std::uint16_t{0});
  }
  return out;
}

std::string ply_bytes(const SolidMesh& mesh) {
  const bool colours = mesh.colours.size() == mesh.vertices.size();
  std::string out = "ply\nformat binary_little_endian 1.0\ncomment impasto relief solid, mm\n";
  out += "element vertex " + std::to_string(mesh.vertices.size()) + "\n";
  out += "property float x\nproperty float y\nproperty float z\n";
  if (colours) out += "property uchar red\nproperty uchar green\nproperty uchar blue\n";
  out += "element face " + std::to_string(mesh.triangles.size()) + "\n";
  out += "property list uchar int vertex_indices\nend_header\n";
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
    for (const float c : mesh.vertices[i]) put(out, c);
    if (colours)
      for (const std::uint8_t c : mesh.colours[i]) put(out, c);
  }
  for (const auto& t : mesh.triangles) {
    put(out, std::uint8_t{3});
    for (const std::uint32_t v : t) put(out, static_cast<std::int32_t>(v));
  }
  return out;
}

std::string obj_text(const SolidMesh& mesh) {
  const bool colours = mesh.colours.size() == mesh.vertices.size();
  std::string out = "# impasto relief solid, millimetres\n";
  char line[160];
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
    const Vec3& p = mesh.vertices[i];
    if (colours) {
      const auto& c = mesh.colours[i];
      std::snprintf(line, sizeof line, "v %.5f %.5f %.5f %.4f %.4f %.4f\n", p[0], p[1], p[2],
                    c[0] / 255.0, c[1] / 255.0, c[2] / 255.0);
    } else {
      std::snprintf(line, sizeof line, "v %.5f %.5f %.5f\n", p[0], p[1], p[2]);
    }
    out += line;
  }
  for (const auto& t : mesh.triangles) {
    std::snprintf(line, sizeof line, "f %u %u %u\n", t[0] + 1, t[1] + 1, t[2] + 1);
    out += line;
  }
  return out;
}

}  // namespace

void write_solid(const std::filesystem::path& path, const SolidMesh& mesh) {
  const std::string extension = util::ascii_lowercase(path.extension().string());
  if (extension == ".stl") {
    files::write_file_atomically(path, stl_bytes(mesh));
  } else if (extension == ".ply") {
    files::write_file_atomically(path, ply_bytes(mesh));
  } else if (extension == ".obj") {
    files::write_file_atomically(path, obj_text(mesh));
  } else {
    throw std::runtime_error(path.string() + ": a solid is written as .stl, .ply or .obj");
  }
}

}  // namespace impasto::render
