#pragma once
// --pigments DIR on the top level and on every sub-command: a pigment folder layered over the
// bundled and user pigments (impasto/data/pigment_library.hpp). Repeatable; later folders win.
#include <CLI/CLI.hpp>

namespace impasto::app {

// Adds the option to root and to every sub-command below it that has none of its own.
void add_pigment_folder_options(CLI::App& root);

}  // namespace impasto::app
