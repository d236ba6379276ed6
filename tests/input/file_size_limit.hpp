#pragma once
// Fault injection for writers: a full disk, as the kernel gives it. While a FileSizeLimit is
// alive, every write of this process past `bytes` into any file fails (EFBIG; a write that
// crosses the limit is cut short first, as on a disk that fills mid-write). SIGXFSZ is
// ignored meanwhile so the failure comes back as an error instead of killing the process.
#include <signal.h>
#include <sys/resource.h>

#include <cstdint>

namespace impasto::testing_support {

class FileSizeLimit {
 public:
  explicit FileSizeLimit(std::uint64_t bytes) {
    ::getrlimit(RLIMIT_FSIZE, &old_limit_);
    old_handler_ = ::signal(SIGXFSZ, SIG_IGN);
    rlimit limit = old_limit_;
    limit.rlim_cur = static_cast<rlim_t>(bytes);
    ::setrlimit(RLIMIT_FSIZE, &limit);
  }
  ~FileSizeLimit() {
    ::setrlimit(RLIMIT_FSIZE, &old_limit_);
    ::signal(SIGXFSZ, old_handler_);
  }
  FileSizeLimit(const FileSizeLimit&) = delete;
  FileSizeLimit& operator=(const FileSizeLimit&) = delete;

 private:
  rlimit old_limit_{};
  sighandler_t old_handler_ = SIG_DFL;
};

}  // namespace impasto::testing_support
