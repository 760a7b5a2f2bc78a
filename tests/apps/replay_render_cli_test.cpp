// `facadeslam replay --render DIR` end to end on the first frames of the
// demo scene (rendered here by `facadeslam synth`): rendering leaves the
// tracking results identical bit for bit (--sync), writes the frames, the
// MP4 and the contact sheet, and counts the frames drawn without overlay in
// report.json. (Bad render options: replay_render_options_cli_test.cpp.)
#include <algorithm>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <opencv2/imgcodecs.hpp>

#include "tests/apps/cli_run.hpp"
#include "tests/support/test_support.hpp"

namespace facadeslam {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

std::string quoted(const fs::path& p) { return test::shell_quoted(p.string()); }

constexpr int kFrames = 40;

class ReplayRenderCli : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = new test::TempDir();
    fs::create_directories(scratch());
    std::string args = "-q synth --scene ";
    args.append(quoted(test::source_dir() / "configs" / "scenes" / "demo.yaml"))
        .append(" --out ")
        .append(quoted(sequence()))
        .append(" --frames ")
        .append(std::to_string(kFrames));
    const test::CliResult r = run(args);
    ASSERT_EQ(r.exit_code, 0) << r.err;
  }
  static void TearDownTestSuite() {
    delete dir_;
    dir_ = nullptr;
  }
  static fs::path scratch() { return dir_->path() / "scratch"; }
  static fs::path sequence() { return dir_->path() / "demo"; }
  static test::CliResult run(const std::string& arguments) {
    return test::run_cli(FACADESLAM_BINARY, arguments, scratch());
  }
  // A synchronous replay without the semantic worker (faster; labels are
  // not what is tested) into OUT, with `extra` arguments.
  static test::CliResult replay(const fs::path& out, const std::string& extra) {
    std::string args = "-q replay ";
    args.append(quoted(sequence())).append(" --sync --semantics off --out ").append(quoted(out)).append(" ");
    return run(args + extra);
  }

  static test::TempDir* dir_;
};

test::TempDir* ReplayRenderCli::dir_ = nullptr;

TEST_F(ReplayRenderCli, RenderingLeavesTrackingBitForBitTheSameAndWritesItsOutputs) {
  const fs::path plain = dir_->path() / "plain", rendered = dir_->path() / "rendered";
  const fs::path render_dir = dir_->path() / "ar";
  const test::CliResult without = replay(plain, "");
  ASSERT_EQ(without.exit_code, 0) << without.err;
  const test::CliResult with = replay(rendered, "--render " + quoted(render_dir) + " --render-every 2");
  ASSERT_EQ(with.exit_code, 0) << with.err;

  for (const char* file : {"trajectory.txt", "trajectory_online.txt", "keyframes.txt"}) {
    const std::string a = test::read_file_text(plain / file), b = test::read_file_text(rendered / file);
    EXPECT_FALSE(a.empty()) << file;
    EXPECT_EQ(a, b) << file << " differs with --render";
  }
  const std::string report = test::read_file_text(rendered / "report.json");
  EXPECT_EQ(test::json_number(report, "frames_rendered"), kFrames / 2.0);
  // The frames before initialisation have no pose: drawn without overlay.
  const double without_overlay = test::json_number(report, "frames_without_overlay");
  EXPECT_GT(without_overlay, 0.0);
  EXPECT_LT(without_overlay, kFrames / 2.0);
  EXPECT_THAT(report, HasSubstr("\"video_codec\""));
  EXPECT_THAT(test::read_file_text(plain / "report.json"), ::testing::Not(HasSubstr("\"render\"")));

  std::size_t pngs = 0;
  for (const auto& entry : fs::directory_iterator(render_dir / "frames")) pngs += entry.path().extension() == ".png";
  EXPECT_EQ(pngs, static_cast<std::size_t>(kFrames / 2));
  const cv::Mat last = cv::imread((render_dir / "frames" / "ar_000038.png").string());
  ASSERT_FALSE(last.empty());
  EXPECT_EQ(last.rows, 480);
  EXPECT_EQ(last.cols, 640 + 640);  // the AR view beside the map view
  EXPECT_GT(fs::file_size(render_dir / "augmented.mp4"), 10000u);
  EXPECT_FALSE(cv::imread((render_dir / "contact_sheet.png").string()).empty());
  // Nothing half-written is left behind.
  for (const auto& entry : fs::directory_iterator(render_dir))
    EXPECT_THAT(entry.path().filename().string(), ::testing::Not(HasSubstr("partial")));
  // The report names where the outputs are, not the folder they were staged in.
  const auto render = nlohmann::json::parse(report)["render"];
  EXPECT_EQ(render["video"], (render_dir / "augmented.mp4").string());
  EXPECT_EQ(render["frames_dir"], (render_dir / "frames").string());
  EXPECT_EQ(render["contact_sheet"], (render_dir / "contact_sheet.png").string());
}

// Bad input for the object: with no map to stand it on the frames are
// rendered without it, and the report and the log say why.
TEST_F(ReplayRenderCli, WithoutAMapTheFramesAreRenderedWithoutTheObjectAndTheReportSaysWhy) {
  const fs::path out = dir_->path() / "small", render_dir = out / "ar";
  // Two frames: the map never initialises.
  const test::CliResult r = replay(out, "--limit 2 --render " + quoted(render_dir));
  ASSERT_EQ(r.exit_code, 3) << r.err;  // never initialised
  const auto render = nlohmann::json::parse(test::read_file_text(out / "report.json"))["render"];
  EXPECT_EQ(render["plane"]["kind"], "none");
  EXPECT_EQ(render["plane"]["why"], "no rendered frame was tracked");
  EXPECT_EQ(render["frames_with_object"], 0);
  EXPECT_THAT(r.err, HasSubstr("render: no virtual object in the view: no rendered frame was tracked"));
}

}  // namespace
}  // namespace facadeslam
