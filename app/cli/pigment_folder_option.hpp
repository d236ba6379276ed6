#pragma once
// The pigment library of a command line: --pigments DIR on the top level and on every
// sub-command, a folder layered over the bundled and user pigments
// (impasto/data/pigment_library.hpp; repeatable, later folders win), and paintings that carry
// the library's version of each pigment they take up (render/pigment_records.hpp).
#include <CLI/CLI.hpp>

namespace impasto::app {

// Adds the option to root and to every sub-command below it that has none of its own, and
// installs the pigment record source.
void setup_pigment_library(CLI::App& root);

}  // namespace impasto::app
