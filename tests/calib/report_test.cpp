// Outputs of a calibration: the printed report, the JSON report, the camera
// YAML (loadable by core/camera as is) and the coverage/residual PNG.
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <opencv2/imgcodecs.hpp>

#include "calib/calibration_report.hpp"
#include "calib/pinhole_calibration.hpp"
#include "calib/atan_calibration.hpp"
#include "calib/residual_plot.hpp"
#include "core/camera/camera_yaml.hpp"
#include "core/util/error.hpp"
#include "tests/calib/calib_test_scenes.hpp"
#include "tests/support/test_support.hpp"

namespace facadeslam::calib {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;

std::string read_file(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// A run built from projected corners (0.05 px noise) of the pinhole scene,
// with one rejected image, as run_calibration would return it.
CalibrationRun pinhole_run() {
  const Camera truth = test::true_pinhole();
  CalibrationRequest request;
  request.images = "boards";
  request.board = test::test_board();
  ViewCollection views;
  views.image_size = {640, 480};
  views.views = test::projected_views(truth, test::scene_poses(truth), 0.05);
  views.image_count = views.views.size() + 1;
  views.rejected.push_back({"boards/blurry.png", "blurred (board edges 7.0 px wide, more than 5.0 px)"});
  CalibrationResult result = calibrate_pinhole(views.views, views.image_size, request.board);
  CoverageFigures coverage = compute_coverage(views.views, views.image_size);
  return CalibrationRun{request, std::move(views), std::move(result), std::move(coverage), std::nullopt};
}

CalibrationRun atan_run() {
  CalibrationRun run = pinhole_run();
  run.request.model = ModelKind::atan;
  run.pinhole_rms_px = run.result.rms_px;
  run.result = calibrate_atan(run.views.views, run.result, run.request.board);
  return run;
}

TEST(CalibrationReport, TextListsFiguresAndRejections) {
  const CalibrationRun run = pinhole_run();
  const std::string text = format_report(run);
  EXPECT_THAT(text, HasSubstr("10 of 11 images used, board 9x6, square 0.03 m, model pinhole"));
  EXPECT_THAT(text, HasSubstr("blurry.png"));
  EXPECT_THAT(text, HasSubstr("blurred (board edges 7.0 px wide"));
  EXPECT_THAT(text, HasSubstr("projected_9.png"));
  EXPECT_THAT(text, HasSubstr("RMS reprojection error"));
  EXPECT_THAT(text, HasSubstr("k1 k2 p1 p2 k3"));
  EXPECT_THAT(text, HasSubstr("% of 8x6 cells"));
  EXPECT_THAT(text, Not(HasSubstr("pinhole RMS")));
  char rms[32];
  std::snprintf(rms, sizeof rms, "%.4f px", run.result.rms_px);
  EXPECT_THAT(text, HasSubstr(rms));
}

TEST(CalibrationReport, AtanTextShowsWAndThePinholeStart) {
  const std::string text = format_report(atan_run());
  EXPECT_THAT(text, HasSubstr("model atan"));
  EXPECT_THAT(text, HasSubstr("w (FOV)"));
  EXPECT_THAT(text, HasSubstr("pinhole RMS"));
  EXPECT_THAT(text, Not(HasSubstr("k1 k2 p1 p2 k3")));
}

TEST(CalibrationReport, PoorCoverageAddsANote) {
  CalibrationRun run = pinhole_run();
  EXPECT_THAT(format_report(run), Not(HasSubstr("note:")));
  run.coverage.cell_fraction = 0.2;
  EXPECT_THAT(format_report(run), HasSubstr("note: the corners cover little of the image"));
}

TEST(CalibrationReport, JsonHoldsEveryFigure) {
  const CalibrationRun run = pinhole_run();
  const Json json = report_json(run);
  const std::string text = json.dump();
  EXPECT_EQ(json.at("rms_px").get<double>(), run.result.rms_px);
  EXPECT_EQ(json.at("camera").at("fx").get<double>(), run.result.camera.fx());
  EXPECT_EQ(json.at("coverage").at("cell_fraction").get<double>(), run.coverage.cell_fraction);
  EXPECT_EQ(json.at("used_count").get<double>(), 10.0);
  EXPECT_EQ(json.at("image_count").get<double>(), 11.0);
  EXPECT_THAT(text, HasSubstr("\"distortion\""));
  EXPECT_THAT(text, HasSubstr("\"file\":\"blurry.png\""));
  EXPECT_THAT(text, HasSubstr("\"reason\":\"blurred"));
  EXPECT_THAT(text, HasSubstr("\"detector\":\"classic\""));
  EXPECT_FALSE(json.contains("pinhole_rms_px"));
  const Json atan = report_json(atan_run());
  EXPECT_TRUE(atan.at("camera").contains("w"));
  EXPECT_TRUE(atan.contains("pinhole_rms_px"));
}

TEST(CameraFile, LoadsBackTheSameCameraWithAProvenanceHeader) {
  test::TempDir dir;
  for (const CalibrationRun& run : {pinhole_run(), atan_run()}) {
    const auto path = dir / (run.result.camera.model_name() + ".yaml");
    write_camera_file(path, run);
    const Camera loaded = load_camera(path);
    EXPECT_EQ(loaded.model_name(), run.result.camera.model_name());
    EXPECT_EQ(loaded.width(), 640);
    EXPECT_EQ(loaded.fx(), run.result.camera.fx());
    EXPECT_EQ(loaded.cy(), run.result.camera.cy());
    const Eigen::Vector3d p(0.3, -0.2, 1.0);
    EXPECT_EQ(loaded.project(p), run.result.camera.project(p));
    const std::string text = read_file(path);
    EXPECT_THAT(text, HasSubstr("# Calibrated by `facadeslam calibrate`"));
    EXPECT_THAT(text, HasSubstr("# from 10 of 11 images in boards, board 9x6 inner corners"));
    EXPECT_THAT(text, HasSubstr("# RMS reprojection error"));
  }
  EXPECT_EQ(camera_file_header(pinhole_run()), camera_file_header(pinhole_run()));  // no date: reproducible
}

TEST(CameraFile, RefusesACameraThatCannotBeLoaded) {
  test::TempDir dir;
  CalibrationRun run = pinhole_run();
  PinholeRadTan folding = std::get<PinholeRadTan>(run.result.camera.model());
  folding.k1 = -1.5;  // folds back well inside the image
  folding.k2 = 0.0;
  folding.k3 = 0.0;
  run.result.camera = Camera(640, 480, folding);
  test::write_text(dir / "camera.yaml", "previous content\n");
  try {
    write_camera_file(dir / "camera.yaml", run);
    FAIL() << "expected an Error";
  } catch (const Error& e) {
    EXPECT_THAT(e.what(), HasSubstr("camera.yaml: the calibrated camera is not valid over the whole image"));
    EXPECT_THAT(e.what(), HasSubstr("--fix-k3"));
  }
  EXPECT_EQ(read_file(dir / "camera.yaml"), "previous content\n");
}

TEST(ResidualPlot, WritesAPngWithFrameAndPanel) {
  test::TempDir dir;
  const CalibrationRun run = pinhole_run();
  save_residual_plot(dir / "coverage.png", run.views, run.result, run.coverage);
  const cv::Mat image = cv::imread((dir / "coverage.png").string(), cv::IMREAD_COLOR);
  ASSERT_FALSE(image.empty());
  EXPECT_EQ(image.cols, 640 + 280);
  EXPECT_EQ(image.rows, 480);
  // The first view's first corner is drawn in its colour (BGR of series 0).
  const cv::Point2f c = run.views.views[0].corners[0];
  const cv::Vec3b pixel = image.at<cv::Vec3b>(cvRound(c.y + 0.5), cvRound(c.x + 0.5));
  EXPECT_NE(pixel, cv::Vec3b(255, 255, 255));
  EXPECT_THROW(save_residual_plot(dir / "coverage.jpg", run.views, run.result, run.coverage), Error);
}

TEST(ResidualPlot, SmallImagesAreEnlarged) {
  CalibrationRun run = pinhole_run();
  run.views.image_size = {320, 240};
  const cv::Mat image = render_residual_plot(run.views, run.result, run.coverage);
  EXPECT_EQ(image.cols, 640 + 280);
  EXPECT_EQ(image.rows, 480);
}

TEST(ResidualPlot, ScaleShrinksForLargeResiduals) {
  CalibrationRun run = pinhole_run();
  EXPECT_EQ(residual_scale(run.result, {640, 480}), 50.0);
  run.result.residuals[0][0] = Eigen::Vector2d(5.0, 0.0);  // 80 px limit / 5 px = 16 -> 10
  EXPECT_EQ(residual_scale(run.result, {640, 480}), 10.0);
}

}  // namespace
}  // namespace facadeslam::calib
