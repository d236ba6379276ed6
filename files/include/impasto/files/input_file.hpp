#pragma once
// Opening a file to read, checked before anything is allocated: a folder, a device, a FIFO or
// a socket is refused by name ("is a folder, not a file"), and so is a file larger than the
// reader's limit. Reading then goes through a small buffer, never the whole file at once.
#include <cstdint>
#include <filesystem>
#include <istream>
#include <memory>
#include <streambuf>
#include <string>
#include <vector>

namespace impasto::files {

// Limits by kind of file: far above any real one, far below what would exhaust memory.
inline constexpr std::uint64_t kMaxTextFileBytes = 64ull << 20;  // tables, CSVs, heads
inline constexpr std::uint64_t kMaxRecordingBytes = 1ull << 30;  // stroke and HID text
inline constexpr std::uint64_t kMaxPaintingBytes = 64ull << 30;  // .impasto
inline constexpr std::uint64_t kMaxImageFileBytes = 1ull << 30;  // PNG crack maps, images

class InputFile {
 public:
  // `what` names the kind of file in messages ("painting", "stroke file").
  InputFile(const std::filesystem::path& path, const std::string& what, std::uint64_t max_bytes);
  ~InputFile();
  InputFile(const InputFile&) = delete;
  InputFile& operator=(const InputFile&) = delete;

  std::uint64_t size() const { return size_; }
  const std::filesystem::path& path() const { return path_; }
  // A stream over the file (64 KiB buffered); it ends at the size seen when it was opened.
  std::istream& stream() { return stream_; }
  // Reads exactly `size` bytes or throws naming the file.
  void read_exact(void* out, std::size_t size);
  // Back to the start (for a second pass).
  void rewind();

 private:
  class Buffer : public std::streambuf {
   public:
    Buffer(int fd, std::uint64_t limit) : fd_(fd), limit_(limit), data_(64 << 10) {}
    void rewind();
    bool failed() const { return failed_; }

   protected:
    int_type underflow() override;

   private:
    int fd_;
    std::uint64_t limit_;
    std::uint64_t consumed_ = 0;
    bool failed_ = false;
    std::vector<char> data_;
  };
  std::filesystem::path path_;
  std::string what_;
  int fd_ = -1;
  std::uint64_t size_ = 0;
  std::unique_ptr<Buffer> buffer_;
  std::istream stream_{nullptr};
};

// The whole of a small file (text, or a compressed image to decode), at most max_bytes,
// checked as above.
std::string read_whole_file(const std::filesystem::path& path, const std::string& what,
                            std::uint64_t max_bytes = kMaxTextFileBytes);

}  // namespace impasto::files
