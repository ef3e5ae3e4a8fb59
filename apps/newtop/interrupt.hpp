#pragma once
// SIGINT and SIGTERM during a run. The handler only records the signal; the run checks it at every
// step and stops by throwing Interrupted, so that the stack unwinds and every output file under
// construction (io::AtomicFile) is removed on the way out. The command then reports the
// interruption and exits with 128 + the signal number, the shell's convention. A second signal
// while the first is being handled takes the default action (immediate termination).

#include <exception>
#include <string>

namespace newtop::app {

/// For the commands that do not stop gracefully: SIGINT or SIGTERM removes the temporaries of
/// the open output files (io::AtomicFile) and then terminates the process as the signal would
/// (exit status 128 + the signal number in the shell). An InterruptGuard overrides it while it
/// lives.
void remove_partial_files_on_signal();

/// Thrown by throw_if_interrupted when a signal arrived.
struct Interrupted : std::exception {
  int signal;
  double t;  ///< the time the run had reached
  Interrupted(int s, double time) : signal(s), t(time) {}
  const char* what() const noexcept override { return "interrupted by a signal"; }
};

/// Installs the handlers for its lifetime (restoring the previous ones after).
class InterruptGuard {
 public:
  InterruptGuard();
  ~InterruptGuard();
  InterruptGuard(const InterruptGuard&) = delete;
  InterruptGuard& operator=(const InterruptGuard&) = delete;
};

/// The signal that arrived under an InterruptGuard, 0 if none.
int pending_signal();

/// Throws Interrupted{signal, t} when SIGINT or SIGTERM arrived under an InterruptGuard.
void throw_if_interrupted(double t);

/// "SIGINT", "SIGTERM".
std::string signal_name(int signal);

}  // namespace newtop::app
