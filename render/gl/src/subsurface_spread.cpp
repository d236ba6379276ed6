#include "impasto/render_gl/subsurface_spread.hpp"

#include <algorithm>
#include <stdexcept>

#include "embedded_shaders.hpp"
#include "impasto/render/display.hpp"

namespace impasto::render_gl {
namespace {

constexpr int kMaxRadius = render::kSubsurfaceMaxRadius;
constexpr int kSide = 2 * kMaxRadius + 1;  // a kernel's block in the atlas, padded to the most
constexpr int kAtlasColumns = 64;          // blocks a row of the atlas
// The gather's loop is bounded per square of kBlock cells by the largest radius of the mapped
// cells in it and its eight neighbours: as wide as the largest radius, so those are all that
// reach it.
constexpr int kBlock = kMaxRadius;
static_assert(kBlock >= kMaxRadius, "a block's neighbours must hold every cell that reaches it");

int blocks(int cells) {
  return (cells + kBlock - 1) / kBlock;
}

// Row-major 3x3 (as display.hpp gives it) to the column-major GLSL mat3.
std::array<float, 9> column_major(const std::array<double, 9>& m) {
  std::array<float, 9> out{};
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) {
      out[static_cast<std::size_t>(3 * c + r)] =
          static_cast<float>(m[static_cast<std::size_t>(3 * r + c)]);
    }
  }
  return out;
}

}  // namespace

GpuSubsurfaceSpread::GpuSubsurfaceSpread(int width_cells, int height_cells)
    : width_(width_cells), height_(height_cells), blank_(1, 1, 0, TexelFormat::kRGBA32F) {
  const float zero[4] = {0.0f, 0.0f, 0.0f, 0.0f};
  blank_.upload(0, 0, 1, 1, 0, zero, 1);
}

GpuSubsurfaceSpread::~GpuSubsurfaceSpread() = default;

std::string GpuSubsurfaceSpread::canvas_glsl() {
  return "#define SPREAD_MAP_FULL_SCALE " + std::to_string(render::kSubsurfaceMapFullScaleCells) +
         "\n" + shaders::subsurface_canvas_lib;
}

void GpuSubsurfaceSpread::clear() {
  kernel_ids_.clear();
  kernel_radius_.clear();
  atlas_texels_.clear();
  atlas_stale_ = false;
  radius_ = 0;
  mapped_count_ = 0;
  std::fill(mapped_.begin(), mapped_.end(), std::uint8_t{0});
  std::fill(own_block_radius_.begin(), own_block_radius_.end(), std::uint8_t{0});
  if (ids_.id() != 0) {
    const std::vector<float> no_radius(own_block_radius_.size(), 0.0f);
    block_radius_.upload(0, 0, blocks(width_), blocks(height_), 0, no_radius.data(),
                         blocks(width_));
    const std::vector<float> zeros(4 * static_cast<std::size_t>(width_) * height_, 0.0f);
    ids_.upload(0, 0, width_, height_, 0, zeros.data(), width_);
    lengths_.upload(0, 0, width_, height_, 0, zeros.data(), width_);
  }
}

void GpuSubsurfaceSpread::allocate_cell_textures() {
  if (ids_.id() != 0) return;
  ids_ = Texture(width_, height_, 0, TexelFormat::kRGBA32F);
  lengths_ = Texture(width_, height_, 0, TexelFormat::kRGBA32F);
  const std::vector<float> zeros(4 * static_cast<std::size_t>(width_) * height_, 0.0f);
  ids_.upload(0, 0, width_, height_, 0, zeros.data(), width_);
  lengths_.upload(0, 0, width_, height_, 0, zeros.data(), width_);
  mapped_.assign(static_cast<std::size_t>(width_) * height_, 0);
  own_block_radius_.assign(static_cast<std::size_t>(blocks(width_)) * blocks(height_), 0);
  block_radius_ = Texture(blocks(width_), blocks(height_), 0, TexelFormat::kR32F);
  const std::vector<float> no_radius(own_block_radius_.size(), 0.0f);
  block_radius_.upload(0, 0, blocks(width_), blocks(height_), 0, no_radius.data(), blocks(width_));
  delta_ = std::make_unique<Framebuffer>(width_, height_, TexelFormat::kRGBA32F);
  delta_->bind();
  glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
  glClear(GL_COLOR_BUFFER_BIT);
}

int GpuSubsurfaceSpread::kernel_id(const render::dipole::Medium& medium, float layer_mm,
                                   double cell_mm) {
  // The map's coefficients are quantised, so a painting holds a handful of kernels.
  const KernelKey key{medium.absorption_per_mm, medium.reduced_scattering_per_mm, medium.eta,
                      layer_mm};
  const auto found = kernel_ids_.find(key);
  if (found != kernel_ids_.end()) return found->second;
  const render::SpreadKernel kernel = render::spread_kernel(medium, layer_mm, cell_mm);
  const int id = static_cast<int>(kernel_radius_.size());
  kernel_ids_.emplace(key, id);
  kernel_radius_.push_back(kernel.radius);
  if (kernel.radius == 0) return id;  // the colour untouched: no block needed
  // The weights padded to kSide x kSide about the centre, and their prefix sums (for the
  // edge cells that keep the light of every offset beyond the canvas).
  const auto rows_needed = static_cast<std::size_t>(id / kAtlasColumns + 1);
  const std::size_t row_floats = 2 * static_cast<std::size_t>(kAtlasColumns) * kSide * kSide;
  if (atlas_texels_.size() < rows_needed * row_floats) {
    atlas_texels_.resize(rows_needed * row_floats, 0.0f);
  }
  const int ox = (id % kAtlasColumns) * kSide, oy = (id / kAtlasColumns) * kSide;
  const std::size_t stride = static_cast<std::size_t>(kAtlasColumns) * kSide;
  std::vector<double> prefix(static_cast<std::size_t>(kSide * kSide), 0.0);
  for (int j = 0; j < kSide; ++j) {
    double row = 0.0;
    for (int i = 0; i < kSide; ++i) {
      const int dx = i - kMaxRadius, dy = j - kMaxRadius;
      const bool inside = std::abs(dx) <= kernel.radius && std::abs(dy) <= kernel.radius;
      const float w = inside ? kernel.at(dx, dy) : 0.0f;
      row += w;
      const double above = j > 0 ? prefix[static_cast<std::size_t>((j - 1) * kSide + i)] : 0.0;
      prefix[static_cast<std::size_t>(j * kSide + i)] = above + row;
      float* texel = atlas_texels_.data() + 2 * ((oy + j) * stride + ox + i);
      texel[0] = w;
      texel[1] = static_cast<float>(prefix[static_cast<std::size_t>(j * kSide + i)]);
    }
  }
  radius_ = std::max(radius_, kernel.radius);
  atlas_stale_ = true;
  return id;
}

void GpuSubsurfaceSpread::set_cells(const paintcore::CellRect& region,
                                    const render::SubsurfaceMap& map) {
  const int x0 = std::max(region.x0, 0), y0 = std::max(region.y0, 0);
  const int x1 = std::min(region.x1, width_), y1 = std::min(region.y1, height_);
  if (x1 <= x0 || y1 <= y0) return;
  if (map.cells.empty() && mapped_count_ == 0) return;  // nothing was, nothing is
  if (map.cell_mm != cell_mm_ && !kernel_ids_.empty()) clear();
  cell_mm_ = map.cell_mm;
  allocate_cell_textures();
  const int w = x1 - x0, h = y1 - y0;
  std::vector<float> ids(4 * static_cast<std::size_t>(w) * h, 0.0f);
  std::vector<float> lengths(ids.size(), 0.0f);
  for (int y = y0; y < y1; ++y) {
    for (int x = x0; x < x1; ++x) {
      std::uint8_t& m = mapped_[static_cast<std::size_t>(y) * width_ + x];
      mapped_count_ -= m > 0 ? 1 : 0;
      m = 0;
    }
  }
  for (const render::SpreadingCell& cell : map.cells) {
    if (cell.x < x0 || cell.x >= x1 || cell.y < y0 || cell.y >= y1) continue;
    const std::size_t at = 4 * (static_cast<std::size_t>(cell.y - y0) * w + (cell.x - x0));
    int radius = 0;
    for (std::size_t c = 0; c < 3; ++c) {
      const int id = kernel_id(cell.medium[c], cell.layer_mm, map.cell_mm);
      const int r = kernel_radius_[static_cast<std::size_t>(id)];
      if (r > 0) ids[at + c] = static_cast<float>(id + 1);
      radius = std::max(radius, r);
      lengths[at + c] = cell.length_cells[c];
    }
    if (radius > 0) {
      mapped_[static_cast<std::size_t>(cell.y) * width_ + cell.x] =
          static_cast<std::uint8_t>(radius);
      ++mapped_count_;
    }
  }
  ids_.upload(x0, y0, w, h, 0, ids.data(), w);
  lengths_.upload(x0, y0, w, h, 0, lengths.data(), w);
  update_block_radius(x0 / kBlock, y0 / kBlock, (x1 - 1) / kBlock + 1, (y1 - 1) / kBlock + 1);
}

void GpuSubsurfaceSpread::update_block_radius(int bx0, int by0, int bx1, int by1) {
  const int bw = blocks(width_), bh = blocks(height_);
  // Each block's own largest radius, then the gather's: the largest of it and its neighbours.
  for (int by = by0; by < by1; ++by) {
    for (int bx = bx0; bx < bx1; ++bx) {
      std::uint8_t largest = 0;
      for (int y = by * kBlock; y < std::min((by + 1) * kBlock, height_); ++y) {
        const std::uint8_t* row = mapped_.data() + static_cast<std::size_t>(y) * width_;
        for (int x = bx * kBlock; x < std::min((bx + 1) * kBlock, width_); ++x) {
          largest = std::max(largest, row[x]);
        }
      }
      own_block_radius_[static_cast<std::size_t>(by) * bw + bx] = largest;
    }
  }
  const int gx0 = std::max(bx0 - 1, 0), gy0 = std::max(by0 - 1, 0);
  const int gx1 = std::min(bx1 + 1, bw), gy1 = std::min(by1 + 1, bh);
  std::vector<float> gather(static_cast<std::size_t>(gx1 - gx0) * (gy1 - gy0), 0.0f);
  for (int by = gy0; by < gy1; ++by) {
    for (int bx = gx0; bx < gx1; ++bx) {
      std::uint8_t largest = 0;
      for (int ny = std::max(by - 1, 0); ny <= std::min(by + 1, bh - 1); ++ny) {
        for (int nx = std::max(bx - 1, 0); nx <= std::min(bx + 1, bw - 1); ++nx) {
          largest = std::max(largest, own_block_radius_[static_cast<std::size_t>(ny) * bw + nx]);
        }
      }
      gather[static_cast<std::size_t>(by - gy0) * (gx1 - gx0) + (bx - gx0)] = largest;
    }
  }
  block_radius_.upload(gx0, gy0, gx1 - gx0, gy1 - gy0, 0, gather.data(), gx1 - gx0);
}

paintcore::CellRect GpuSubsurfaceSpread::mapped_box() const {
  if (mapped_count_ == 0) return {};
  paintcore::CellRect box{width_, height_, 0, 0};
  for (int y = 0; y < height_; ++y) {
    const std::uint8_t* row = mapped_.data() + static_cast<std::size_t>(y) * width_;
    const std::uint8_t* first =
        std::find_if(row, row + width_, [](std::uint8_t r) { return r > 0; });
    if (first == row + width_) continue;
    int last = width_ - 1;
    while (row[last] == 0) --last;
    box.x0 = std::min(box.x0, static_cast<int>(first - row));
    box.x1 = std::max(box.x1, last + 1);
    box.y0 = std::min(box.y0, y);
    box.y1 = y + 1;
  }
  return box;
}

Framebuffer& GpuSubsurfaceSpread::body() {
  if (!body_) body_ = std::make_unique<Framebuffer>(width_, height_, TexelFormat::kRGBA32F);
  return *body_;
}

void GpuSubsurfaceSpread::spread(const paintcore::CellRect& cells) {
  if (!delta_ || cells.empty()) return;
  if (!pass_) {
    std::string source = "#version 330 core\n#define SPREAD_MAX_RADIUS " +
                         std::to_string(kMaxRadius) + "\n#define SPREAD_ATLAS_COLUMNS " +
                         std::to_string(kAtlasColumns) + "\n#define SPREAD_BLOCK " +
                         std::to_string(kBlock) + "\n";
    source += shaders::subsurface_spread_frag;
    pass_ = std::make_unique<FullscreenPass>("subsurface_spread_frag.glsl", std::move(source));
  }
  if (atlas_stale_) {
    const int rows = static_cast<int>(
        atlas_texels_.size() / (2 * static_cast<std::size_t>(kAtlasColumns) * kSide * kSide));
    if (rows > atlas_rows_) {
      atlas_rows_ = std::max(rows, 2 * atlas_rows_);
      atlas_ = Texture(kAtlasColumns * kSide, atlas_rows_ * kSide, 0, TexelFormat::kRG32F);
    }
    atlas_.upload(0, 0, kAtlasColumns * kSide, rows * kSide, 0, atlas_texels_.data(),
                  kAtlasColumns * kSide);
    atlas_stale_ = false;
  }
  delta_->bind();  // texel row = cell row: the pass's rows are cell rows
  glEnable(GL_SCISSOR_TEST);
  glScissor(cells.x0, cells.y0, cells.x1 - cells.x0, cells.y1 - cells.y0);
  const ShaderProgram& program = pass_->program();
  program.use();
  body().color().bind(0);
  ids_.bind(1);
  (atlas_.id() != 0 ? atlas_ : blank_).bind(2);
  block_radius_.bind(3);
  glUniform1i(program.uniform("body"), 0);
  glUniform1i(program.uniform("kernel_ids"), 1);
  glUniform1i(program.uniform("kernels"), 2);
  glUniform1i(program.uniform("block_radius"), 3);
  glUniform2i(program.uniform("canvas_cells"), width_, height_);
  pass_->draw();
  check_gl_error("subsurface spread pass");
}

void GpuSubsurfaceSpread::bind(const ShaderProgram& program, bool enabled, bool map_view) const {
  (delta_ ? delta_->color() : blank_).bind(kDeltaUnit);
  (lengths_.id() != 0 ? lengths_ : blank_).bind(kLengthsUnit);
  glUniform1i(program.uniform("spread_delta"), kDeltaUnit);
  glUniform1i(program.uniform("spread_lengths"), kLengthsUnit);
  glUniform1i(program.uniform("spread_enabled"), enabled && delta_ ? 1 : 0);
  glUniform1i(program.uniform("spread_map_view"), map_view ? 1 : 0);
  static const std::array<float, 9> to_xyz =
      column_major(render::invert_3x3(render::xyz_to_linear_srgb()));
  static const std::array<float, 9> to_srgb = column_major(render::xyz_to_linear_srgb());
  glUniformMatrix3fv(program.uniform("spread_srgb_to_xyz"), 1, GL_FALSE, to_xyz.data());
  glUniformMatrix3fv(program.uniform("spread_xyz_to_srgb"), 1, GL_FALSE, to_srgb.data());
}

}  // namespace impasto::render_gl
