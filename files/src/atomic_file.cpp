#include "impasto/files/atomic_file.hpp"

#include <dirent.h>
#include <fcntl.h>
#include <signal.h>
#include <sys/random.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <string>

#include "impasto/util/fnv1a.hpp"

namespace impasto::files {
namespace {

constexpr std::size_t kBufferBytes = 1 << 20;
constexpr const char* kTempTag = ".impasto-tmp-";

// A name may use the file system's 255 bytes; the temp name adds up to 41 ("." and
// ".impasto-tmp-PID-RANDOM"), so a long name is cut to its first bytes (at a UTF-8
// character's start) and its hash, which keeps one target's temps apart from another's.
constexpr std::size_t kLongNameBytes = 200;
constexpr std::size_t kKeptNameBytes = 160;

std::string temp_prefix(const std::filesystem::path& target) {
  std::string name = target.filename().string();
  if (name.size() > kLongNameBytes) {
    std::size_t cut = kKeptNameBytes;
    while (cut > 0 && (static_cast<unsigned char>(name[cut]) & 0xC0) == 0x80) --cut;
    char hash[20];
    std::snprintf(hash, sizeof hash, "~%016llx",
                  static_cast<unsigned long long>(util::fnv1a(name)));
    name = name.substr(0, cut) + hash;
  }
  return "." + name + kTempTag;
}

std::uint64_t random_word() {
  std::uint64_t word = 0;
  if (::getrandom(&word, sizeof word, 0) != static_cast<ssize_t>(sizeof word)) {
    // getrandom cannot fail for 8 bytes once the pool is ready; fall back to time and address.
    word = static_cast<std::uint64_t>(::time(nullptr)) ^ reinterpret_cast<std::uintptr_t>(&word);
  }
  return word;
}

std::filesystem::path folder_of(const std::filesystem::path& path) {
  return path.has_parent_path() ? path.parent_path() : std::filesystem::path(".");
}

void fsync_folder(const std::filesystem::path& folder) {
  if (const int fd = ::open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC); fd >= 0) {
    ::fsync(fd);
    ::close(fd);
  }
}

}  // namespace

std::filesystem::path resolve_symlinks(const std::filesystem::path& path) {
  std::filesystem::path current = path;
  for (int hop = 0; hop < 40; ++hop) {
    struct stat st {};
    if (::lstat(current.c_str(), &st) != 0 || !S_ISLNK(st.st_mode)) return current;
    std::error_code error;
    const std::filesystem::path link = std::filesystem::read_symlink(current, error);
    if (error) return current;
    current = link.is_absolute() ? link : folder_of(current) / link;
  }
  throw std::runtime_error(path.string() + ": too many levels of symbolic links");
}

int remove_stale_temp_files(const std::filesystem::path& target) {
  const std::filesystem::path folder = folder_of(target);
  const std::string prefix = temp_prefix(target);
  DIR* dir = ::opendir(folder.c_str());
  if (dir == nullptr) return 0;
  int removed = 0;
  while (const dirent* entry = ::readdir(dir)) {
    const std::string name = entry->d_name;
    if (name.rfind(prefix, 0) != 0) continue;
    // ".NAME.impasto-tmp-PID-RANDOM": only a dead process's file is stale.
    const long pid = std::strtol(name.c_str() + prefix.size(), nullptr, 10);
    if (pid <= 0) continue;
    if (::kill(static_cast<pid_t>(pid), 0) == 0 || errno != ESRCH) continue;  // alive
    if (::unlinkat(::dirfd(dir), entry->d_name, 0) == 0) ++removed;
  }
  ::closedir(dir);
  return removed;
}

AtomicFile::AtomicFile(const std::filesystem::path& target, AtomicFileOptions options)
    : shown_(target), target_(resolve_symlinks(target)), options_(options) {
  struct stat st {};
  if (::stat(target_.c_str(), &st) == 0 && !S_ISREG(st.st_mode)) {
    throw std::runtime_error(shown_.string() + ": cannot save: " +
                             (S_ISDIR(st.st_mode) ? "it is a folder" : "it is not a regular file"));
  }
  // A read-only file is protected on purpose: replacing it would bypass that (root included).
  if (::stat(target_.c_str(), &st) == 0 &&
      ((st.st_mode & 0222) == 0 || ::access(target_.c_str(), W_OK) != 0)) {
    char mode[8];
    std::snprintf(mode, sizeof mode, "%04o", static_cast<unsigned>(st.st_mode & 07777));
    throw std::runtime_error(shown_.string() + ": cannot save: the file is read-only (mode " +
                             mode + "); make it writable or save under another name");
  }
  remove_stale_temp_files(target_);
  const std::string prefix = (folder_of(target_) / temp_prefix(target_)).string();
  for (int attempt = 0; fd_ < 0; ++attempt) {
    char suffix[48];
    std::snprintf(suffix, sizeof suffix, "%ld-%016llx", static_cast<long>(::getpid()),
                  static_cast<unsigned long long>(random_word()));
    temp_ = prefix + suffix;
    fd_ = ::open(temp_.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0666);
    if (fd_ < 0 && (errno != EEXIST || attempt >= 16)) {
      const int error = errno;
      temp_.clear();  // nothing of ours to remove
      fail("cannot create a temp file in " + folder_of(target_).string(), error);
    }
  }
  buffer_.reserve(kBufferBytes);
}

AtomicFile::~AtomicFile() {
  if (fd_ >= 0) ::close(fd_);
  if (!committed_ && !temp_.empty()) ::unlink(temp_.c_str());
}

void AtomicFile::fail(const std::string& what, int error) {
  if (fd_ >= 0) ::close(fd_);
  fd_ = -1;
  if (!temp_.empty()) ::unlink(temp_.c_str());
  temp_.clear();
  std::string message = shown_.string() + ": cannot save (" + what + ": " + std::strerror(error);
  if (target_ != shown_) message += "; the link's target is " + target_.string();
  throw std::runtime_error(message + "); the old file is untouched");
}

void AtomicFile::write(const void* data, std::size_t size) {
  if (fd_ < 0) throw std::logic_error("AtomicFile::write after commit or failure");
  const char* p = static_cast<const char*>(data);
  while (size > 0) {
    const std::size_t take = std::min(size, kBufferBytes - buffer_.size());
    buffer_.insert(buffer_.end(), p, p + take);
    p += take;
    size -= take;
    if (buffer_.size() == kBufferBytes) flush();
  }
}

void AtomicFile::flush() {
  std::size_t done = 0;
  while (done < buffer_.size()) {
    std::size_t chunk = buffer_.size() - done;
    if (written_ + chunk > options_.fail_after_bytes) {
      chunk = static_cast<std::size_t>(options_.fail_after_bytes - written_);
      if (chunk == 0) fail("write " + temp_.string(), ENOSPC);
    }
    const ssize_t n = ::write(fd_, buffer_.data() + done, chunk);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) fail("write " + temp_.string(), n < 0 ? errno : ENOSPC);
    done += static_cast<std::size_t>(n);
    written_ += static_cast<std::uint64_t>(n);
  }
  buffer_.clear();
}

void AtomicFile::write_at(std::uint64_t offset, const void* data, std::size_t size) {
  if (fd_ < 0) throw std::logic_error("AtomicFile::write_at after commit or failure");
  if (offset > bytes_written() || size > bytes_written() - offset)
    throw std::logic_error("AtomicFile::write_at past the bytes written");
  flush();
  const char* p = static_cast<const char*>(data);
  while (size > 0) {
    const ssize_t n = ::pwrite(fd_, p, size, static_cast<off_t>(offset));
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) fail("write " + temp_.string(), n < 0 ? errno : ENOSPC);
    p += n;
    offset += static_cast<std::uint64_t>(n);
    size -= static_cast<std::size_t>(n);
  }
}

void AtomicFile::commit() {
  if (fd_ < 0) throw std::logic_error("AtomicFile::commit twice or after a failure");
  flush();
  struct stat old {};
  if (::stat(target_.c_str(), &old) == 0) {
    // The owner first: changing it clears set-user-ID bits, which the mode then restores.
    // Only root may give a file away; others keep the file as theirs.
    if ((old.st_uid != ::geteuid() || old.st_gid != ::getegid()) &&
        ::fchown(fd_, old.st_uid, old.st_gid) != 0 && errno != EPERM)
      fail("chown " + temp_.string(), errno);
    if (::fchmod(fd_, old.st_mode & 07777) != 0) fail("chmod " + temp_.string(), errno);
  }
  if (::fsync(fd_) != 0) fail("fsync " + temp_.string(), errno);
  const int fd = fd_;
  fd_ = -1;
  if (::close(fd) != 0) fail("close " + temp_.string(), errno);
  if (::rename(temp_.c_str(), target_.c_str()) != 0) fail("rename over the target", errno);
  committed_ = true;
  fsync_folder(folder_of(target_));
}

void write_file_atomically(const std::filesystem::path& target, std::string_view bytes,
                           AtomicFileOptions options) {
  AtomicFile file(target, options);
  file.write(bytes);
  file.commit();
}

}  // namespace impasto::files
