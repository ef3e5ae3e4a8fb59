#include "interrupt.hpp"

#include <csignal>

#include "newtop/io/output.hpp"

namespace newtop::app {
namespace {

volatile std::sig_atomic_t g_signal = 0;

extern "C" void record_signal(int s) { g_signal = s; }

struct sigaction g_previous_int, g_previous_term;

// The default action, after removing the temporaries of the open output files.
extern "C" void remove_partial_files_and_die(int s) {
  io::remove_open_temporaries();
  std::signal(s, SIG_DFL);
  std::raise(s);
}

}  // namespace

void remove_partial_files_on_signal() {
  struct sigaction sa {};
  sa.sa_handler = remove_partial_files_and_die;
  sigemptyset(&sa.sa_mask);
  sigaction(SIGINT, &sa, nullptr);
  sigaction(SIGTERM, &sa, nullptr);
}

InterruptGuard::InterruptGuard() {
  g_signal = 0;
  struct sigaction sa {};
  sa.sa_handler = record_signal;
  sigemptyset(&sa.sa_mask);
  sa.sa_flags = SA_RESETHAND;  // a second signal terminates at once
  sigaction(SIGINT, &sa, &g_previous_int);
  sigaction(SIGTERM, &sa, &g_previous_term);
}

InterruptGuard::~InterruptGuard() {
  sigaction(SIGINT, &g_previous_int, nullptr);
  sigaction(SIGTERM, &g_previous_term, nullptr);
}

int pending_signal() { return static_cast<int>(g_signal); }

void throw_if_interrupted(double t) {
  if (g_signal != 0) throw Interrupted(static_cast<int>(g_signal), t);
}

std::string signal_name(int signal) {
  return signal == SIGINT ? "SIGINT" : signal == SIGTERM ? "SIGTERM" : std::to_string(signal);
}

}  // namespace newtop::app
