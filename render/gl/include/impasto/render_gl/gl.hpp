#pragma once
// The one way Impasto includes OpenGL: glad's GL 4.5 core loader. Never include GL/gl.h
// beside it (glad defines the same names).
#include <glad/gl.h>

#include <string>

namespace impasto::render_gl {

// Loads the GL entry points through get_proc (eglGetProcAddress, glfwGetProcAddress, ...)
// for the context current on this thread; throws std::runtime_error when GL 3.3 or more
// is not available. The pointers are process-wide: call it again after switching to a
// context made by a different library.
void load_gl(GLADloadfunc get_proc);

// "vendor / renderer / version" of the current context, for logs and reports.
std::string gl_description();

// Throws std::runtime_error naming `what` when glGetError reports an error.
void check_gl_error(const char* what);

}  // namespace impasto::render_gl
