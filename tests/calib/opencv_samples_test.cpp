// OpenCV's own sample boards (../shared/data/opencv-samples/left*.jpg, 9x6
// inner corners, 25 mm) against OpenCV's own calibration of them,
// left_intrinsics.yml (13 views, CALIB_FIX_ASPECT_RATIO with aspect 1:
// fx = fy = 535.916, cx = 342.283, cy = 235.571, RMS 0.393 px).
#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <string>

#include <gtest/gtest.h>
#include <opencv2/core.hpp>

#include "calib/calibrate.hpp"
#include "tests/support/test_support.hpp"

namespace facadeslam::calib {
namespace {

struct OpenCvReference {
  double fx, fy, cx, cy, rms;
  int frames;
};

OpenCvReference read_reference(const std::filesystem::path& file) {
  cv::FileStorage storage(file.string(), cv::FileStorage::READ);
  EXPECT_TRUE(storage.isOpened()) << file;
  cv::Mat K;
  storage["camera_matrix"] >> K;
  return {K.at<double>(0, 0),
          K.at<double>(1, 1),
          K.at<double>(0, 2),
          K.at<double>(1, 2),
          static_cast<double>(storage["avg_reprojection_error"]),
          static_cast<int>(storage["nframes"])};
}

// left01.jpg ... left14.jpg (not left.jpg, which shows no board) copied to
// a scratch folder, since the sample folder holds other images too.
void copy_left_boards(const std::filesystem::path& to) {
  const std::filesystem::path from = test::shared_data_dir() / "opencv-samples";
  // std::regex is avoided project-wide: GCC 12 warns inside <regex> at -O2
  // with sanitizers, and warnings are errors.
  const auto is_left_board = [](const std::string& name) {
    return name.size() == 10 && name.starts_with("left") && name.ends_with(".jpg") &&
           std::isdigit(static_cast<unsigned char>(name[4])) && std::isdigit(static_cast<unsigned char>(name[5]));
  };
  for (const auto& entry : std::filesystem::directory_iterator(from))
    if (is_left_board(entry.path().filename().string()))
      std::filesystem::copy_file(entry.path(), to / entry.path().filename());
}

CalibrationRequest left_request(const std::filesystem::path& folder, ModelKind model, bool fix_aspect) {
  CalibrationRequest request;
  request.images = folder;
  request.board = {9, 6, 0.025};
  request.model = model;
  request.fit.fix_aspect = fix_aspect;
  return request;
}

class OpenCvSamples : public ::testing::Test {
 protected:
  void SetUp() override {
    FACADESLAM_REQUIRE_SHARED_DATA("opencv-samples/left_intrinsics.yml");
    reference_ = read_reference(test::shared_data_dir() / "opencv-samples/left_intrinsics.yml");
    copy_left_boards(dir_.path());
  }
  void expect_matches_reference(const CalibrationRun& run) const {
    EXPECT_EQ(run.views.views.size(), static_cast<std::size_t>(reference_.frames));
    EXPECT_TRUE(run.views.rejected.empty());
    EXPECT_NEAR(run.result.camera.fx(), reference_.fx, 0.01 * reference_.fx);
    EXPECT_NEAR(run.result.camera.fy(), reference_.fy, 0.01 * reference_.fy);
    EXPECT_NEAR(run.result.camera.cx(), reference_.cx, 3.0);
    EXPECT_NEAR(run.result.camera.cy(), reference_.cy, 3.0);
    EXPECT_LT(run.result.rms_px, 0.5);
  }
  test::TempDir dir_;
  OpenCvReference reference_{};
};

TEST_F(OpenCvSamples, PinholeWithFreeAspectMatchesOpenCv) {
  const CalibrationRun run = run_calibration(left_request(dir_.path(), ModelKind::pinhole, false));
  expect_matches_reference(run);
}

TEST_F(OpenCvSamples, PinholeWithOpenCvsFlagsMatchesOpenCvClosely) {
  const CalibrationRun run = run_calibration(left_request(dir_.path(), ModelKind::pinhole, true));
  expect_matches_reference(run);
  EXPECT_EQ(run.result.camera.fx(), run.result.camera.fy());
  // The adaptive sub-pixel window (board_detection.hpp) fits the corners
  // better than the sample's fixed 11 px one, which spoils left02.jpg.
  EXPECT_LT(run.result.rms_px, reference_.rms);
  EXPECT_LT(*std::max_element(run.result.view_rms_px.begin(), run.result.view_rms_px.end()), 0.5);
}

TEST_F(OpenCvSamples, AtanModelFitsTheSameBoards) {
  const CalibrationRun run = run_calibration(left_request(dir_.path(), ModelKind::atan, false));
  ASSERT_EQ(run.result.camera.model_name(), "atan");
  ASSERT_TRUE(run.pinhole_rms_px.has_value());
  const auto& m = std::get<AtanCamera>(run.result.camera.model());
  // A clearly barrel-distorted lens (OpenCV: k1 = -0.27): w well above 0.
  EXPECT_GT(m.w, 0.5);
  EXPECT_LT(m.w, 1.2);
  EXPECT_NEAR(run.result.camera.cx(), reference_.cx, 5.0);
  EXPECT_NEAR(run.result.camera.cy(), reference_.cy, 5.0);
  EXPECT_LT(run.result.rms_px, 1.0);
  std::printf("ATAN on left*.jpg: fx %.3f fy %.3f cx %.3f cy %.3f w %.5f RMS %.4f px (pinhole %.4f px)\n",
              run.result.camera.fx(), run.result.camera.fy(), run.result.camera.cx(), run.result.camera.cy(), m.w,
              run.result.rms_px, *run.pinhole_rms_px);
}

}  // namespace
}  // namespace facadeslam::calib
