#pragma once
// The impasto executable's whole main(). It lives in the command files, not in main.cpp, so
// that CLI11 (header-only and slow to compile) is compiled once with them.

namespace impasto::app {

// Parses argv and runs the chosen sub-command; returns the exit status.
int run_command_line(int argc, char** argv);

}  // namespace impasto::app
