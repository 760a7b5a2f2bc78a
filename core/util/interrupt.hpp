#pragma once
// Ctrl-C (SIGINT) and SIGTERM for long commands: the first one only asks the
// work to stop at its next safe point (a replay after the current frame, the
// optimiser after the current generation), which then finishes what it has
// and writes complete outputs; a second one ends the process at once with
// the signal's default action.
namespace facadeslam {

// Installs the handlers for the life of the guard (restores the previous
// ones after); one guard at a time.
class InterruptGuard {
 public:
  InterruptGuard();
  ~InterruptGuard();
  InterruptGuard(const InterruptGuard&) = delete;
  InterruptGuard& operator=(const InterruptGuard&) = delete;
};

// A stop was asked for (since the guard was made).
bool interrupt_requested();

// The conventional exit code of a command stopped by SIGINT (128 + 2).
inline constexpr int kExitInterrupted = 130;

}  // namespace facadeslam
