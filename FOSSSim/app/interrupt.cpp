#include "app/interrupt.h"

#include <csignal>
#include <cstring>
#include <initializer_list>

namespace fosssim {

namespace {
volatile std::sig_atomic_t g_signal = 0;
extern "C" void on_interrupt(int number) {
  if (g_signal == 0) g_signal = number;
}
/// Installs `action` for `number` only where the default action holds: a signal ignored from
/// the start (nohup, a background job of a script) stays ignored, and one that a profiler or
/// another library already handles (SIGPROF under gperftools) stays theirs.
void install(int number, const struct sigaction& action) {
  struct sigaction current {};
  if (::sigaction(number, nullptr, &current) != 0) return;
  if ((current.sa_flags & SA_SIGINFO) == 0 && current.sa_handler == SIG_DFL) {
    ::sigaction(number, &action, nullptr);
  }
}

}  // namespace

void install_interrupt_handler() {
  struct sigaction action {};
  action.sa_handler = on_interrupt;
  sigemptyset(&action.sa_mask);
  action.sa_flags = SA_RESTART;  // blocking reads and writes resume; the run checks between steps
  for (const int number : {SIGINT, SIGTERM, SIGHUP, SIGQUIT, SIGPIPE, SIGALRM, SIGUSR1, SIGUSR2,
                           SIGXFSZ, SIGXCPU, SIGVTALRM, SIGPROF, SIGIO, SIGPWR, SIGSTKFLT}) {
    install(number, action);
  }
  for (int number = SIGRTMIN; number <= SIGRTMAX; ++number) install(number, action);
}

bool interrupt_requested() { return g_signal != 0; }

int interrupt_signal() { return g_signal; }

std::string interrupted_at(std::int64_t step) {
  return "interrupted by signal " + std::to_string(g_signal) + " (" + strsignal(g_signal) +
         ") at step " + std::to_string(step);
}

}  // namespace fosssim
