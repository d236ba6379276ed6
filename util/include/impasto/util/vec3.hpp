#pragma once
// The one 3-vector: x, y, z and the few operations the shading and the ray tracing need,
// written so that each line maps to GLSL's vec3. T is double for the references (flakes,
// cracks), float where the shaders' own precision is mirrored.
#include <cmath>
#include <type_traits>

namespace impasto::util {

template <class T>
struct Vec3 {
  T x{}, y{}, z{};
};

template <class T>
constexpr Vec3<T> operator+(Vec3<T> a, Vec3<T> b) {
  return {a.x + b.x, a.y + b.y, a.z + b.z};
}
template <class T>
constexpr Vec3<T> operator-(Vec3<T> a, Vec3<T> b) {
  return {a.x - b.x, a.y - b.y, a.z - b.z};
}
template <class T>
constexpr Vec3<T> operator-(Vec3<T> a) {
  return {-a.x, -a.y, -a.z};
}
// The scale's type follows the vector's (so 2 * v and 0.5f * v both work).
template <class T>
constexpr Vec3<T> operator*(std::type_identity_t<T> s, Vec3<T> a) {
  return {s * a.x, s * a.y, s * a.z};
}
template <class T>
constexpr T dot(Vec3<T> a, Vec3<T> b) {
  return a.x * b.x + a.y * b.y + a.z * b.z;
}
template <class T>
constexpr Vec3<T> cross(Vec3<T> a, Vec3<T> b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
template <class T>
T length(Vec3<T> a) {
  return std::sqrt(dot(a, a));
}
// a over its length; a zero vector gives NaN, as GLSL's normalize may: callers guard it.
template <class T>
Vec3<T> normalized(Vec3<T> a) {
  return (T(1) / length(a)) * a;
}

}  // namespace impasto::util
