// `facadeslam calibrate` end to end: the built binary on rendered boards,
// its outputs, and its exit codes on bad input (1: bad input or failed run,
// with one line on stderr; 2: bad command line).
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "core/camera/camera_yaml.hpp"
#include "tests/calib/calib_test_scenes.hpp"
#include "tests/support/test_support.hpp"

namespace facadeslam {
namespace {

using ::testing::HasSubstr;

std::string read_file(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

struct CommandResult {
  int exit_code = -1;
  std::string out, err;
};

// Runs `facadeslam calibrate <arguments>` with stdout and stderr captured.
CommandResult calibrate(const test::TempDir& dir, const std::string& arguments) {
  const auto out = dir / "stdout.txt";
  const auto err = dir / "stderr.txt";
  // Built with a stream: GCC 12 misreports -Wrestrict on chains of
  // std::string operator+ with literals.
  std::ostringstream command;
  command << "'" << FACADESLAM_BINARY << "' calibrate " << arguments << " > '" << out.string() << "' 2> '"
          << err.string() << "'";
  const int status = std::system(command.str().c_str());
  CommandResult result;
  if (status != -1 && WIFEXITED(status)) result.exit_code = WEXITSTATUS(status);
  result.out = read_file(out);
  result.err = read_file(err);
  return result;
}

std::string quoted(const std::filesystem::path& path) {
  std::ostringstream text;
  text << "'" << path.string() << "'";
  return text.str();
}

class CalibrateCommand : public ::testing::Test {
 protected:
  void SetUp() override {
    std::filesystem::create_directory(images_);
    test::write_views(images_, test::rendered_views(test::true_pinhole()), 10);
  }
  test::TempDir dir_;
  std::filesystem::path images_ = dir_ / "images";
};

TEST_F(CalibrateCommand, WritesALoadableCameraThePlotAndTheJson) {
  const auto out = dir_ / "cam" / "camera.yaml";
  const CommandResult r = calibrate(dir_, "--images " + quoted(images_) + " --board 9x6 --square 0.03 --out " +
                                              quoted(out) + " --json " + quoted(dir_ / "report.json"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_THAT(r.out, HasSubstr("RMS reprojection error"));
  EXPECT_THAT(r.out, HasSubstr("10 of 10 images used"));
  const Camera camera = load_camera(out);
  EXPECT_EQ(camera.model_name(), "pinhole");
  EXPECT_NEAR(camera.fx(), 520.0, 0.005 * 520.0);
  EXPECT_NEAR(camera.fy(), 516.0, 0.005 * 516.0);
  const cv::Mat plot = cv::imread((dir_ / "cam" / "camera_coverage.png").string());
  EXPECT_FALSE(plot.empty());
  const std::string json = read_file(dir_ / "report.json");
  EXPECT_THAT(json, HasSubstr("\"rms_px\""));
  EXPECT_THAT(json, HasSubstr("\"camera_file\""));
}

TEST_F(CalibrateCommand, AtanModelWithFixedAspectAndPlotPath) {
  const auto out = dir_ / "atan.yaml";
  const CommandResult r = calibrate(dir_, "--images " + quoted(images_) + " --board 9x6 --model atan --fix-aspect" +
                                              " --out " + quoted(out) + " --plot " + quoted(dir_ / "p.png"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const Camera camera = load_camera(out);
  EXPECT_EQ(camera.model_name(), "atan");
  EXPECT_EQ(camera.fx(), camera.fy());
  EXPECT_TRUE(std::filesystem::exists(dir_ / "p.png"));
  EXPECT_THAT(read_file(out), HasSubstr("fixed aspect ratio"));
}

TEST_F(CalibrateCommand, BadCommandLinesExitWithTwo) {
  const std::string base = "--images " + quoted(images_) + " --out " + quoted(dir_ / "c.yaml");
  for (const std::string bad : {"--board 9x", "--board 9x1", "--board nine", "--square 0", "--square -0.02",
                                "--model fisheye", "--max-blur 0"}) {
    const CommandResult r = calibrate(dir_, base + " " + bad);
    EXPECT_EQ(r.exit_code, 2) << bad << ": " << r.err;
    EXPECT_FALSE(std::filesystem::exists(dir_ / "c.yaml")) << bad;
  }
  EXPECT_THAT(calibrate(dir_, base + " --board 9x").err, HasSubstr("expected WxH"));
  EXPECT_EQ(calibrate(dir_, "--out " + quoted(dir_ / "c.yaml")).exit_code, 2);  // --images missing
  EXPECT_EQ(calibrate(dir_, "--images " + quoted(images_)).exit_code, 2);       // --out missing
}

TEST_F(CalibrateCommand, NoBoardInAnyImageExitsWithOne) {
  const auto empty_walls = dir_ / "walls";
  std::filesystem::create_directory(empty_walls);
  for (int i = 0; i < 3; ++i)
    test::write_png(empty_walls / ("wall" + std::to_string(i) + ".png"),
                    cv::Mat(240, 320, CV_8UC1, cv::Scalar(60 * i)));
  const CommandResult r = calibrate(dir_, "--images " + quoted(empty_walls) + " --out " + quoted(dir_ / "c.yaml"));
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_THAT(r.err, HasSubstr("no image of 3 contained a 9x6 board"));
  EXPECT_FALSE(std::filesystem::exists(dir_ / "c.yaml"));
}

TEST_F(CalibrateCommand, TooFewImagesExitsWithOne) {
  const auto two = dir_ / "two";
  std::filesystem::create_directory(two);
  test::write_views(two, test::rendered_views(test::true_pinhole()), 2);
  const CommandResult r = calibrate(dir_, "--images " + quoted(two) + " --out " + quoted(dir_ / "c.yaml"));
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_THAT(r.err, HasSubstr("only 2 of 2 images are usable, at least 3 are needed"));
}

TEST_F(CalibrateCommand, MixedImageSizesExitWithOne) {
  cv::Mat small;
  cv::resize(test::rendered_views(test::true_pinhole())[0], small, cv::Size(320, 240), 0, 0, cv::INTER_AREA);
  test::write_png(images_ / "view_05_small.png", small);
  const CommandResult r = calibrate(dir_, "--images " + quoted(images_) + " --out " + quoted(dir_ / "c.yaml"));
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_THAT(r.err,
              HasSubstr("view_05_small.png: image is 320x240 pixels, but the first image (view_00.png) is 640x480"));
}

TEST_F(CalibrateCommand, MissingFolderExitsWithOne) {
  const CommandResult r = calibrate(dir_, "--images " + quoted(dir_ / "nowhere") + " --out " + quoted(dir_ / "c.yaml"));
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_THAT(r.err, HasSubstr("nowhere: no such folder"));
}

}  // namespace
}  // namespace facadeslam
