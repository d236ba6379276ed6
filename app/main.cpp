// impasto: paint with thick, spectrally rendered paint.
#include "command_line.hpp"

int main(int argc, char** argv) {
  return impasto::app::run_command_line(argc, argv);
}
