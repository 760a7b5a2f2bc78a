#pragma once
// An output folder that is whole or untouched: a run writes its files into
// a hidden sibling of the target (DIR/../.NAME.tmp-PID) and commit() moves
// that folder into place at the end, so that the target never mixes the
// files of two runs. A run that fails (an exception: the destructor), or a
// second Ctrl-C (core/util/interrupt.hpp), removes the staging folder and
// leaves the previous target as it was.
//
// commit() swaps the two folders with one renameat2(RENAME_EXCHANGE), then
// removes the old one. Where the file system has no exchange (some network
// and FUSE file systems), it renames the old target away (.NAME.old-PID),
// the new one in and removes the old: between the two renames, a window of
// microseconds, the target does not exist; a crash inside it leaves the old
// folder as .NAME.old-PID beside it.
//
// While the run lasts it holds the target's lock (output_lock.hpp): a second
// run into the same target is refused at once, naming the first.
#include <filesystem>
#include <functional>
#include <memory>

namespace facadeslam {

class AbortCleanupFile;
class OutputLock;

// What a staging folder starts with: nothing (a run that writes everything
// anew), or the target's files, for a run that continues an earlier one
// (optimise --resume). Such a run's staging folder, left by a SIGKILL, may
// be further on than the target: `abandoned_is_newer(abandoned, than)` says
// so, and the run then continues from it.
struct StagedFolderStart {
  bool from_target = false;
  std::function<bool(const std::filesystem::path& abandoned, const std::filesystem::path& than)> abandoned_is_newer;
};

class StagedFolder {
 public:
  // Creates the empty staging folder beside `target` (and target's missing
  // ancestors, removed again if the run fails) and locks the target.
  // Staging folders of earlier runs whose process is gone are removed. An
  // Error naming `target` when it is a file, nothing can be made beside it,
  // or another run is writing it.
  explicit StagedFolder(std::filesystem::path target, const StagedFolderStart& start = {});
  ~StagedFolder();
  StagedFolder(const StagedFolder&) = delete;
  StagedFolder& operator=(const StagedFolder&) = delete;

  // Where the run writes its files until commit().
  const std::filesystem::path& path() const { return staging_; }
  const std::filesystem::path& target() const { return target_; }
  // `p` inside the target -> the same place inside the staging folder; any
  // other path unchanged.
  std::filesystem::path staged(const std::filesystem::path& p) const;
  // Whether `p` lies inside the target folder (lexically, made absolute).
  bool contains(const std::filesystem::path& p) const;

  // Moves the staging folder into place (replacing an existing target).
  void commit();

 private:
  std::filesystem::path target_, staging_;
  std::filesystem::path created_root_;  // the outermost ancestor this made, or empty
  std::unique_ptr<OutputLock> lock_;
  std::unique_ptr<AbortCleanupFile> abort_cleanup_;  // the staging folder, for a signal that ends the run
  bool committed_ = false;
};

}  // namespace facadeslam
