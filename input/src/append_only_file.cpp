#include <impasto/input/append_only_file.hpp>

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>

namespace impasto::input {

AppendOnlyFile::AppendOnlyFile(const std::filesystem::path& path, unsigned mode) : path_(path) {
  fd_ = ::open(path.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC,
               static_cast<mode_t>(mode));
  if (fd_ < 0) {
    const int error_number = errno;
    std::string why = std::strerror(error_number);
    if (error_number == EEXIST) why = "it already exists (a recording is never overwritten)";
    throw std::runtime_error(path.string() + ": cannot create the file: " + why);
  }
  // The new name itself must survive a power cut, or a synced recording could be lost with it.
  const std::filesystem::path dir = path.has_parent_path() ? path.parent_path() : ".";
  if (const int dir_fd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC); dir_fd >= 0) {
    ::fsync(dir_fd);
    ::close(dir_fd);
  }
}

AppendOnlyFile::~AppendOnlyFile() {
  if (fd_ >= 0) ::close(fd_);
}

void AppendOnlyFile::fail(const std::string& what, int error_number) {
  error_ = path_.string() + ": " + what + ": " + std::strerror(error_number);
}

bool AppendOnlyFile::append_line(std::string_view line) {
  if (failed()) return false;
  std::string text(line);
  text += '\n';
  std::size_t written = 0;
  while (written < text.size()) {
    const ssize_t n = ::write(fd_, text.data() + written, text.size() - written);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      const int error_number = n < 0 ? errno : ENOSPC;
      // Cut the part of this line that did get written, so the file ends on a whole line.
      if (written > 0 && ::ftruncate(fd_, static_cast<off_t>(size_)) != 0) {
        fail("write failed, and the part written could not be cut off", error_number);
        return false;
      }
      fail("write failed", error_number);
      return false;
    }
    written += static_cast<std::size_t>(n);
  }
  size_ += text.size();
  dirty_ = true;
  return true;
}

bool AppendOnlyFile::sync() {
  if (failed()) return false;
  if (!dirty_) return true;
  if (::fdatasync(fd_) != 0) {
    fail("sync failed", errno);
    return false;
  }
  dirty_ = false;
  return true;
}

}  // namespace impasto::input
