// Test helper for tests/second_signal_test.sh: starts writing argv[1] through
// a temporary file and, in the middle of the write, receives SIGINT as a user
// pressing Ctrl-C would. With argv[2] = "loop" the write happens inside an
// interruptible loop: the first signal only sets the flag, the second ends
// the process. With "outside" the first signal ends it. Either way no
// temporary file may be left behind.
#include <csignal>
#include <iostream>
#include <optional>
#include <string>

#include "framework/process/interrupt.h"
#include "framework/process/output_file.h"

int main(int argc, char** argv) {
  if (argc != 3 || (std::string(argv[2]) != "loop" && std::string(argv[2]) != "outside")) {
    std::cerr << "usage: second_signal_writer OUTPUT loop|outside\n";
    return 2;
  }
  akvf::install_interrupt_handler();
  std::optional<akvf::InterruptibleLoop> loop;
  if (std::string(argv[2]) == "loop") loop.emplace();
  akvf::write_file_atomically(argv[1], [&](std::ostream& out) {
    out << "partial content" << std::flush;
    std::raise(SIGINT);  // in a loop: only sets the flag; outside: ends the process
    if (!loop) return;
    if (!akvf::interrupt_requested()) std::cerr << "second_signal_writer: the flag is not set\n";
    std::raise(SIGINT);  // the second ends the process
  });
  std::cerr << "second_signal_writer: still alive after the signals\n";
  return 1;
}
