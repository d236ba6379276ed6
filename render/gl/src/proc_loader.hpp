#pragma once
// The GL entry-point loader type without glad's header, for files that must include a
// platform's own GL headers (OSMesa's osmesa.h pulls in GL/gl.h, which clashes with glad).

namespace impasto::render_gl {

using GlProc = void (*)();
using GlProcLoader = GlProc (*)(const char* name);

// Same as load_gl() in gl.hpp.
void load_gl_entry_points(GlProcLoader loader);

}  // namespace impasto::render_gl
