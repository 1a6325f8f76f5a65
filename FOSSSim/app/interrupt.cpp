#include "app/interrupt.h"

#include <csignal>
#include <initializer_list>

namespace fosssim {

namespace {
volatile std::sig_atomic_t g_signal = 0;
extern "C" void on_interrupt(int number) {
  if (g_signal == 0) g_signal = number;
}
}  // namespace

void install_interrupt_handler() {
  struct sigaction action {};
  action.sa_handler = on_interrupt;
  sigemptyset(&action.sa_mask);
  action.sa_flags = SA_RESTART;  // blocking reads and writes resume; the run checks between steps
  // A run started with nohup, or in the background of a shell without job control, was told
  // to ignore these: it goes on ignoring them.
  for (const int number : {SIGINT, SIGHUP, SIGQUIT}) {
    struct sigaction current {};
    if (::sigaction(number, nullptr, &current) == 0 && current.sa_handler == SIG_IGN) continue;
    ::sigaction(number, &action, nullptr);
  }
  for (const int number : {SIGTERM, SIGPIPE, SIGALRM, SIGUSR1, SIGUSR2, SIGXFSZ, SIGXCPU, SIGVTALRM,
                           SIGPROF, SIGIO, SIGPWR, SIGSTKFLT}) {
    ::sigaction(number, &action, nullptr);
  }
  for (int number = SIGRTMIN; number <= SIGRTMAX; ++number) ::sigaction(number, &action, nullptr);
}

bool interrupt_requested() { return g_signal != 0; }

int interrupt_signal() { return g_signal; }

}  // namespace fosssim
