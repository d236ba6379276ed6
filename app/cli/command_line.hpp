#pragma once
// The impasto executable's whole main(). It lives in the command files, not in main.cpp, so
// that CLI11 (header-only and slow to compile) is compiled once with them.
#include <stdexcept>
#include <string>

namespace impasto::app {

// Parses argv and runs the chosen sub-command; returns the exit status.
int run_command_line(int argc, char** argv);

// A command line the parser refused (an unknown option, a value out of range or of the wrong
// form): CLI11's ParseError, as a type its callers can catch without compiling CLI11.
struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Runs one command line (without the program's name, e.g. "render a.impasto -o a.png") in
// this process, through the registered sub-commands; a refused command line throws
// UsageError, a failing command its own exception. For tests: each test file that included
// CLI11 to do this cost ~20 s of compiling in the sanitizer build.
void run_command_in_process(const std::string& command_line);

}  // namespace impasto::app
