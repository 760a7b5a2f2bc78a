#include "core/util/interrupt.hpp"

#include <csignal>

namespace facadeslam {
namespace {

volatile std::sig_atomic_t g_requested = 0;
struct sigaction g_previous_int {}, g_previous_term {};

extern "C" void on_interrupt(int signal) {
  if (g_requested) {
    // The second one: now, as if we had never caught it.
    std::signal(signal, SIG_DFL);
    std::raise(signal);
    return;
  }
  g_requested = 1;
}

}  // namespace

InterruptGuard::InterruptGuard() {
  g_requested = 0;
  struct sigaction action {};
  action.sa_handler = on_interrupt;
  sigemptyset(&action.sa_mask);
  sigaction(SIGINT, &action, &g_previous_int);
  sigaction(SIGTERM, &action, &g_previous_term);
}

InterruptGuard::~InterruptGuard() {
  sigaction(SIGINT, &g_previous_int, nullptr);
  sigaction(SIGTERM, &g_previous_term, nullptr);
}

bool interrupt_requested() { return g_requested != 0; }

}  // namespace facadeslam
