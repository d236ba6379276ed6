#pragma once
// The painting file's reader and writer (painting_file.cpp), a friend of Painting: it builds
// a Painting from its state, as the synthetic painting of the benchmark does too.
#include <filesystem>
#include <map>
#include <memory>
#include <string>

#include "impasto/files/input_file.hpp"
#include "painting_impl.hpp"

namespace impasto::paintcore {

namespace file_io {
class Reader;
}

struct PaintingFile {
  using Records = std::map<std::string, std::string>;
  template <typename W>
  static void write_payload(const Painting::Impl& p, const Records& records, W& w);
  // The painting's records, and the record source's for slots that have none.
  static Records records_to_save(const Painting::Impl& p);
  static void save(const Painting::Impl& p, const std::filesystem::path& file);
  static std::unique_ptr<Painting::Impl> load(const std::filesystem::path& file, int threads,
                                              bool with_history);
  // After the header's magic and version: version 8's compressed sections, or the raw ones of
  // versions 1 to 7.
  static std::unique_ptr<Painting::Impl> load_compressed(files::InputFile& in,
                                                         file_io::Reader& header,
                                                         std::uint32_t version, int threads,
                                                         bool with_history);
  static std::unique_ptr<Painting::Impl> load_uncompressed(files::InputFile& in,
                                                           file_io::Reader& header,
                                                           std::uint32_t version, int threads,
                                                           bool with_history);
  // A history that failed to load is dropped, and the painting says so.
  static void drop_history_if(Painting::Impl& p, const std::string& problem,
                              const std::string& name);
  // The payload's fields, from the canvas spec to the last (the checksum is the caller's).
  static std::unique_ptr<Painting::Impl> read_payload(file_io::Reader& r, std::uint32_t version,
                                                      const std::string& name, int threads);
  // An empty painting's state, and a Painting around a state (the synthetic painting's).
  static std::unique_ptr<Painting::Impl> make_impl(const CanvasSpec& spec, int threads) {
    return std::make_unique<Painting::Impl>(spec, threads);
  }
  static Painting adopt(std::unique_ptr<Painting::Impl> impl) { return Painting(std::move(impl)); }
};

}  // namespace impasto::paintcore
