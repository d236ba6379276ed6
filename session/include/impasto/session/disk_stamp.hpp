#pragma once
// What a painting file on disk was when this session last read or wrote it, so that saving
// over it notices another window's or program's save in between instead of silently
// replacing that work (docs/guarantees.md, "Two windows, one file").
#include <cstdint>
#include <filesystem>
#include <optional>

namespace impasto::session {

struct DiskStamp {
  std::uintmax_t size = 0;
  std::filesystem::file_time_type modified{};
  std::uint64_t content_hash = 0;  // FNV-1a of the bytes
};

// The file's stamp now; nothing when it does not exist or cannot be read.
std::optional<DiskStamp> stamp_of(const std::filesystem::path& file);

// Whether the file differs from `known`: its size or time moved and its content with them (a
// file touched but not changed is the same file), or it appeared or vanished. A file this
// session never stamped (`known` empty) is changed when it exists.
bool changed_on_disk(const std::filesystem::path& file, const std::optional<DiskStamp>& known);

}  // namespace impasto::session
