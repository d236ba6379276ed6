#include "impasto/session/disk_stamp.hpp"

#include <fstream>
#include <vector>

#include "impasto/util/fnv1a.hpp"

namespace impasto::session {
namespace {

std::optional<std::uint64_t> content_hash(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) return std::nullopt;
  util::Fnv1a hash;
  std::vector<char> buffer(1 << 16);
  while (in) {
    in.read(buffer.data(), static_cast<std::streamsize>(buffer.size()));
    hash.add(buffer.data(), static_cast<std::size_t>(in.gcount()));
  }
  if (in.bad()) return std::nullopt;
  return hash.value();
}

}  // namespace

std::optional<DiskStamp> stamp_of(const std::filesystem::path& file) {
  std::error_code error;
  if (!std::filesystem::is_regular_file(file, error)) return std::nullopt;
  DiskStamp stamp;
  stamp.size = std::filesystem::file_size(file, error);
  if (error) return std::nullopt;
  stamp.modified = std::filesystem::last_write_time(file, error);
  if (error) return std::nullopt;
  const std::optional<std::uint64_t> hash = content_hash(file);
  if (!hash) return std::nullopt;
  stamp.content_hash = *hash;
  return stamp;
}

bool changed_on_disk(const std::filesystem::path& file, const std::optional<DiskStamp>& known) {
  std::error_code error;
  const bool exists = std::filesystem::exists(file, error);
  if (!known) return exists;
  if (!exists) return true;
  const std::uintmax_t size = std::filesystem::file_size(file, error);
  if (error) return true;
  const auto modified = std::filesystem::last_write_time(file, error);
  if (error) return true;
  if (size == known->size && modified == known->modified) return false;
  if (size != known->size) return true;
  // Same size, another time: read it (a touch, or a copy of the same bytes, is no change).
  const std::optional<std::uint64_t> hash = content_hash(file);
  return !hash || *hash != known->content_hash;
}

}  // namespace impasto::session
