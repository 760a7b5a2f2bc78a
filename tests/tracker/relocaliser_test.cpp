#include "tracker/relocaliser.hpp"

#include <cmath>

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

#include "tests/support/random_rectangles.hpp"

namespace facadeslam {
namespace {

constexpr double kDeg = M_PI / 180.0;

Camera test_camera() { return Camera(640, 480, PinholeRadTan{500, 500, 319.5, 239.5, 0, 0, 0, 0, 0}); }

cv::Mat random_scene(int seed) {
  cv::Mat img(480, 640, CV_8UC3, cv::Scalar(110, 120, 130));
  cv::RNG rng(static_cast<std::uint64_t>(seed));
  test::paint_random_rectangles(img, rng, 250, -40, 10, 90);
  return img;
}

// The image a camera rotated by R_cur_kf about its centre sees: x_cur = K R K^-1 x_kf.
cv::Mat rotate_view(const cv::Mat& image, const SO3d& R_cur_kf, const Camera& camera) {
  const Eigen::Matrix3d K = camera.pinhole_matrix();
  const Eigen::Matrix3d H = K * R_cur_kf.matrix() * K.inverse();
  cv::Mat Hcv(3, 3, CV_64F);
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) Hcv.at<double>(r, c) = H(r, c);
  cv::Mat out;
  cv::warpPerspective(image, out, Hcv, image.size(), cv::INTER_LINEAR, cv::BORDER_REPLICATE);
  return out;
}

// A keyframe of `image` at `T_c_w`, as the map would snapshot it.
KeyFrameSnapshot keyframe_from(const cv::Mat& image, KeyFrame::Id id, const SE3d& T_c_w = SE3d()) {
  auto pyramid = std::make_shared<const ImagePyramid>(image, PyramidOptions{.fast = {}, .detect_corners = false});
  return {std::make_shared<const KeyFrame>(id, Frame{0, 0.0, image, {}, pyramid}, T_c_w), T_c_w};
}

TEST(KeyFrame, BuildsItsSmallBlurryImageFromItsPyramid) {
  const cv::Mat image = random_scene(3);
  const KeyFrameSnapshot kf = keyframe_from(image, 0);
  const cv::Mat expected = make_small_blurry_image(*kf.keyframe->pyramid());
  ASSERT_EQ(kf.keyframe->small_blurred().size(), expected.size());
  EXPECT_EQ(cv::norm(kf.keyframe->small_blurred(), expected, cv::NORM_INF), 0.0);
}

TEST(SmallBlurryImage, IsSixteenTimesSmallerAndZeroMean) {
  const ImagePyramid pyramid(random_scene(1));
  const cv::Mat sbi = make_small_blurry_image(pyramid);
  EXPECT_EQ(sbi.size(), cv::Size(40, 30));
  EXPECT_EQ(sbi.type(), CV_32FC1);
  EXPECT_NEAR(cv::mean(sbi)[0], 0.0, 1e-3);
}

TEST(SmallBlurryImage, AlignmentRecoversAShift) {
  const cv::Mat image = random_scene(2);
  cv::Mat shifted;
  // Content moves 32 px right: current(x) = reference(x - 32) -> t = -2 SBI px.
  const cv::Mat M = (cv::Mat_<double>(2, 3) << 1, 0, 32, 0, 1, 0);
  cv::warpAffine(image, shifted, M, image.size(), cv::INTER_LINEAR, cv::BORDER_REPLICATE);
  const cv::Mat a = make_small_blurry_image(ImagePyramid(image));
  const cv::Mat b = make_small_blurry_image(ImagePyramid(shifted));
  const Se2Motion motion = align_small_blurry_images(a, b);
  EXPECT_NEAR(motion.t.x(), -2.0, 0.15);
  EXPECT_NEAR(motion.t.y(), 0.0, 0.15);
  EXPECT_NEAR(motion.theta, 0.0, 0.01);
}

TEST(Relocaliser, PicksTheRightKeyframeAndRecoversTheRotation) {
  const Camera camera = test_camera();
  std::vector<KeyFrameSnapshot> keyframes;
  for (int k = 0; k < 3; ++k)
    keyframes.push_back(
        keyframe_from(random_scene(10 + k), static_cast<KeyFrame::Id>(k),
                      SE3d::exp((Eigen::Matrix<double, 6, 1>() << k, 0.5 * k, 0, 0, 0.1 * k, 0).finished())));
  const SO3d R_true = SO3d::exp(Eigen::Vector3d(1.5 * kDeg, -2.5 * kDeg, 2.0 * kDeg));
  const cv::Mat current = rotate_view(random_scene(11), R_true, camera);
  const cv::Mat sbi = make_small_blurry_image(ImagePyramid(current));

  const auto candidate = find_relocalisation_candidate(sbi, keyframes, camera);
  ASSERT_TRUE(candidate.has_value());
  EXPECT_EQ(candidate->keyframe->id(), 1u);
  const SE3d T_c_kf = candidate->T_c_w * keyframes[1].T_c_w.inverse();
  EXPECT_LT(T_c_kf.translation().norm(), 1e-9) << "relocalisation proposes a rotation about the keyframe centre";
  const double error_deg = (T_c_kf.so3() * R_true.inverse()).log().norm() / kDeg;
  EXPECT_LT(error_deg, 0.5) << "rotation error " << error_deg << " deg";
}

TEST(Relocaliser, RejectsWhenNothingIsSimilarEnough) {
  const Camera camera = test_camera();
  const std::vector<KeyFrameSnapshot> keyframes{keyframe_from(random_scene(20), 0)};
  const cv::Mat sbi = make_small_blurry_image(ImagePyramid(random_scene(21)));
  RelocaliserOptions strict;
  strict.max_rms_difference = 1.0;
  EXPECT_FALSE(find_relocalisation_candidate(sbi, keyframes, camera, strict).has_value());
  EXPECT_FALSE(find_relocalisation_candidate(sbi, {}, camera).has_value());
}

}  // namespace
}  // namespace facadeslam
