// Ctrl-C handling: the first signal only asks the work to stop; a second one
// ends the process, removing the staged folder and the files being written
// first (death tests: each runs in a child process).
#include "core/util/interrupt.hpp"

#include <csignal>
#include <cstdlib>
#include <fstream>
#include <memory>
#include <utility>
#include <vector>

#include <sys/wait.h>

#include <gtest/gtest.h>

#include "tests/support/test_support.hpp"

namespace facadeslam {
namespace {

namespace fs = std::filesystem;

void touch(const fs::path& file) { std::ofstream(file) << "half-written"; }

// The second signal ends the process with the signal's default action, or,
// where the signal is still blocked inside its handler, with exit code 130.
bool ended_by_the_signal(int status) {
  return (WIFSIGNALED(status) && WTERMSIG(status) == SIGINT) ||
         (WIFEXITED(status) && WEXITSTATUS(status) == kExitInterrupted);
}

// Death tests fork (gtest's "fast" style, the default): the child writes
// into the parent's scratch folder, whose paths the parent then checks.

TEST(Interrupt, TheFirstSignalOnlyAsksToStop) {
  test::TempDir dir;
  const fs::path file = dir / "output.tmp";
  touch(file);
  {
    const InterruptGuard guard;
    const AbortCleanupFile cleanup(file);
    EXPECT_FALSE(interrupt_requested());
    std::raise(SIGINT);
    EXPECT_TRUE(interrupt_requested());
  }
  EXPECT_TRUE(fs::exists(file));
}

TEST(InterruptDeathTest, ASecondSignalRemovesTheFilesBeingWrittenAndTheStagedFolder) {
  test::TempDir dir;
  const fs::path writing = dir / ".map.tmp1_0.bin", finished = dir / "trajectory.txt", staged = dir / ".out.staging";
  EXPECT_EXIT(
      {
        touch(writing);
        touch(finished);
        fs::create_directories(staged / "plots");
        touch(staged / "plots" / "a.png");
        const InterruptGuard guard;
        set_abort_cleanup_folder(staged);
        const AbortCleanupFile cleanup(writing);
        { const AbortCleanupFile done(finished); }  // written and released: not removed
        std::raise(SIGINT);
        std::raise(SIGINT);
        std::_Exit(0);
      },
      ended_by_the_signal, "");
  EXPECT_FALSE(fs::exists(writing));
  EXPECT_FALSE(fs::exists(staged));
  EXPECT_TRUE(fs::exists(finished));
}

TEST(InterruptDeathTest, MoreFilesThanSlotsAreStillWrittenTheLastOnesUnregistered) {
  test::TempDir dir;
  EXPECT_EXIT(
      {
        const InterruptGuard guard;
        std::vector<std::unique_ptr<AbortCleanupFile>> guards;
        for (int i = 0; i <= kAbortCleanupFiles; ++i) {
          const fs::path file = dir / ("f" + std::to_string(i));
          touch(file);
          guards.push_back(std::make_unique<AbortCleanupFile>(file));
        }
        std::raise(SIGINT);
        std::raise(SIGINT);
        std::_Exit(0);
      },
      ended_by_the_signal, "");
  for (int i = 0; i < kAbortCleanupFiles; ++i) EXPECT_FALSE(fs::exists(dir / ("f" + std::to_string(i)))) << i;
  EXPECT_TRUE(fs::exists(dir / ("f" + std::to_string(kAbortCleanupFiles))));
}

// SIGTERM and SIGHUP (the terminal closed) are handled like Ctrl-C, each
// with its own exit code.
TEST(Interrupt, EachSignalGivesItsOwnExitCode) {
  for (const auto& [signal, code] : {std::pair{SIGINT, 130}, std::pair{SIGTERM, 143}, std::pair{SIGHUP, 129}}) {
    const InterruptGuard guard;
    EXPECT_EQ(interrupt_exit_code(), kExitInterrupted) << "none yet";
    std::raise(signal);
    EXPECT_TRUE(interrupt_requested()) << signal;
    EXPECT_EQ(interrupt_exit_code(), code) << signal;
  }
}

bool exited_with(int status, int code) { return WIFEXITED(status) && WEXITSTATUS(status) == code; }

TEST(InterruptDeathTest, EndAtOnceEndsAtTheFirstSignalRemovingWhatIsBeingWritten) {
  test::TempDir dir;
  const fs::path writing = dir / ".model.tmp1_0.fsmodel", staged = dir / ".out.tmp-1";
  EXPECT_EXIT(
      {
        touch(writing);
        fs::create_directories(staged / "frames");
        touch(staged / "frames" / "a.png");
        const InterruptGuard guard(InterruptResponse::end_at_once);
        const AbortCleanupFile file(writing);
        const AbortCleanupFile folder(staged);  // a folder, removed with what it holds
        std::raise(SIGHUP);
        std::_Exit(0);
      },
      [](int status) { return exited_with(status, 129); }, "");
  EXPECT_FALSE(fs::exists(writing));
  EXPECT_FALSE(fs::exists(staged));
}

TEST(InterruptDeathTest, ASignalWhileOutputsAreMovedInPlaceWaitsForThem) {
  test::TempDir dir;
  const fs::path finished = dir / "model.fsmodel";
  EXPECT_EXIT(
      {
        const InterruptGuard guard(InterruptResponse::end_at_once);
        {
          const AbortDeferral both_or_neither;
          std::raise(SIGTERM);
          touch(finished);  // still runs: the signal waits
        }
        std::_Exit(0);
      },
      [](int status) { return exited_with(status, 143); }, "");
  EXPECT_TRUE(fs::exists(finished));
}

}  // namespace
}  // namespace facadeslam
