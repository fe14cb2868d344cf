#include "framework/process/interrupt.h"

#include <atomic>
#include <csignal>

#include "framework/process/output_file.h"

namespace akvf {

namespace {

std::atomic<bool> interrupted{false};
std::atomic<int> signals_received{0};
std::atomic<int> interruptible_loops{0};

extern "C" void on_signal(int signal) {
  interrupted.store(true);
  if (signals_received.fetch_add(1) == 0 && interruptible_loops.load() > 0) return;
  // Outside a loop that checks the flag, or a second signal: end the process
  // at once, after deleting the temporary files of outputs being written, so
  // no `*.tmpPID` file is left behind.
  remove_pending_temporary_files();
  std::signal(signal, SIG_DFL);
  std::raise(signal);
}

}  // namespace

void install_interrupt_handler() {
  std::signal(SIGINT, on_signal);
  std::signal(SIGTERM, on_signal);
}

bool interrupt_requested() { return interrupted.load(); }

void request_interrupt() { interrupted.store(true); }

void clear_interrupt() {
  interrupted.store(false);
  signals_received.store(0);
}

InterruptibleLoop::InterruptibleLoop() { interruptible_loops.fetch_add(1); }
InterruptibleLoop::~InterruptibleLoop() { interruptible_loops.fetch_sub(1); }

}  // namespace akvf
