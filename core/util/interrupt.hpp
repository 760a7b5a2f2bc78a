#pragma once
// Ctrl-C (SIGINT) and SIGTERM for long commands: the first one only asks the
// work to stop at its next safe point (a replay after the current frame, the
// optimiser after the current generation), which then finishes what it has
// and writes complete outputs; a second one ends the process at once
// (exit code 130: the signal is still blocked in its handler, so _exit comes
// before the re-raised signal), after removing the staged output folder and
// the files being written.
#include <filesystem>

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

// A folder that a second signal removes before it ends the process (a
// staged output folder, core/util/staged_folder.hpp), so that an abort
// leaves no half-written folder behind. One at a time; an empty path
// clears it. The removal in the handler uses only async-signal-safe calls.
void set_abort_cleanup_folder(const std::filesystem::path& folder);

// A file being written (atomic_write.hpp's temporary) that a second signal
// removes before it ends the process, for the life of the guard. Up to
// kAbortCleanupFiles at once (writers on several threads); beyond that the
// file is not registered.
class AbortCleanupFile {
 public:
  explicit AbortCleanupFile(const std::filesystem::path& file);
  ~AbortCleanupFile();
  AbortCleanupFile(const AbortCleanupFile&) = delete;
  AbortCleanupFile& operator=(const AbortCleanupFile&) = delete;

 private:
  int slot_ = -1;
};
inline constexpr int kAbortCleanupFiles = 8;

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
