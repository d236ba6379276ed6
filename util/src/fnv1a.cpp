#include "impasto/util/fnv1a.hpp"

namespace impasto::util {

std::uint64_t fnv1a(std::string_view text) {
  Fnv1a hash;
  hash.add(text.data(), text.size());
  return hash.value();
}

}  // namespace impasto::util
