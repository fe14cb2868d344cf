#pragma once
// Clean interruption (Ctrl-C) for programs that install the handler. While an
// optimizer iterates (it holds an InterruptibleLoop and checks the flag once
// per iteration), the first SIGINT or SIGTERM only raises a flag, so a run
// ends with the status "interrupted", its best iterate and a complete trace,
// and the commands write their outputs as usual (through temporary names).
// The parameterization's rounds of seams and cuts for the packing hold one
// too, checking between their steps. Any other time (reading, ordering, the
// start map, the analysis, writing) a signal ends the process at once, as does a second signal: first the
// temporary files of the outputs being written are deleted (output_file.h).
namespace akvf {

// Installs the handler for SIGINT and SIGTERM (idempotent).
void install_interrupt_handler();
// True once a signal arrived (or request_interrupt() was called).
bool interrupt_requested();
// Sets the flag as a signal would (for tests and embedding programs).
void request_interrupt();
// Clears the flag (between independent runs in one process).
void clear_interrupt();

// Marks a loop that checks interrupt_requested() once per iteration: while
// one exists, the handler's first signal only raises the flag.
class InterruptibleLoop {
 public:
  InterruptibleLoop();
  ~InterruptibleLoop();
  InterruptibleLoop(const InterruptibleLoop&) = delete;
  InterruptibleLoop& operator=(const InterruptibleLoop&) = delete;
};

}  // namespace akvf
