// Test helper for tests/second_signal_test.sh: starts writing argv[1] through
// a temporary file and, in the middle of the write, receives SIGINT twice, as
// a user pressing Ctrl-C twice would. The second signal must end the process
// and leave no temporary file behind.
#include <csignal>
#include <iostream>

#include "framework/process/interrupt.h"
#include "framework/process/output_file.h"

int main(int argc, char** argv) {
  if (argc != 2) {
    std::cerr << "usage: second_signal_writer OUTPUT\n";
    return 2;
  }
  akvf::install_interrupt_handler();
  akvf::write_file_atomically(argv[1], [](std::ostream& out) {
    out << "partial content" << std::flush;
    std::raise(SIGINT);  // the first only sets the flag
    std::raise(SIGINT);  // the second ends the process
  });
  std::cerr << "second_signal_writer: still alive after two signals\n";
  return 1;
}
