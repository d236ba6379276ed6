// impasto thumbnail: a small PNG of a painting, for file managers (packaging/impasto.thumbnailer).
#include <memory>
#include <string>

#include "command.hpp"
#include "thumbnail.hpp"
#include "vocabulary.hpp"

// A namespace of its own: the command files are compiled together (unity build).
namespace impasto::app::thumbnail_cmd {
namespace {

struct ThumbnailArgs {
  std::string painting;
  std::string out;
  int size = 256;
};

const CommandRegistrar registrar("thumbnail", [](CLI::App& root) {
  CLI::App* cmd = root.add_subcommand(
      "thumbnail", "Write a small PNG of a painting (the file managers' thumbnailer)");
  auto args = std::make_shared<ThumbnailArgs>();
  cmd->add_option("painting", args->painting, "The .impasto painting file")->required();
  cmd->add_option("out", args->out, "The PNG to write")->required();
  cmd->add_option("size", args->size, "Longest side in pixels (never enlarged)")
      ->check(finite_range(1, 4096))
      ->capture_default_str();
  cmd->callback([args] { write_thumbnail(args->painting, args->out, args->size); });
});

}  // namespace
}  // namespace impasto::app::thumbnail_cmd
