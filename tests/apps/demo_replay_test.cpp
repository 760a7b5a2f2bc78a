// The README's main job exactly as a user runs it: `facadeslam replay` with
// no sequence replays the embedded demo threaded, with its ground truth.
// Issue 16 holds its final trajectory (trajectory.txt, recomposed from the
// map after the last bundle adjustment) to 0.5 % of the path. Measured:
// 0.42-0.44 % on a quiet machine. A threaded replay is fed as fast as the
// tracker goes, so another heavy process on the 2 cores slows the map maker
// against the frames (1.49 % once beside a whole test run): the test runs
// alone (RUN_SERIAL), as a user's replay does.
#include <cstdio>
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "tests/apps/cli_run.hpp"
#include "tests/support/test_support.hpp"

namespace facadeslam {
namespace {

namespace fs = std::filesystem;

TEST(DemoReplay, TheEmbeddedDemoThreadedTracksWithinHalfAPercent) {
  const fs::path demo = test::source_dir() / "data" / "demo" / "sequence";
  if (!fs::exists(demo / "rgb.txt")) GTEST_SKIP() << "the embedded demo is not rendered (scripts/make-demo)";
  test::TempDir dir;
  fs::create_directories(dir / "scratch");
  const fs::path out = dir / "demo-threaded";
  // From the project folder, as the README runs it (the demo and the
  // default model are found relative to it).
  const fs::path previous = fs::current_path();
  fs::current_path(test::source_dir());
  const test::CliResult r =
      test::run_cli(FACADESLAM_BINARY, "-q replay --out " + test::shell_quoted(out.string()), dir / "scratch");
  fs::current_path(previous);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string report = test::read_file_text(out / "report.json");
  const double ate = test::json_number(report, "ate_percent_of_path");
  std::printf("[  FIGURES ] demo (threaded): trajectory.txt ATE %.3f %% of the path, %g of %g frames tracked\n", ate,
              test::json_number(report, "frames_tracked"), test::json_number(report, "frames"));
  std::fflush(stdout);
  EXPECT_LE(ate, 0.5);
  EXPECT_EQ(test::json_number(report, "frames_lost"), 0.0);
}

}  // namespace
}  // namespace facadeslam
