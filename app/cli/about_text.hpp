#pragma once
// What the program says of its terms wherever it introduces itself (`--version`, the About
// box): one text, so the two cannot disagree.

namespace impasto::app {

inline constexpr const char* kLicenceText =
    "Licensed under the Apache License 2.0. It ships data others made, each under its own\n"
    "licence and credited in NOTICE (/usr/share/doc/impasto/copyright in the package).";

}  // namespace impasto::app
