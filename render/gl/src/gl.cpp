#include "impasto/render_gl/gl.hpp"

#include <cstdio>
#include <stdexcept>

#include "proc_loader.hpp"

namespace impasto::render_gl {

void load_gl(GLADloadfunc get_proc) {
  const int version = gladLoadGL(get_proc);
  if (version == 0) throw std::runtime_error("OpenGL: could not load the GL entry points");
  const int major = GLAD_VERSION_MAJOR(version);
  const int minor = GLAD_VERSION_MINOR(version);
  if (major * 10 + minor < 33) {
    throw std::runtime_error("OpenGL 3.3 or newer is required; the context offers " +
                             std::to_string(major) + "." + std::to_string(minor));
  }
}

void load_gl_entry_points(GlProcLoader loader) {
  load_gl(loader);
}

std::string gl_description() {
  auto text = [](GLenum name) {
    const auto* s = reinterpret_cast<const char*>(glGetString(name));
    return std::string(s ? s : "?");
  };
  return text(GL_VENDOR) + " / " + text(GL_RENDERER) + " / " + text(GL_VERSION);
}

void check_gl_error(const char* what) {
  const GLenum first = glGetError();
  if (first == GL_NO_ERROR) return;
  while (glGetError() != GL_NO_ERROR) {  // drain the queue so later checks start clean
  }
  char code[16];
  std::snprintf(code, sizeof code, "0x%04X", first);
  throw std::runtime_error(std::string("OpenGL error ") + code + " in " + what);
}

}  // namespace impasto::render_gl
