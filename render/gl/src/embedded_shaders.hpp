#pragma once
// GLSL sources from render/gl/shaders/, compiled into the library (see EmbedShaders.cmake).

namespace impasto::render_gl::shaders {

extern const char* const fullscreen_vert;            // full-viewport triangle, uv 0..1
extern const char* const optics_lib;                 // fresnel_dielectric (no #version)
extern const char* const km_lib;                     // K-M layer and compositing (no #version)
extern const char* const shading_lib;                // normals and Blinn-Phong (no #version)
extern const char* const surface_ghs_lib;            // the ghs surface model (no #version)
extern const char* const relief_lib;                 // relief shadows and occlusion (no #version)
extern const char* const flakes_lib;                 // flake sparkles (no #version)
extern const char* const cracks_lib;                 // crack far-view blend (no #version)
extern const char* const crack_close_up_lib;         // a cavity shaded point by point
extern const char* const crack_close_up_canvas_lib;  // the close-up in the canvas pass
extern const char* const tile_atlas_lib;             // a cell's texel in a TileAtlas
extern const char* const subsurface_canvas_lib;      // the spread in the canvas pass
extern const char* const subsurface_spread_frag;     // the spread's gather pass
extern const char* const canvas_km_frag;             // the canvas pass (after the libraries)

}  // namespace impasto::render_gl::shaders
