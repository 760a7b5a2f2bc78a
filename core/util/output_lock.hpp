#pragma once
// One run at a time per output: a second run into an output another run is
// still writing is refused at once, with the other process named, instead of
// both finishing and the last one silently winning. The lock is a file
// beside the target, DIR/.NAME.lock, holding the writer's process id, locked
// with flock(): the kernel releases it when the process ends however it
// ends, so the lock of a killed run is simply taken over. The file is
// removed when the lock is released (and by a second Ctrl-C's clean-up).
#include <filesystem>
#include <memory>

namespace facadeslam {

class AbortCleanupFile;

class OutputLock {
 public:
  // Locks `target` (its folder must exist). An Error naming the target and
  // the other process when another run holds it, or when the lock file
  // cannot be made.
  explicit OutputLock(const std::filesystem::path& target);
  ~OutputLock();
  OutputLock(const OutputLock&) = delete;
  OutputLock& operator=(const OutputLock&) = delete;

  const std::filesystem::path& path() const { return lock_file_; }

 private:
  std::filesystem::path lock_file_;
  int fd_ = -1;
  std::unique_ptr<AbortCleanupFile> abort_cleanup_;
};

// DIR/.NAME.lock for DIR/NAME.
std::filesystem::path output_lock_file(const std::filesystem::path& target);

}  // namespace facadeslam
