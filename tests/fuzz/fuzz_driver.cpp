// Runs a fuzz target without libFuzzer (for GCC builds and CTest): every seed file as it is,
// then a fixed number of deterministic mutations of the seeds. Any crash, sanitizer report
// or uncaught exception fails the test.
//
// usage: fuzz_driver [--mutations N] [--max-seed-bytes N] SEED_FILE_OR_DIR...
#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>
#include <string>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);

namespace {

using Bytes = std::vector<std::uint8_t>;

Bytes read_file(const std::filesystem::path& path, std::size_t max_bytes) {
  std::ifstream in(path, std::ios::binary);
  Bytes bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (bytes.size() > max_bytes) bytes.resize(max_bytes);
  return bytes;
}

void run(const Bytes& input) {
  LLVMFuzzerTestOneInput(input.data(), input.size());
}

// One random edit of the kinds libFuzzer makes: flip a bit, set a byte to an edge value,
// insert or erase bytes, copy a chunk, truncate, or splice in part of another seed.
Bytes mutate(Bytes input, const std::vector<Bytes>& seeds, std::mt19937_64& rng) {
  static const std::uint8_t kEdges[] = {0x00, 0x01, 0x7F, 0x80, 0xFF, 0xFE, ' ', '\n', '#',
                                        '"',  '-',  '.',  'e',  'n',  '9',  '0', 0x0A, 0xC0};
  const auto pick = [&](std::size_t n) { return n == 0 ? 0 : static_cast<std::size_t>(rng() % n); };
  const int edits = 1 + static_cast<int>(rng() % 4);
  for (int e = 0; e < edits; ++e) {
    switch (rng() % 7) {
      case 0:
        if (!input.empty())
          input[pick(input.size())] ^= static_cast<std::uint8_t>(1u << (rng() % 8));
        break;
      case 1:
        if (!input.empty()) input[pick(input.size())] = kEdges[pick(std::size(kEdges))];
        break;
      case 2:
        input.insert(input.begin() + static_cast<std::ptrdiff_t>(pick(input.size() + 1)),
                     static_cast<std::uint8_t>(rng()));
        break;
      case 3:
        if (!input.empty()) {
          const std::size_t at = pick(input.size());
          const std::size_t n = std::min<std::size_t>(1 + pick(16), input.size() - at);
          input.erase(input.begin() + static_cast<std::ptrdiff_t>(at),
                      input.begin() + static_cast<std::ptrdiff_t>(at + n));
        }
        break;
      case 4:
        if (!input.empty()) {
          const std::size_t from = pick(input.size());
          const std::size_t n = std::min<std::size_t>(1 + pick(32), input.size() - from);
          const Bytes chunk(input.begin() + static_cast<std::ptrdiff_t>(from),
                            input.begin() + static_cast<std::ptrdiff_t>(from + n));
          input.insert(input.begin() + static_cast<std::ptrdiff_t>(pick(input.size() + 1)),
                       chunk.begin(), chunk.end());
        }
        break;
      case 5:
        input.resize(pick(input.size() + 1));
        break;
      default: {
        const Bytes& other = seeds[pick(seeds.size())];
        if (other.empty()) break;
        const std::size_t from = pick(other.size());
        const std::size_t n = std::min<std::size_t>(1 + pick(64), other.size() - from);
        input.insert(input.begin() + static_cast<std::ptrdiff_t>(pick(input.size() + 1)),
                     other.begin() + static_cast<std::ptrdiff_t>(from),
                     other.begin() + static_cast<std::ptrdiff_t>(from + n));
      }
    }
  }
  return input;
}

}  // namespace

int main(int argc, char** argv) {
  long mutations = 3000;
  std::size_t max_seed_bytes = 1 << 16;
  std::vector<std::filesystem::path> paths;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--mutations" && i + 1 < argc) {
      mutations = std::strtol(argv[++i], nullptr, 10);
    } else if (arg == "--max-seed-bytes" && i + 1 < argc) {
      max_seed_bytes = static_cast<std::size_t>(std::strtoul(argv[++i], nullptr, 10));
    } else {
      paths.emplace_back(arg);
    }
  }
  std::vector<std::filesystem::path> files;
  for (const auto& path : paths) {
    if (std::filesystem::is_directory(path)) {
      for (const auto& entry : std::filesystem::directory_iterator(path)) {
        if (entry.is_regular_file()) files.push_back(entry.path());
      }
    } else if (std::filesystem::is_regular_file(path)) {
      files.push_back(path);
    } else {
      std::fprintf(stderr, "fuzz driver: no seed file or folder %s\n", path.string().c_str());
      return 2;
    }
  }
  std::sort(files.begin(), files.end());  // directory order is not deterministic
  std::vector<Bytes> seeds;
  for (const auto& file : files) seeds.push_back(read_file(file, max_seed_bytes));
  seeds.push_back({});
  for (const Bytes& seed : seeds) run(seed);
  std::mt19937_64 rng(20240611);
  for (long i = 0; i < mutations; ++i) {
    run(mutate(seeds[static_cast<std::size_t>(rng() % seeds.size())], seeds, rng));
  }
  std::printf("fuzz driver: %zu seeds, %ld mutations, no failure\n", seeds.size(), mutations);
  return 0;
}
