#pragma once

#include <cstdint>
#include <string>

namespace fosssim {

/// Installs a handler that only records the request for every signal whose default action ends
/// the process and that a program may catch: SIGINT, SIGTERM, SIGHUP, SIGQUIT, SIGPIPE, SIGALRM,
/// SIGUSR1, SIGUSR2, SIGXFSZ, SIGXCPU, SIGVTALRM, SIGPROF, SIGIO, SIGPWR, SIGSTKFLT and the
/// real-time signals. Long runs then stop between steps and keep what they computed, as for
/// Ctrl-C; a write that the signal interrupts fails with an error instead (SIGPIPE: the reader
/// is gone; SIGXFSZ: the file size limit). Only SIGKILL (and SIGSTOP) cannot be handled.
/// Only signals at their default action are taken: one ignored from the start (nohup, a
/// background job of a non-interactive shell) stays ignored, and one another library already
/// handles (a profiler's SIGPROF) stays with it.
void install_interrupt_handler();

/// True once one of those signals was received.
bool interrupt_requested();

/// The number of the first signal received, 0 if none.
int interrupt_signal();

/// What a run stopped by that signal says, headless or in the window, followed by what it
/// kept of its outputs: "interrupted by signal 15 (Terminated) at step 12".
std::string interrupted_at(std::int64_t step);

}  // namespace fosssim
