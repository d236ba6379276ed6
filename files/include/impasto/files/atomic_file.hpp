#pragma once
// Saving a file so that a crash, a full disk or a power cut leaves either the old file or the
// new one, never a mix (docs/guarantees.md):
//  - the bytes go to a temp file beside the target, named ".NAME.impasto-tmp-PID-RANDOM" and
//    created with O_EXCL | O_NOFOLLOW (a planted file or symlink is never written through);
//  - a symlink target is followed to the real file, which is the one replaced;
//  - the new file keeps the old one's mode and (where allowed) owner; a new file gets
//    0666 less the umask;
//  - the temp file is fsynced, renamed over the target, and the folder fsynced;
//  - on any error (or an exception while the bytes are produced) the temp file is removed and
//    the target is untouched; temp files of dead processes for the same target are removed
//    at the next save.
// A hard-linked target is replaced, not rewritten in place: its other names keep the old
// contents (rewriting in place could leave a torn file, which we never do).
#include <cstdint>
#include <filesystem>
#include <limits>
#include <string>
#include <string_view>
#include <vector>

namespace impasto::files {

struct AtomicFileOptions {
  // Fault injection for tests: writing past this many bytes fails as a full disk does
  // (ENOSPC), so the error path can be checked without filling a disk.
  std::uint64_t fail_after_bytes = std::numeric_limits<std::uint64_t>::max();
};

class AtomicFile {
 public:
  explicit AtomicFile(const std::filesystem::path& target, AtomicFileOptions options = {});
  ~AtomicFile();  // removes the temp file unless commit() succeeded
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  // Buffered; throws std::runtime_error naming the target on a write error.
  void write(const void* data, std::size_t size);
  void write(std::string_view bytes) { write(bytes.data(), bytes.size()); }
  std::uint64_t bytes_written() const { return written_ + buffer_.size(); }
  // Overwrites bytes already written (a size field whose value is known only at the end);
  // [offset, offset + size) must lie within bytes_written().
  void write_at(std::uint64_t offset, const void* data, std::size_t size);
  // Flushes, fsyncs, sets mode and owner, renames over the target, fsyncs the folder.
  void commit();

  // The file that is replaced: the target with symlinks followed.
  const std::filesystem::path& resolved_target() const { return target_; }
  const std::filesystem::path& temp_path() const { return temp_; }

 private:
  void flush();
  [[noreturn]] void fail(const std::string& what, int error);
  std::filesystem::path shown_;   // as the caller named it, for messages
  std::filesystem::path target_;  // symlinks followed
  std::filesystem::path temp_;
  AtomicFileOptions options_;
  int fd_ = -1;
  std::vector<char> buffer_;
  std::uint64_t written_ = 0;
  bool committed_ = false;
};

// The whole file at once: the usual way for small files (images, tables, text).
void write_file_atomically(const std::filesystem::path& target, std::string_view bytes,
                           AtomicFileOptions options = {});

// Follows symlinks in the last component (a chain, or one pointing at a file not yet made).
// Throws when the chain is longer than 40 links.
std::filesystem::path resolve_symlinks(const std::filesystem::path& path);

// Removes temp files of `target` left by processes that no longer run; returns how many.
int remove_stale_temp_files(const std::filesystem::path& target);

}  // namespace impasto::files
