// One run per output at a time: the lock beside the target refuses a second
// holder (naming the first), is taken over from a process that died, and
// leaves no file behind.
#include "core/util/output_lock.hpp"

#include <csignal>
#include <fstream>
#include <memory>

#include <sys/wait.h>
#include <unistd.h>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "core/util/staged_folder.hpp"
#include "tests/support/test_support.hpp"

namespace facadeslam {
namespace {

namespace fs = std::filesystem;
using test::error_of;
using ::testing::AllOf;
using ::testing::HasSubstr;

// The process id a lock file names (0 when it names none).
long pid_in(const fs::path& lock_file) {
  std::ifstream in(lock_file);
  long pid = 0;
  in >> pid;
  return pid;
}

TEST(OutputLock, IsAFileBesideTheTargetRemovedWhenReleased) {
  test::TempDir dir;
  EXPECT_EQ(output_lock_file(dir / "out"), dir / ".out.lock");
  EXPECT_EQ(output_lock_file(dir / "out" / ""), dir / ".out.lock");
  {
    const OutputLock lock(dir / "out");
    EXPECT_EQ(pid_in(dir / ".out.lock"), ::getpid());
  }
  EXPECT_FALSE(fs::exists(dir / ".out.lock"));
}

// flock() locks belong to the open file, so a second lock in this process
// conflicts like another process's would.
TEST(OutputLock, ASecondHolderIsRefusedWithTheFirstNamed) {
  test::TempDir dir;
  const OutputLock first(dir / "out");
  EXPECT_THAT(error_of([&] { const OutputLock second(dir / "out"); }),
              AllOf(HasSubstr((dir / "out").string()), HasSubstr("process " + std::to_string(::getpid())),
                    HasSubstr("is writing this output now")));
  EXPECT_THAT(error_of([&] { const StagedFolder staged(dir / "out"); }), HasSubstr("is writing this output now"));
  EXPECT_FALSE(fs::exists(dir / "out"));
  EXPECT_TRUE(fs::exists(dir / ".out.lock")) << "the first holder's lock stays";
}

TEST(OutputLock, TheLockOfAProcessThatDiedIsTakenOver) {
  test::TempDir dir;
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    static const OutputLock* const never_released = new OutputLock(dir / "out");  // the process is killed
    (void)never_released;
    ::raise(SIGKILL);
    ::_exit(0);
  }
  int status = 0;
  ::waitpid(child, &status, 0);
  ASSERT_TRUE(WIFSIGNALED(status));
  ASSERT_TRUE(fs::exists(dir / ".out.lock")) << "a killed holder leaves its file";
  {
    const OutputLock lock(dir / "out");
    EXPECT_EQ(pid_in(dir / ".out.lock"), ::getpid());
  }
  EXPECT_FALSE(fs::exists(dir / ".out.lock"));
}

TEST(OutputLock, StagedFoldersHoldItForTheirLife) {
  test::TempDir dir;
  {
    StagedFolder staged(dir / "out");
    EXPECT_TRUE(fs::exists(dir / ".out.lock"));
    staged.commit();
    EXPECT_TRUE(fs::exists(dir / ".out.lock")) << "held until the run is done with the folder";
  }
  EXPECT_FALSE(fs::exists(dir / ".out.lock"));
  EXPECT_TRUE(fs::is_directory(dir / "out"));
}

}  // namespace
}  // namespace facadeslam
