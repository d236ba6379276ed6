#include "impasto/render_gl/tile_atlas.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "impasto/paintcore/canvas.hpp"

namespace impasto::render_gl {

using paintcore::kTileCells;
using paintcore::kTileSize;

namespace {

// Places a row: 64 (an atlas 4096 texels wide) unless the GPU's largest texture needs wider
// rows to hold every tile.
constexpr int kPreferredColumns = 64;

int max_texture_size() {
  GLint size = 0;
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &size);
  return size;
}

}  // namespace

TileAtlas::TileAtlas(int tiles_x, int tiles_y, int layers)
    : tiles_x_(tiles_x), tiles_y_(tiles_y), layers_(layers) {
  if (tiles_x <= 0 || tiles_y <= 0 || layers <= 0) {
    throw std::invalid_argument("tile atlas of " + std::to_string(tiles_x) + "x" +
                                std::to_string(tiles_y) + " tiles, " + std::to_string(layers) +
                                " layers");
  }
  const int tiles = tiles_x * tiles_y;
  const int most_rows = std::max(1, max_texture_size() / kTileSize);
  columns_ = std::min(tiles, std::max(kPreferredColumns, (tiles + most_rows - 1) / most_rows));
  max_rows_ = std::min(most_rows, (tiles + columns_ - 1) / columns_);
  place_of_.assign(static_cast<std::size_t>(tiles), -1);
  // A stand-in of the atlas's kind until the first place: Mesa's llvmpipe compiles a shader
  // again (about 0.2 s) when a sampler's texture kind changes, as from none to the atlas at
  // the first stroke.
  atlas_ = Texture(1, 1, layers_, TexelFormat::kRGBA32F);
  table_ = Texture(tiles_x, tiles_y, 0, TexelFormat::kR32F);
  const std::vector<float> none(static_cast<std::size_t>(tiles), 0.0f);
  table_.upload(0, 0, tiles_x, tiles_y, 0, none.data(), tiles_x);
}

bool TileAtlas::placed(int tile_index) const {
  return place_of_.at(static_cast<std::size_t>(tile_index)) >= 0;
}

void TileAtlas::place(int tile_index) {
  if (placed(tile_index)) return;
  if (count_ == capacity()) grow_to(std::max(1, 2 * rows_));
  const int place = count_++;
  place_of_[static_cast<std::size_t>(tile_index)] = place;
  const auto value = static_cast<float>(place + 1);
  table_.upload(tile_index % tiles_x_, tile_index / tiles_x_, 1, 1, 0, &value, 1);
}

void TileAtlas::reserve(int places) {
  places = std::min({places, tiles_x_ * tiles_y_, max_rows_ * columns_});
  if (places > capacity()) grow_to((places + columns_ - 1) / columns_);
}

void TileAtlas::grow_to(int rows_wanted) {
  if (rows_ >= max_rows_) {
    throw std::runtime_error("tile atlas: the GPU's largest texture holds " +
                             std::to_string(capacity()) + " tiles of this canvas's " +
                             std::to_string(tiles_x_ * tiles_y_));
  }
  const int rows = std::min(max_rows_, rows_wanted);
  Texture grown(columns_ * kTileSize, rows * kTileSize, layers_, TexelFormat::kRGBA32F);
  if (rows_ > 0) {
    // The places so far, copied on the GPU layer by layer through a read framebuffer.
    GLint read_framebuffer = 0;
    glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &read_framebuffer);
    GLuint framebuffer = 0;
    glGenFramebuffers(1, &framebuffer);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer);
    glReadBuffer(GL_COLOR_ATTACHMENT0);
    glBindTexture(GL_TEXTURE_2D_ARRAY, grown.id());
    for (int layer = 0; layer < layers_; ++layer) {
      glFramebufferTextureLayer(GL_READ_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, atlas_.id(), 0, layer);
      glCopyTexSubImage3D(GL_TEXTURE_2D_ARRAY, 0, 0, 0, layer, 0, 0, atlas_.width(),
                          atlas_.height());
    }
    glBindFramebuffer(GL_READ_FRAMEBUFFER, static_cast<GLuint>(read_framebuffer));
    glDeleteFramebuffers(1, &framebuffer);
    if (glGetError() != GL_NO_ERROR) {
      throw std::runtime_error("tile atlas: copying its places into a larger texture failed");
    }
  }
  atlas_ = std::move(grown);
  rows_ = rows;
}

void TileAtlas::upload(int tile_index, int w, int h, int layer, const float* texels,
                       int row_stride) {
  const int place = place_of_.at(static_cast<std::size_t>(tile_index));
  if (place < 0) {
    throw std::logic_error("tile atlas: tile " + std::to_string(tile_index) + " has no place");
  }
  if (w > kTileSize || h > kTileSize) throw std::out_of_range("tile atlas: upload beyond a tile");
  atlas_.upload((place % columns_) * kTileSize, (place / columns_) * kTileSize, w, h, layer, texels,
                row_stride);
}

void TileAtlas::bind(int atlas_unit, int table_unit) const {
  atlas_.bind(atlas_unit);
  table_.bind(table_unit);
}

std::size_t TileAtlas::bytes() const {
  const auto table = static_cast<std::size_t>(tiles_x_) * static_cast<std::size_t>(tiles_y_) * 4;
  const auto atlas = static_cast<std::size_t>(rows_) * static_cast<std::size_t>(columns_) *
                     static_cast<std::size_t>(layers_) * kTileCells * 16;
  return table + atlas;
}

}  // namespace impasto::render_gl
