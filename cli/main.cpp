// akvf: isometry-aware preconditioned mesh parameterization (command line).
#include <iostream>

#include "cli/akvf_cli.h"
#include "framework/process/interrupt.h"
#include "framework/process/native_runtime.h"

int main(int argc, char** argv) {
  akvf::configure_native_runtime(argv);
  akvf::install_interrupt_handler();  // Ctrl-C ends a run cleanly, outputs written (interrupt.h)
  return akvf::run_akvf(std::vector<std::string>(argv + 1, argv + argc), std::cout, std::cerr);
}
