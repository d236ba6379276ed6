#include "impasto/render_gl/framebuffer.hpp"

#include <stdexcept>
#include <string>

namespace impasto::render_gl {

Framebuffer::Framebuffer(int width, int height, TexelFormat format)
    : color_(width, height, 0, format) {
  glGenFramebuffers(1, &id_);
  glBindFramebuffer(GL_FRAMEBUFFER, id_);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, color_.id(), 0);
  const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  if (status != GL_FRAMEBUFFER_COMPLETE) {
    glDeleteFramebuffers(1, &id_);
    throw std::runtime_error("framebuffer incomplete (status " + std::to_string(status) + ")");
  }
}

Framebuffer::~Framebuffer() {
  glDeleteFramebuffers(1, &id_);
}

void Framebuffer::bind() const {
  glBindFramebuffer(GL_FRAMEBUFFER, id_);
  glViewport(0, 0, width(), height());
}

std::vector<float> Framebuffer::read_rgba_float() const {
  std::vector<float> pixels(static_cast<size_t>(width()) * static_cast<size_t>(height()) * 4);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, id_);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, width(), height(), GL_RGBA, GL_FLOAT, pixels.data());
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  return pixels;
}

std::vector<std::uint8_t> Framebuffer::read_rgba8() const {
  std::vector<std::uint8_t> pixels(static_cast<size_t>(width()) * static_cast<size_t>(height()) *
                                   4);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, id_);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, width(), height(), GL_RGBA, GL_UNSIGNED_BYTE, pixels.data());
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  return pixels;
}

}  // namespace impasto::render_gl
