// `facadeslam replay --render`: bad render options are one-line usage errors
// (exit code 2), found before the sequence is opened.
#include <algorithm>
#include <fstream>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "tests/apps/cli_run.hpp"
#include "tests/support/test_support.hpp"

namespace facadeslam {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

std::string quoted(const fs::path& p) { return test::shell_quoted(p.string()); }

// Needs no sequence: the render options are checked before it is opened (an
// empty folder would otherwise fail with exit code 1, "no images found").
TEST(ReplayRenderOptions, BadRenderOptionsAreUsageErrorsBeforeTheReplay) {
  test::TempDir dir;
  fs::create_directories(dir / "scratch");
  fs::create_directories(dir / "empty");
  const auto replay = [&](const std::string& extra) {
    std::string args = "-q replay ";
    args.append(quoted(dir / "empty")).append(" --camera ");
    args.append(quoted(test::source_dir() / "configs" / "camera" / "synthetic-640x480.yaml"));
    args.append(" --out ").append(quoted(dir / "out")).append(" ");
    return test::run_cli(FACADESLAM_BINARY, args + extra, dir / "scratch");
  };
  const auto expect_usage_error = [](const test::CliResult& r, const std::string& mention) {
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_THAT(r.err, HasSubstr(mention));
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  };
  expect_usage_error(replay("--render " + quoted(dir / "x") + " --render-every 0"), "--render-every");
  expect_usage_error(replay("--render-every 3"), "--render");
  // A file where the folder should be: refused by the output policy before
  // anything is read (a bad file, exit code 1, like --out's), and left alone.
  const fs::path file = dir / "a-file";
  { std::ofstream(file) << "x"; }
  const test::CliResult on_a_file = replay("--render " + quoted(file));
  EXPECT_EQ(on_a_file.exit_code, 1) << on_a_file.err;
  EXPECT_THAT(on_a_file.err, HasSubstr("--render is an output folder, but it is a file"));
  EXPECT_EQ(std::count(on_a_file.err.begin(), on_a_file.err.end(), '\n'), 1) << on_a_file.err;
  EXPECT_EQ(test::read_file_text(file), "x");
  // The sequence itself is fine for this check: with a good --render the
  // empty folder is what fails, later.
  const test::CliResult good = replay("--render " + quoted(dir / "ar"));
  EXPECT_EQ(good.exit_code, 1) << good.err;
  EXPECT_THAT(good.err, HasSubstr("no images found"));
  EXPECT_FALSE(fs::exists(dir / "out" / "report.json"));
}

}  // namespace
}  // namespace facadeslam
