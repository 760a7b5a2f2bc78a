// The tests' main (test_main.cpp): a run whose every selected test skipped
// exits with kAllSkippedExitCode, so CTest shows a suite that needs absent
// data as skipped; a run with a pass or a failure keeps gtest's exit code.
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "tests/apps/cli_run.hpp"
#include "tests/support/test_main.hpp"
#include "tests/support/test_support.hpp"

namespace facadeslam {
namespace {

// Run only by the tests below (disabled tests run when asked for).
TEST(DISABLED_TestMainSkipsOnly, Skips) { GTEST_SKIP() << "skipped on purpose"; }
TEST(DISABLED_TestMainSkipsOnly, AlsoSkips) { GTEST_SKIP() << "skipped on purpose"; }
TEST(DISABLED_TestMainMixed, Skips) { GTEST_SKIP() << "skipped on purpose"; }
TEST(DISABLED_TestMainMixed, Passes) { SUCCEED(); }
TEST(DISABLED_TestMainMixed, Fails) { FAIL() << "failed on purpose"; }

int exit_code_of_this_program(const std::string& filter) {
  const test::TempDir scratch;
  const std::string self = std::filesystem::read_symlink("/proc/self/exe").string();
  std::string arguments = "--gtest_also_run_disabled_tests --gtest_filter=";
  arguments.append(test::shell_quoted(filter));
  return test::run_cli(self, arguments, scratch.path()).exit_code;
}

TEST(TestMain, AllSkippedIsItsOwnExitCode) {
  EXPECT_EQ(exit_code_of_this_program("DISABLED_TestMainSkipsOnly.*"), test::kAllSkippedExitCode);
}

TEST(TestMain, APassAmongSkipsIsSuccess) {
  EXPECT_EQ(exit_code_of_this_program("DISABLED_TestMainMixed.Skips:DISABLED_TestMainMixed.Passes"), 0);
}

TEST(TestMain, AFailureAmongSkipsIsFailure) {
  EXPECT_EQ(exit_code_of_this_program("DISABLED_TestMainMixed.Skips:DISABLED_TestMainMixed.Fails"), 1);
  EXPECT_EQ(exit_code_of_this_program("DISABLED_TestMainMixed.*"), 1);
}

}  // namespace
}  // namespace facadeslam
