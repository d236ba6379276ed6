// Optics shared by the surface models and the flakes: one GLSL home, the twin of
// optics/flakes/include/impasto/flakes/fresnel.hpp (tests/gl/optics_glsl_test.cpp compares
// them). Guarded: the libraries that need it each bring it, and a shader holds it once.
#ifndef OPTICS_LIB
#define OPTICS_LIB

// flakes::fresnel_dielectric: the unpolarised reflectance of light meeting a dielectric of
// relative index eta at incidence cosine cos_i (clamped to [0, 1]); 1 under total internal
// reflection.
float fresnel_dielectric(float cos_i, float eta) {
  float c = clamp(cos_i, 0.0, 1.0);
  float sin2_t = (1.0 - c * c) / (eta * eta);
  if (sin2_t >= 1.0) return 1.0;
  float cos_t = sqrt(1.0 - sin2_t);
  float rs = (c - eta * cos_t) / (c + eta * cos_t);
  float rp = (eta * c - cos_t) / (eta * c + cos_t);
  return 0.5 * (rs * rs + rp * rp);
}

#endif
