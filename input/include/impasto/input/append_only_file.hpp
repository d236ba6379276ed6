#pragma once
// A text file that only grows, by whole lines, and is made durable on request: the storage
// of a session recording. A line is written whole or not at all: a short write (a full disk,
// a file size limit) is cut back to the end of the last whole line, so the file never ends in
// a line written only in part. After the first failure nothing more is written, so the file
// stays a clean prefix of what was sent to it.
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

namespace impasto::input {

class AppendOnlyFile {
 public:
  // Creates `path`, which must not exist yet (O_EXCL); a symlink planted there is not
  // followed but refused. `mode` is filtered by the umask. Throws std::runtime_error naming
  // the path and the reason.
  explicit AppendOnlyFile(const std::filesystem::path& path, unsigned mode = 0666);
  ~AppendOnlyFile();
  AppendOnlyFile(const AppendOnlyFile&) = delete;
  AppendOnlyFile& operator=(const AppendOnlyFile&) = delete;

  // Appends `line` and a newline. False when it could not (error() says why).
  bool append_line(std::string_view line);
  // Makes every line appended so far durable (fdatasync). False when it could not.
  bool sync();

  bool failed() const { return !error_.empty(); }
  const std::string& error() const { return error_; }
  bool dirty() const { return dirty_; }         // appended since the last sync
  std::uint64_t size() const { return size_; }  // bytes of whole lines in the file
  const std::filesystem::path& path() const { return path_; }

 private:
  void fail(const std::string& what, int error_number);

  std::filesystem::path path_;
  int fd_ = -1;
  std::uint64_t size_ = 0;
  bool dirty_ = false;
  std::string error_;
};

}  // namespace impasto::input
