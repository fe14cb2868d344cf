#pragma once
// Clean interruption (Ctrl-C): the first SIGINT or SIGTERM only raises a
// flag that the optimizer loops check once per iteration, so a run ends with
// the status "interrupted", its best iterate and a complete trace, and the
// commands write their outputs as usual (through temporary names). A second
// signal ends the process at once, after deleting the temporary files of the
// outputs being written (output_file.h).
namespace akvf {

// Installs the handler for SIGINT and SIGTERM (idempotent).
void install_interrupt_handler();
// True once a signal arrived (or request_interrupt() was called).
bool interrupt_requested();
// Sets the flag as a signal would (for tests and embedding programs).
void request_interrupt();
// Clears the flag (between independent runs in one process).
void clear_interrupt();

}  // namespace akvf
