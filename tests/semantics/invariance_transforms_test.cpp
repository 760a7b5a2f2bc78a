// The invariance cases change images as documented, and the geometric ones
// move keypoints exactly as they move the picture: a bright dot ends up
// where the mapped keypoint says.
#include <cctype>
#include <cmath>
#include <numbers>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

#include "core/util/error.hpp"
#include "semantics/invariance/geometric_transforms.hpp"
#include "semantics/invariance/illuminant.hpp"
#include "semantics/invariance/invariance_cases.hpp"
#include "semantics/invariance/keypoint_mapping.hpp"
#include "semantics/invariance/photometric_transforms.hpp"
#include "tests/semantics/semantics_test_util.hpp"
#include "tests/support/test_support.hpp"

namespace facadeslam::semantics {
namespace {

using ::testing::HasSubstr;

// A black image with a small Gaussian blob (sigma 1.5) centred at `at`.
cv::Mat dot_image(cv::Size size, cv::Point2d at) {
  cv::Mat image(size, CV_8UC3, cv::Scalar::all(0));
  for (int y = 0; y < size.height; ++y)
    for (int x = 0; x < size.width; ++x) {
      const double r2 = (x - at.x) * (x - at.x) + (y - at.y) * (y - at.y);
      image.at<cv::Vec3b>(y, x) = cv::Vec3b::all(cv::saturate_cast<uchar>(250.0 * std::exp(-r2 / (2 * 1.5 * 1.5))));
    }
  return image;
}

// Intensity-weighted centroid of the whole image (the background is black).
cv::Point2d centroid(const cv::Mat& bgr) {
  cv::Mat grey;
  cv::cvtColor(bgr, grey, cv::COLOR_BGR2GRAY);
  const cv::Moments m = cv::moments(grey, false);
  return {m.m10 / m.m00, m.m01 / m.m00};
}

struct GeometricValue {
  InvarianceCase id;
  double value;
};

std::string case_label(const ::testing::TestParamInfo<GeometricValue>& info) {
  std::string name(case_info(info.param.id).name);
  name.append("_").append(std::to_string(static_cast<int>(std::lround(info.param.value * 100))));
  for (char& c : name)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  return name;
}

class GeometricCase : public ::testing::TestWithParam<GeometricValue> {};

TEST_P(GeometricCase, BrightDotLandsWhereTheMappedKeypointSays) {
  const GeometricValue g = GetParam();
  const cv::Point2d dot(53.0, 41.0);  // off-centre, so that rotation and tilt move it
  const TransformedImage changed = apply_case(g.id, g.value, dot_image({160, 120}, dot));
  const cv::Point2d expected = map_point(changed.point_map, dot);
  const cv::Point2d found = centroid(changed.bgr);
  EXPECT_NEAR(found.x, expected.x, 0.25);
  EXPECT_NEAR(found.y, expected.y, 0.25);
  // The dot lands in the part of the canvas that shows the original.
  EXPECT_EQ(changed.valid.at<uchar>(cvRound(expected.y), cvRound(expected.x)), 255);
  EXPECT_EQ(changed.valid.size(), changed.bgr.size());
}

INSTANTIATE_TEST_SUITE_P(
    EveryGeometricCase, GeometricCase,
    ::testing::Values(GeometricValue{InvarianceCase::rotation, 30}, GeometricValue{InvarianceCase::rotation, 90},
                      GeometricValue{InvarianceCase::rotation, -45}, GeometricValue{InvarianceCase::rotation, 180},
                      GeometricValue{InvarianceCase::resize, 0.5}, GeometricValue{InvarianceCase::resize, 0.75},
                      GeometricValue{InvarianceCase::resize, 1.7}, GeometricValue{InvarianceCase::affine, 1},
                      GeometricValue{InvarianceCase::affine, 2}, GeometricValue{InvarianceCase::affine, 3},
                      GeometricValue{InvarianceCase::affine, 4}, GeometricValue{InvarianceCase::affine, 5},
                      GeometricValue{InvarianceCase::affine, 6}, GeometricValue{InvarianceCase::affine, 7},
                      GeometricValue{InvarianceCase::affine, 8}, GeometricValue{InvarianceCase::affine, 9},
                      GeometricValue{InvarianceCase::affine, 10}),
    case_label);

TEST(GeometricCase, IdentityValuesKeepTheImage) {
  const cv::Mat image = test_util::textured_image({97, 71}, 4);
  for (const GeometricValue g : {GeometricValue{InvarianceCase::rotation, 0}, GeometricValue{InvarianceCase::resize, 1},
                                 GeometricValue{InvarianceCase::affine, 0}}) {
    const TransformedImage same = apply_case(g.id, g.value, image);
    ASSERT_EQ(same.bgr.size(), image.size()) << case_info(g.id).name;
    EXPECT_EQ(cv::norm(same.bgr, image, cv::NORM_INF), 0.0) << case_info(g.id).name;
    EXPECT_EQ(cv::countNonZero(same.valid), image.cols * image.rows) << case_info(g.id).name;
    EXPECT_NEAR(cv::norm(cv::Mat(same.point_map), cv::Mat(cv::Matx23d(1, 0, 0, 0, 1, 0))), 0.0, 1e-12);
  }
}

TEST(Rotation, CanvasHoldsTheWholeRotatedImage) {
  const cv::Mat image = test_util::textured_image({100, 60}, 5);
  const TransformedImage quarter = rotate_image(image, 90);
  EXPECT_EQ(quarter.bgr.size(), cv::Size(60, 100));
  EXPECT_EQ(cv::countNonZero(quarter.valid), 60 * 100);
  // Counter-clockwise as seen: the top-right corner goes to the top-left.
  const cv::Point2d top_right = map_point(quarter.point_map, {99, 0});
  EXPECT_NEAR(top_right.x, 0.0, 1e-9);
  EXPECT_NEAR(top_right.y, 0.0, 1e-9);
  EXPECT_EQ(quarter.bgr.at<cv::Vec3b>(0, 0), image.at<cv::Vec3b>(0, 99));

  const TransformedImage diagonal = rotate_image(cv::Mat(100, 100, CV_8UC3, cv::Scalar::all(200)), 45);
  EXPECT_EQ(diagonal.bgr.cols, 142);  // 100 sqrt 2, rounded up
  EXPECT_EQ(diagonal.bgr.rows, 142);
  EXPECT_EQ(diagonal.valid.at<uchar>(0, 0), 0);  // corners are fill
  EXPECT_EQ(diagonal.bgr.at<cv::Vec3b>(0, 0), cv::Vec3b(0, 0, 0));
  EXPECT_EQ(diagonal.valid.at<uchar>(71, 71), 255);
}

TEST(Resize, ImageAndMapScaleTogether) {
  const TransformedImage half = resize_image(test_util::textured_image({101, 60}, 6), 0.5);
  EXPECT_EQ(half.bgr.size(), cv::Size(51, 30));                         // round(50.5) = 51
  const cv::Point2d corner = map_point(half.point_map, {100.5, 59.5});  // bottom-right edge of the image
  EXPECT_NEAR(corner.x, 50.5, 1e-9);
  EXPECT_NEAR(corner.y, 29.5, 1e-9);
}

TEST(AffineCases, AreTiltsOfTheDocumentedViewpointAngles) {
  const double degree = std::numbers::pi / 180.0;
  const double viewpoints[] = {20, 30, 40, 50, 60};
  for (int k = 1; k <= kAffineCaseCount; ++k) {
    const cv::Matx22d a = affine_case_matrix(k);
    const double cos_theta = std::cos(viewpoints[(k - 1) % 5] * degree);
    EXPECT_NEAR(cv::determinant(a), cos_theta, 1e-12) << "case " << k;  // area foreshortened by cos theta
    EXPECT_NEAR(a(0, 1), a(1, 0), 1e-12) << "case " << k;               // a pure tilt, no rotation
    // The direction phi is kept, the one across it shrinks by cos theta.
    const cv::Vec2d along = k <= 5 ? cv::Vec2d(1, 0) : cv::Vec2d(1, 1) / std::sqrt(2.0);
    const cv::Vec2d across(-along[1], along[0]);
    EXPECT_NEAR(cv::norm(a * along - cos_theta * along), 0.0, 1e-12) << "case " << k;
    EXPECT_NEAR(cv::norm(a * across - across), 0.0, 1e-12) << "case " << k;
  }
  EXPECT_EQ(affine_case_matrix(0), cv::Matx22d::eye());
  EXPECT_EQ(affine_case_description(7), "tilt 30 deg along 45 deg");
  EXPECT_THAT(test::error_of([] { affine_case_matrix(11); }), HasSubstr("affine case 11"));
  EXPECT_THAT(test::error_of([] { affine_case_matrix(-1); }), HasSubstr("1..10"));
}

TEST(Photometric, IntensityScaleAndShiftChangeEveryChannelAndSaturate) {
  const cv::Mat image(2, 2, CV_8UC3, cv::Scalar(100, 40, 200));
  EXPECT_EQ(scale_intensity(image, 1.5).at<cv::Vec3b>(1, 1), cv::Vec3b(150, 60, 255));
  EXPECT_EQ(scale_intensity(image, 0.5).at<cv::Vec3b>(0, 0), cv::Vec3b(50, 20, 100));
  EXPECT_EQ(shift_intensity(image, -50).at<cv::Vec3b>(0, 1), cv::Vec3b(50, 0, 150));
  EXPECT_EQ(shift_intensity(image, 60).at<cv::Vec3b>(1, 0), cv::Vec3b(160, 100, 255));
}

TEST(Photometric, BlurOfKernelOneIsTheIdentityAndLargerKernelsSmoothMore) {
  const cv::Mat image = test_util::textured_image({80, 60}, 7);
  EXPECT_EQ(cv::norm(blur_image(image, 1), image, cv::NORM_INF), 0.0);
  const double change3 = cv::norm(blur_image(image, 3), image, cv::NORM_L1);
  const double change9 = cv::norm(blur_image(image, 9), image, cv::NORM_L1);
  EXPECT_GT(change3, 0.0);
  EXPECT_GT(change9, change3);
}

TEST(Photometric, LowerJpegQualityChangesTheImageMore) {
  const cv::Mat image = test_util::textured_image({80, 64}, 8);
  const double at100 = cv::norm(jpeg_round_trip(image, 100), image, cv::NORM_L2);
  const double at90 = cv::norm(jpeg_round_trip(image, 90), image, cv::NORM_L2);
  const double at10 = cv::norm(jpeg_round_trip(image, 10), image, cv::NORM_L2);
  EXPECT_GT(at100, 0.0);  // JPEG is lossy even at 100 (colour subsampling)
  EXPECT_GT(at90, at100);
  EXPECT_GT(at10, 1.3 * at90);
  EXPECT_EQ(jpeg_round_trip(image, 50).size(), image.size());
}

TEST(Photometric, CasesKeepTheGeometry) {
  const cv::Mat image = test_util::textured_image({64, 48}, 9);
  for (const GeometricValue g :
       {GeometricValue{InvarianceCase::blur, 5}, GeometricValue{InvarianceCase::intensity_scale, 2},
        GeometricValue{InvarianceCase::intensity_shift, -30}, GeometricValue{InvarianceCase::temperature, 3000},
        GeometricValue{InvarianceCase::jpeg, 30}}) {
    const TransformedImage changed = apply_case(g.id, g.value, image);
    EXPECT_EQ(changed.bgr.size(), image.size());
    EXPECT_EQ(cv::countNonZero(changed.valid), 64 * 48);
    EXPECT_EQ(map_point(changed.point_map, {10.5, 20.25}), cv::Point2d(10.5, 20.25));
    EXPECT_GT(cv::norm(changed.bgr, image, cv::NORM_L1), 0.0) << case_info(g.id).name;
  }
}

TEST(Illuminant, GainsAreOneAtTheReferenceTemperature) {
  const cv::Vec3d g = illuminant_gains_bgr(kReferenceKelvin);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(g[c], 1.0, 1e-12);
}

TEST(Illuminant, WarmLightIsRedderAndColdLightBluer) {
  const cv::Vec3d warm = illuminant_gains_bgr(3000), cold = illuminant_gains_bgr(10000);
  EXPECT_DOUBLE_EQ(warm[1], 1.0);    // green keeps the brightness
  EXPECT_NEAR(warm[2], 1.24, 0.01);  // the header's documented values
  EXPECT_NEAR(warm[0], 0.68, 0.01);
  EXPECT_NEAR(cold[2], 0.94, 0.01);
  EXPECT_NEAR(cold[0], 1.11, 0.01);
  // Red over blue falls steadily as the light gets hotter.
  double previous = HUGE_VAL;
  for (const double k : {2000.0, 3000.0, 4000.0, 5000.0, 6500.0, 8000.0, 12000.0}) {
    const cv::Vec3d g = illuminant_gains_bgr(k);
    EXPECT_LT(g[2] / g[0], previous) << k << " K";
    previous = g[2] / g[0];
  }
}

TEST(Illuminant, ImageChannelsAreMultipliedByTheGains) {
  const cv::Mat grey(3, 3, CV_8UC3, cv::Scalar::all(100));
  const cv::Vec3d g = illuminant_gains_bgr(3000);
  const cv::Vec3b changed = change_illuminant(grey, 3000).at<cv::Vec3b>(1, 1);
  for (int c = 0; c < 3; ++c) EXPECT_EQ(changed[c], cv::saturate_cast<uchar>(100 * g[c])) << "channel " << c;
  EXPECT_THAT(test::error_of([] { illuminant_gains_bgr(100); }), HasSubstr("between 500 and 100000 K"));
}

TEST(CaseValues, DefaultsAreValidAndHoldTheIdentity) {
  for (const InvarianceCaseInfo& info : kInvarianceCases) {
    const std::vector<double> values = default_case_values(info.id);
    EXPECT_NO_THROW(check_case_values(info.id, values)) << info.name;
    EXPECT_GE(values.size(), 7u) << info.name;
  }
}

TEST(CaseValues, BadValuesAreRejectedNamingTheCaseAndTheExpectation) {
  struct Bad {
    InvarianceCase id;
    std::vector<double> values;
    const char* mention;
  };
  const Bad bad[] = {
      {InvarianceCase::blur, {3, 4}, "blur: 4 is not a valid kernel size (px) (expected an odd integer from 1 to 99)"},
      {InvarianceCase::blur, {0}, "blur: 0"},
      {InvarianceCase::rotation, {std::nan("")}, "rotation: nan"},
      {InvarianceCase::resize, {0}, "resize: 0 is not a valid scale factor (expected a number from 0.1 to 4)"},
      {InvarianceCase::affine, {11}, "affine: 11"},
      {InvarianceCase::affine, {2.5}, "affine: 2.5"},
      {InvarianceCase::intensity_scale, {-1}, "intensity-scale: -1"},
      {InvarianceCase::intensity_shift, {300}, "intensity-shift: 300"},
      {InvarianceCase::temperature, {0}, "temperature: 0"},
      {InvarianceCase::jpeg, {101}, "jpeg: 101 is not a valid quality (expected an integer from 0 to 100)"},
      {InvarianceCase::jpeg, {}, "jpeg: expected at least one value"},
  };
  for (const Bad& b : bad)
    EXPECT_THAT(test::error_of([&] { check_case_values(b.id, b.values); }), HasSubstr(b.mention));
}

TEST(CaseValues, UnknownCaseNameListsTheKnownOnes) {
  EXPECT_EQ(case_by_name("intensity-shift"), InvarianceCase::intensity_shift);
  EXPECT_THAT(test::error_of([] { case_by_name("shear"); }),
              HasSubstr("unknown invariance case 'shear' (expected one of blur, rotation, resize, affine"));
}

TEST(KeypointMapping, KeepsKeypointsWhoseMarginSquareIsInsideTheImage) {
  const TransformedImage same = same_geometry(cv::Mat(80, 100, CV_8UC3, cv::Scalar::all(50)));
  const std::vector<cv::Point2f> points{{5, 5}, {50, 40}, {84, 64}, {85, 64}, {84, 65}, {15, 15}, {14, 15}};
  const KeypointPairs pairs = map_keypoints(points, same, 15);
  EXPECT_EQ(pairs.reference, (std::vector<int>{1, 2, 5}));
  ASSERT_EQ(pairs.moved.size(), 3u);
  EXPECT_EQ(pairs.moved[1], cv::Point2f(84, 64));
  EXPECT_EQ(map_keypoints(points, same, 0).reference.size(), points.size());
}

TEST(KeypointMapping, DropsKeypointsWhosePatchWouldCoverTheFill) {
  const TransformedImage turned = rotate_image(cv::Mat(100, 100, CV_8UC3, cv::Scalar::all(200)), 45);
  // (15, 15) has its 15-pixel margin inside the original, but after the turn
  // the image edges run diagonally 15.5 pixels away: the corners of its
  // 31 x 31 square (21 pixels out) reach into the black fill. (30, 50) is
  // 30 pixels from every edge and stays.
  const std::vector<cv::Point2f> points{{49.5f, 49.5f}, {15, 15}, {30, 50}};
  const KeypointPairs pairs = map_keypoints(points, turned, 15);
  EXPECT_EQ(pairs.reference, (std::vector<int>{0, 2}));
  EXPECT_NEAR(pairs.moved[0].x, (turned.bgr.cols - 1) / 2.0, 1e-4);  // the centre stays the centre
  EXPECT_NEAR(pairs.moved[0].y, (turned.bgr.rows - 1) / 2.0, 1e-4);
  EXPECT_THAT(test::error_of([&] { map_keypoints(points, turned, -1); }), HasSubstr("margin"));
}

}  // namespace
}  // namespace facadeslam::semantics
