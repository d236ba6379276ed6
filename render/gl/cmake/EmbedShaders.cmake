# Turns each GLSL file in SOURCES into a string constant (name = file name without .glsl) in
# OUTPUT, so that shaders travel inside the library and need no files at run time.
set(body "// Generated from render/gl/shaders/*.glsl; do not edit.\n#include \"embedded_shaders.hpp\"\n\nnamespace impasto::render_gl::shaders {\n")
foreach(file IN LISTS SOURCES)
  get_filename_component(name ${file} NAME_WE)
  file(READ ${file} text)
  string(APPEND body "extern const char* const ${name};\nconst char* const ${name} = R\"glsl(${text})glsl\";\n")
endforeach()
string(APPEND body "}  // namespace impasto::render_gl::shaders\n")
file(WRITE ${OUTPUT}.tmp "${body}")
file(COPY_FILE ${OUTPUT}.tmp ${OUTPUT} ONLY_IF_DIFFERENT)
