// Fuzz target: any bytes as a painting file, as they are, with the header's size and the
// checksum made to match (so that mutations reach the fields), and with the bytes after the
// header compressed as version 8 stores its payload (painting_file_codec.hpp). Nothing may
// crash or allocate what a field declares. The bytes go to an in-memory file (memfd), read by
// its /proc name.
#include <sys/mman.h>
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "hasher.hpp"
#include "impasto/paintcore/painting.hpp"
#include "impasto/paintcore/painting_file_header.hpp"
#include "section_codec.hpp"

namespace paintcore = impasto::paintcore;

namespace {

void load(const std::vector<std::uint8_t>& bytes) {
  static const int fd = ::memfd_create("impasto_fuzz_painting", MFD_CLOEXEC);
  if (fd < 0) std::abort();
  if (::ftruncate(fd, 0) != 0 ||
      ::pwrite(fd, bytes.data(), bytes.size(), 0) != static_cast<ssize_t>(bytes.size()))
    std::abort();
  try {
    (void)paintcore::Painting::load("/proc/self/fd/" + std::to_string(fd), 1);
  } catch (const std::runtime_error&) {
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::vector<std::uint8_t> bytes(data, data + size);
  load(bytes);
  constexpr std::size_t kHeader = paintcore::kPaintingFileHeaderBytes;
  if (bytes.size() >= kHeader + 8) {
    const std::uint64_t payload = bytes.size() - kHeader - 8;
    std::memcpy(bytes.data() + 12, &payload, 8);
    paintcore::Hasher checksum;
    checksum.bytes(bytes.data() + kHeader, payload);
    const std::uint64_t digest = checksum.digest();
    std::memcpy(bytes.data() + bytes.size() - 8, &digest, 8);
    load(bytes);
    // The same payload compressed into a version-8 file.
    const std::span<const std::uint8_t> section(bytes.data() + kHeader, payload);
    const std::vector<unsigned char> stored = paintcore::file_io::compress_section(section);
    std::vector<std::uint8_t> file(bytes.begin(), bytes.begin() + 8);
    const auto append = [&file](const void* p, std::size_t n) {
      file.insert(file.end(), static_cast<const std::uint8_t*>(p),
                  static_cast<const std::uint8_t*>(p) + n);
    };
    const std::uint32_t version = 8;
    const std::uint64_t sizes[2] = {stored.size(), payload};
    append(&version, 4);
    append(sizes, sizeof sizes);
    append(stored.data(), stored.size());
    paintcore::StreamHasher stored_checksum;
    stored_checksum.bytes(stored.data(), stored.size());
    const std::uint64_t stored_digest = stored_checksum.digest();
    append(&stored_digest, 8);
    load(file);
  }
  return 0;
}
