#pragma once
// Ctrl-C (SIGINT), SIGTERM and SIGHUP (the terminal closed) for long
// commands. A command that can stop at a safe point (a replay after the
// current frame, the optimiser after the current generation) asks the guard
// for that: the first signal only asks the work to stop, which then finishes
// what it has and writes complete outputs; a second one ends the process at
// once. Other commands (training a forest, an evaluation: nothing worth
// keeping before the end) end at the first signal. Ending removes the staged
// output folder and the files being written first, and exits with 128 + the
// signal (130 SIGINT, 143 SIGTERM, 129 SIGHUP: the signal is still blocked in
// its handler, so _exit comes before the re-raised signal).
#include <filesystem>

namespace facadeslam {

enum class InterruptResponse {
  stop_at_safe_point,  // the first signal asks (interrupt_requested()), the second ends
  end_at_once,         // the first signal ends the process
};

// Installs the handlers for the life of the guard (restores the previous
// ones after); one guard at a time.
class InterruptGuard {
 public:
  explicit InterruptGuard(InterruptResponse response = InterruptResponse::stop_at_safe_point);
  ~InterruptGuard();
  InterruptGuard(const InterruptGuard&) = delete;
  InterruptGuard& operator=(const InterruptGuard&) = delete;
};

// A stop was asked for (since the guard was made).
bool interrupt_requested();
// The exit code for the signal that asked it: 128 + its number (130 for
// SIGINT, 143 for SIGTERM, 129 for SIGHUP); kExitInterrupted when none came.
int interrupt_exit_code();

// A folder that a second signal removes before it ends the process (a
// staged output folder, core/util/staged_folder.hpp), so that an abort
// leaves no half-written folder behind. One at a time; an empty path
// clears it. The removal in the handler uses only async-signal-safe calls.
void set_abort_cleanup_folder(const std::filesystem::path& folder);

// A file being written (atomic_write.hpp's temporary), a staging folder or a
// lock file that a signal ending the process removes first (a folder with
// everything in it), for the life of the object. Up to kAbortCleanupFiles at
// once (writers on several threads, two staged folders); beyond that the
// path is not registered.
class AbortCleanupFile {
 public:
  explicit AbortCleanupFile(const std::filesystem::path& file);
  ~AbortCleanupFile();
  AbortCleanupFile(const AbortCleanupFile&) = delete;
  AbortCleanupFile& operator=(const AbortCleanupFile&) = delete;

 private:
  int slot_ = -1;
};
inline constexpr int kAbortCleanupFiles = 16;

// While a staged folder is being moved into place, a second signal waits
// for it to finish (the rename and the removal of the old folder), then
// ends the process: the target is the old or the new folder, never neither.
class AbortDeferral {
 public:
  AbortDeferral();
  ~AbortDeferral();  // ends the process now if a signal came meanwhile
  AbortDeferral(const AbortDeferral&) = delete;
  AbortDeferral& operator=(const AbortDeferral&) = delete;
};

// The conventional exit code of a command stopped by SIGINT (128 + 2).
inline constexpr int kExitInterrupted = 130;

}  // namespace facadeslam
