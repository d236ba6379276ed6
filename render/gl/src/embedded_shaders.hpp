#pragma once
// GLSL sources from render/gl/shaders/, compiled into the library (see EmbedShaders.cmake).

namespace impasto::render_gl::shaders {

extern const char* const fullscreen_vert;  // full-viewport triangle, uv 0..1

}  // namespace impasto::render_gl::shaders
