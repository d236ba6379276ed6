#include "impasto/render/shading_key.hpp"

#include <type_traits>

namespace impasto::render {
namespace {

// A setting as the numbers of a key: a material is its specular share and shininess.
template <class Value>
void append(std::vector<double>& key, const Value& value) {
  if constexpr (std::is_same_v<Value, shade::Material>) {
    key.push_back(value.specular);
    key.push_back(value.shininess);
  } else {
    key.push_back(static_cast<double>(value));
  }
}

}  // namespace

std::vector<double> shading_settings_key(const RenderSettings& s) {
  std::vector<double> key;
  for_each_shading_setting([&](auto member) { append(key, s.*member); });
  return key;
}

std::vector<double> shader_colour_settings_key(const RenderSettings& s) {
  std::vector<double> key;
  for_each_shader_colour_setting([&](auto member) { append(key, s.*member); });
  return key;
}

void copy_shading_settings(const RenderSettings& from, RenderSettings& to) {
  const auto copy = [&](auto member) { to.*member = from.*member; };
  for_each_shading_setting(copy);
  for_each_shader_colour_setting(copy);
}

}  // namespace impasto::render
