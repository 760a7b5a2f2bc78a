// The whole initialiser on rendered sequences of a facade plane: KLT tracks,
// the parallax gate, the model choice and the recovered pose.
#include "slam/init/two_view_initialiser.hpp"

#include <cstdio>
#include <functional>

#include <gtest/gtest.h>

#include "core/image/image_pyramid.hpp"
#include "core/util/error.hpp"
#include "tests/slam/init/plane_sequence.hpp"
#include "tests/support/test_support.hpp"

namespace facadeslam {
namespace {

using test::error_of;

struct Outcome {
  int success_frame = -1;
  std::vector<InitStatus> statuses;
};

// Feeds frames 1..max_frames of the camera path `pose` until success.
Outcome run(TwoViewInitialiser& init, const test::TexturedPlane& plane, const std::function<SE3d(int)>& pose,
            int max_frames) {
  const cv::Mat frame0 = test::render(init.camera(), plane, pose(0));
  init.reset(frame0, ImagePyramid(frame0).level(0).corners, 0.0);
  Outcome outcome;
  for (int k = 1; k <= max_frames; ++k) {
    const InitStatus status = init.add_frame(test::render(init.camera(), plane, pose(k)));
    outcome.statuses.push_back(status);
    if (status == InitStatus::success) {
      outcome.success_frame = k;
      break;
    }
    if (status == InitStatus::too_few_tracks) break;
  }
  return outcome;
}

// Sliding in front of a facade: the initialiser must wait for parallax, then
// succeed with the homography and the true relative pose up to scale, with
// its points on the true plane.
void expect_initialises_on(const test::TexturedPlane& plane, const char* name) {
  TwoViewInitialiser init(test::plain_camera());
  const Outcome outcome = run(init, plane, test::sliding_camera, 30);
  ASSERT_GT(outcome.success_frame, 0) << "last: " << to_string(init.last_attempt().status) << " ("
                                      << init.last_attempt().reason << ")";
  const TwoViewResult& r = init.result();
  const SE3d truth = test::sliding_camera(outcome.success_frame) * test::sliding_camera(0).inverse();
  const double rotation_error = test::rotation_error_deg(r.T_c1_c0, truth);
  const double direction_error = test::direction_error_deg(r.T_c1_c0.translation(), truth.translation());
  // Points scaled to metres by |t| must lie on the plane n.p = d.
  const double scale = truth.translation().norm() / r.T_c1_c0.translation().norm();
  std::vector<double> plane_errors;
  for (const Eigen::Vector3d& p : r.points_c0)
    plane_errors.push_back(std::abs(plane.normal_c0().dot(p * scale) - plane.distance_c0()) / plane.distance_c0());
  std::printf(
      "[ measured ] %s: success at frame %d (baseline %.1f cm) with the %s, R_H %.3f, %zu points, median "
      "parallax %.2f deg, rotation error %.3f deg, direction error %.2f deg, plane distance error median "
      "%.2f%% p90 %.2f%%\n",
      name, outcome.success_frame, 100.0 * truth.translation().norm(), to_string(r.model), r.homography_ratio,
      r.points_c0.size(), r.median_parallax_deg, rotation_error, direction_error,
      100.0 * test::percentile(plane_errors, 0.5), 100.0 * test::percentile(plane_errors, 0.9));
  // Before success it only ever asked for more parallax (or refused a
  // not-yet-good geometry); the tracks never died.
  for (std::size_t i = 0; i + 1 < outcome.statuses.size(); ++i)
    EXPECT_TRUE(outcome.statuses[i] == InitStatus::need_more_parallax || outcome.statuses[i] == InitStatus::degenerate);
  EXPECT_GE(outcome.success_frame, 3);  // the first frames move a few pixels only
  EXPECT_EQ(r.model, TwoViewModel::homography);
  EXPECT_GT(r.points_c0.size(), 100u);
  EXPECT_GE(r.median_parallax_deg, 1.0);
  EXPECT_LT(rotation_error, 0.15);
  EXPECT_LT(direction_error, 3.0);
  EXPECT_LT(test::percentile(plane_errors, 0.5), 0.01);
  EXPECT_LT(test::percentile(plane_errors, 0.9), 0.03);
  EXPECT_FALSE(init.has_reference());
  EXPECT_EQ(init.reference_timestamp(), 0.0);
}

TEST(TwoViewInitialiser, InitialisesOnASyntheticFacadeTexture) {
  expect_initialises_on(test::facade_plane(test::synthetic_facade_texture(1000, 750, 7), 10.0, 0.0035),
                        "synthetic texture");
}

TEST(TwoViewInitialiser, InitialisesOnTheBuildingPhoto) {
  FACADESLAM_REQUIRE_SHARED_DATA("opencv-samples");
  cv::Mat photo = test::building_texture(test::shared_data_dir());
  ASSERT_FALSE(photo.empty()) << "cannot read opencv-samples/building.jpg";
  // 868x600 at 4 mm a pixel: a 3.5 x 2.4 m facade, one texture pixel per
  // image pixel at 2 m.
  expect_initialises_on(test::facade_plane(std::move(photo), 10.0, 0.004), "building.jpg");
}

// Turning on the spot in front of the facade: plenty of image motion, no
// parallax; it must never initialise and must say why.
TEST(TwoViewInitialiser, RotatingOnTheSpotNeverInitialises) {
  const auto plane = test::facade_plane(test::synthetic_facade_texture(1000, 750, 7), 10.0, 0.0035);
  const auto turning = [](int k) {
    return test::second_camera(Eigen::Vector3d::Zero(), {0.05 * test::kDeg * k, -0.25 * test::kDeg * k, 0.0});
  };
  TwoViewInitialiser init(test::plain_camera());
  const Outcome outcome = run(init, plane, turning, 20);
  EXPECT_EQ(outcome.success_frame, -1);
  ASSERT_EQ(outcome.statuses.size(), 20u);
  EXPECT_EQ(outcome.statuses.back(), InitStatus::degenerate);
  EXPECT_NE(init.last_attempt().reason.find("pure rotation"), std::string::npos) << init.last_attempt().reason;
  EXPECT_TRUE(init.has_reference());
  EXPECT_NE(error_of([&] { init.result(); }).find("degenerate"), std::string::npos);
}

// The view changes completely: the tracks die, the caller must restart, and
// the initialiser refuses frames until it does.
TEST(TwoViewInitialiser, TracksDyingAsksForARestart) {
  const Camera camera = test::plain_camera();
  TwoViewInitialiser init(camera);
  const cv::Mat frame0 = test::synthetic_facade_texture(640, 480, 1);
  init.reset(frame0, ImagePyramid(frame0).level(0).corners, 12.5);
  EXPECT_EQ(init.reference_timestamp(), 12.5);
  EXPECT_EQ(init.add_frame(test::synthetic_facade_texture(640, 480, 2)), InitStatus::too_few_tracks);
  EXPECT_FALSE(init.has_reference());
  EXPECT_NE(error_of([&] { init.add_frame(frame0); }).find("call reset() first"), std::string::npos);
  init.reset(frame0, ImagePyramid(frame0).level(0).corners, 13.0);
  EXPECT_EQ(init.add_frame(frame0), InitStatus::need_more_parallax);
  EXPECT_EQ(init.frames_since_reset(), 1);
}

TEST(TwoViewInitialiser, AddFrameBeforeResetThrows) {
  TwoViewInitialiser init(test::plain_camera());
  EXPECT_NE(error_of([&] { init.add_frame(cv::Mat(480, 640, CV_8UC1, cv::Scalar(0))); }).find("call reset() first"),
            std::string::npos);
  EXPECT_NE(error_of([&] { init.result(); }).find("result() requested"), std::string::npos);
}

TEST(TwoViewInitialiser, WrongImagesThrow) {
  TwoViewInitialiser init(test::plain_camera());
  const cv::Mat small(240, 320, CV_8UC1, cv::Scalar(0));
  EXPECT_NE(error_of([&] { init.reset(small, {}, 0.0); }).find("is 320x240 but the camera is 640x480"),
            std::string::npos);
  EXPECT_NE(error_of([&] { init.reset(cv::Mat(480, 640, CV_8UC3), {}, 0.0); }).find("8-bit single-channel"),
            std::string::npos);
  const cv::Mat grey(480, 640, CV_8UC1, cv::Scalar(0));
  init.reset(grey, {}, 0.0);
  EXPECT_NE(error_of([&] { init.add_frame(small); }).find("is 320x240"), std::string::npos);
}

TEST(TwoViewInitialiser, OptionsOutOfRangeThrow) {
  TwoViewOptions options;
  options.homography_ratio_threshold = 1.5;
  EXPECT_NE(
      error_of([&] { TwoViewInitialiser init(test::plain_camera(), options); }).find("homography_ratio_threshold"),
      std::string::npos);
  options = {};
  options.tracking.border_px = -1.0;
  EXPECT_NE(error_of([&] { TwoViewInitialiser init(test::plain_camera(), options); }).find("tracking.border_px"),
            std::string::npos);
}

}  // namespace
}  // namespace facadeslam
