#include "impasto/files/input_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>

#include "impasto/files/memory_budget.hpp"

namespace impasto::files {
namespace {

std::string kind_of(mode_t mode) {
  if (S_ISDIR(mode)) return "a folder";
  if (S_ISCHR(mode) || S_ISBLK(mode)) return "a device";
  if (S_ISFIFO(mode)) return "a pipe";
  if (S_ISSOCK(mode)) return "a socket";
  return "not a regular file";
}

}  // namespace

InputFile::InputFile(const std::filesystem::path& path, const std::string& what,
                     std::uint64_t max_bytes)
    : path_(path), what_(what) {
  const std::string name = path.string();
  // O_NONBLOCK: opening a FIFO must not wait for a writer before we can refuse it.
  fd_ = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NOCTTY | O_NONBLOCK);
  if (fd_ < 0)
    throw std::runtime_error(name + ": cannot open the " + what + " (" + std::strerror(errno) +
                             ")");
  struct stat st {};
  if (::fstat(fd_, &st) != 0 || !S_ISREG(st.st_mode)) {
    const std::string kind = kind_of(st.st_mode);
    ::close(fd_);
    fd_ = -1;
    throw std::runtime_error(name + ": cannot read the " + what + ": it is " + kind +
                             ", not a file");
  }
  ::fcntl(fd_, F_SETFL, ::fcntl(fd_, F_GETFL) & ~O_NONBLOCK);
  size_ = static_cast<std::uint64_t>(st.st_size);
  if (size_ > max_bytes) {
    ::close(fd_);
    fd_ = -1;
    throw std::runtime_error(name + ": the " + what + " is " + describe_bytes(size_) +
                             ", more than the " + describe_bytes(max_bytes) +
                             " this reader accepts");
  }
  buffer_ = std::make_unique<Buffer>(fd_, size_);
  stream_.rdbuf(buffer_.get());
}

InputFile::~InputFile() {
  if (fd_ >= 0) ::close(fd_);
}

void InputFile::Buffer::rewind() {
  ::lseek(fd_, 0, SEEK_SET);
  consumed_ = 0;
  failed_ = false;
  setg(nullptr, nullptr, nullptr);
}

InputFile::Buffer::int_type InputFile::Buffer::underflow() {
  if (gptr() < egptr()) return traits_type::to_int_type(*gptr());
  if (consumed_ >= limit_) return traits_type::eof();
  const std::size_t want =
      static_cast<std::size_t>(std::min<std::uint64_t>(data_.size(), limit_ - consumed_));
  ssize_t n;
  do n = ::read(fd_, data_.data(), want);
  while (n < 0 && errno == EINTR);
  if (n <= 0) {
    failed_ = n < 0;
    return traits_type::eof();
  }
  consumed_ += static_cast<std::uint64_t>(n);
  setg(data_.data(), data_.data(), data_.data() + n);
  return traits_type::to_int_type(*gptr());
}

void InputFile::read_exact(void* out, std::size_t size) {
  stream_.read(static_cast<char*>(out), static_cast<std::streamsize>(size));
  if (static_cast<std::size_t>(stream_.gcount()) != size)
    throw std::runtime_error(path_.string() + ": the " + what_ + " ended early" +
                             (buffer_->failed() ? std::string(" (read error)") : ""));
}

void InputFile::rewind() {
  buffer_->rewind();
  stream_.clear();
}

std::string read_whole_file(const std::filesystem::path& path, const std::string& what,
                            std::uint64_t max_bytes) {
  InputFile file(path, what, max_bytes);
  std::string text(static_cast<std::size_t>(file.size()), '\0');
  file.read_exact(text.data(), text.size());
  return text;
}

}  // namespace impasto::files
