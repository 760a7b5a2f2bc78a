#include "core/patch/patch_search.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <ostream>
#include <vector>

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

#include "tests/core/patch/patch_source_at.hpp"
#include "tests/support/rendered_plane.hpp"
#include "core/patch/patch_warp.hpp"

namespace facadeslam::patch {
namespace {

// A bright blurred square on a dark background: FAST fires at its four corners only.
cv::Mat square_image(int brightness_offset = 0) {
  cv::Mat image(240, 320, CV_8UC1, cv::Scalar(60 + brightness_offset));
  image(cv::Rect(100, 80, 60, 60)).setTo(200 + brightness_offset);
  cv::GaussianBlur(image, image, cv::Size(0, 0), 0.8);
  return image;
}

// The level-0 corner of `pyramid` nearest to `near`.
Eigen::Vector2d nearest_corner(const ImagePyramid& pyramid, Eigen::Vector2d near) {
  const auto& corners = pyramid.level(0).corners;
  const auto it = std::min_element(corners.begin(), corners.end(), [&](const Corner& a, const Corner& b) {
    return (Eigen::Vector2d(a.x, a.y) - near).norm() < (Eigen::Vector2d(b.x, b.y) - near).norm();
  });
  return {it->x, it->y};
}

// Analytic image of Gaussian blobs (sigma 1-2 px), content moved by `shift`
// pixels: a sub-pixel shift without any resampling.
cv::Mat smooth_image(Eigen::Vector2d shift) {
  struct Blob {
    double x, y, amplitude, sigma;
  };
  std::vector<Blob> blobs;
  cv::RNG rng(4);
  for (int i = 0; i < 400; ++i)
    blobs.push_back(
        {rng.uniform(0.0, 160.0), rng.uniform(0.0, 120.0), rng.uniform(-80.0, 120.0), 0.7 * rng.uniform(1.5, 3.0)});
  cv::Mat image(120, 160, CV_8UC1);
  for (int y = 0; y < image.rows; ++y)
    for (int x = 0; x < image.cols; ++x) {
      const double u = x - shift.x(), v = y - shift.y();
      double f = 60.0;
      for (const Blob& b : blobs)
        f += b.amplitude * std::exp(-((u - b.x) * (u - b.x) + (v - b.y) * (v - b.y)) / (2 * b.sigma * b.sigma));
      image.at<std::uint8_t>(y, x) = cv::saturate_cast<std::uint8_t>(f + 0.5);
    }
  return image;
}

TEST(Zmssd, MatchesTheDefinitionAndIgnoresBrightnessOffsetAndContrast) {
  cv::Mat image(120, 160, CV_8UC1);
  cv::RNG rng(5);
  rng.fill(image, cv::RNG::UNIFORM, 0, 200);
  PyramidOptions options;
  options.detect_corners = false;
  const auto pyramid = std::make_shared<const ImagePyramid>(image, options);
  const PatchTemplate t = make_patch_template(source_at(pyramid, 0, {50, 40}), Eigen::Matrix2d::Identity());
  ASSERT_TRUE(t.valid());
  EXPECT_NEAR(zmssd_at(t, image, 50, 40), 0.0, 1e-5 * t.ssq);
  EXPECT_NEAR(zmssd_at(t, image + 40, 50, 40), 0.0, 1e-5 * t.ssq);  // brightness offset
  // Contrast: x0.6 (and rounding to 8 bits) still matches, far below the
  // ZMSSD of any other block.
  cv::Mat dimmer;
  image.convertTo(dimmer, CV_8U, 0.6, 10.0);
  EXPECT_LT(zmssd_at(t, dimmer, 50, 40), 0.02 * t.ssq);

  // Brute force at another place: the block's contrast scaled to the
  // template's (within x2 either way), then the SSD of the zero-mean values.
  const int x = 90, y = 70;
  double mean = 0;
  for (int j = -4; j < 4; ++j)
    for (int i = -4; i < 4; ++i) mean += image.at<std::uint8_t>(y + j, x + i);
  mean /= 64;
  double s_ii = 0;
  for (int j = -4; j < 4; ++j)
    for (int i = -4; i < 4; ++i) s_ii += std::pow(image.at<std::uint8_t>(y + j, x + i) - mean, 2);
  const double gain = std::clamp(std::sqrt(t.ssq / s_ii), 0.5, 2.0);
  double expected = 0;
  for (int j = 0; j < 8; ++j)
    for (int i = 0; i < 8; ++i) {
      const double d =
          gain * (image.at<std::uint8_t>(y + j - 4, x + i - 4) - mean) - t.values[static_cast<std::size_t>(j * 8 + i)];
      expected += d * d;
    }
  EXPECT_NEAR(zmssd_at(t, image, x, y), expected, 1e-4 * expected);
  EXPECT_NEAR(zmssd_at_subpixel(t, image, {x, y}), expected, 1e-4 * expected);
}

TEST(Zmssd, IsInfiniteWhenTheBlockLeavesTheImage) {
  cv::Mat image(120, 160, CV_8UC1, cv::Scalar(7));
  PatchTemplate t;
  EXPECT_TRUE(std::isinf(zmssd_at(t, image, 3, 50)));    // needs x - 4 >= 0
  EXPECT_TRUE(std::isinf(zmssd_at(t, image, 157, 50)));  // needs x + 3 <= 159
  EXPECT_FALSE(std::isinf(zmssd_at(t, image, 4, 4)));
  EXPECT_FALSE(std::isinf(zmssd_at(t, image, 156, 116)));
  EXPECT_TRUE(std::isinf(zmssd_at_subpixel(t, image, {156.5, 50})));  // bilinear needs floor(x) + 4 <= 159
  EXPECT_FALSE(std::isinf(zmssd_at_subpixel(t, image, {155.5, 50})));
  EXPECT_TRUE(std::isinf(zmssd_at_subpixel(t, image, {std::nan(""), 50})));
}

// The template at (80, 60) of the unshifted smooth image, unwarped.
PatchTemplate smooth_image_template() {
  PyramidOptions options;
  options.detect_corners = false;
  const auto pyramid = std::make_shared<const ImagePyramid>(smooth_image({0, 0}), options);
  return make_patch_template(source_at(pyramid, 0, {80, 60}), Eigen::Matrix2d::Identity());
}

TEST(RefineSubpixel, RecoversAKnownSubpixelShift) {
  const PatchTemplate t = smooth_image_template();
  ASSERT_TRUE(t.valid());
  const Eigen::Vector2d shifts[] = {{0.0, 0.0}, {0.5, 0.0}, {0.3, -0.4}, {-0.7, 0.2}, {1.2, 0.9}};
  for (const Eigen::Vector2d& shift : shifts) {
    const SubpixelResult r = refine_subpixel(t, smooth_image(shift) + 25, {80, 60});
    ASSERT_TRUE(r.converged) << shift.transpose();
    const double error = (r.pixel - Eigen::Vector2d(80, 60) - shift).norm();
    std::printf("[ shift %.1f %.1f ] error %.4f px after %d iterations, offset %.2f\n", shift.x(), shift.y(), error,
                r.iterations, r.brightness_offset);
    // Exact at an integer shift; otherwise bilinear resampling and 8-bit
    // rounding leave a few hundredths of a pixel.
    EXPECT_LT(error, shift.isZero() ? 1e-4 : 0.04) << shift.transpose();
    // The offset is the image block's mean against the zero-mean template.
    EXPECT_NEAR(r.brightness_offset, t.mean + 25.0, 1.0);
  }
}

// A cloud or an exposure change: the image at 0.6x the template's contrast.
TEST(RefineSubpixel, RecoversAShiftUnderAContrastChange) {
  const PatchTemplate t = smooth_image_template();
  ASSERT_TRUE(t.valid());
  for (const Eigen::Vector2d& shift : {Eigen::Vector2d(0.3, -0.4), Eigen::Vector2d(-0.7, 0.2)}) {
    cv::Mat dimmer;
    smooth_image(shift).convertTo(dimmer, CV_8U, 0.6, 30.0);
    const SubpixelResult r = refine_subpixel(t, dimmer, {80, 60});
    ASSERT_TRUE(r.converged) << shift.transpose();
    EXPECT_LT((r.pixel - Eigen::Vector2d(80, 60) - shift).norm(), 0.06) << shift.transpose();
    // Bilinear resampling lowers the sampled block's contrast a little more.
    EXPECT_NEAR(r.gain, 0.57, 0.05);
  }
}

TEST(RefineSubpixel, FailsWhenItCannotConvergeInTheAllowedIterations) {
  const auto pyramid = std::make_shared<const ImagePyramid>(smooth_image({0, 0}), PyramidOptions{{}, false});
  const PatchTemplate t = make_patch_template(source_at(pyramid, 0, {80, 60}), Eigen::Matrix2d::Identity());
  SearchOptions options;
  options.max_subpixel_iterations = 1;
  EXPECT_FALSE(refine_subpixel(t, smooth_image({0.8, 0.5}), {80, 60}, options).converged);
  options.max_subpixel_iterations = 10;
  EXPECT_TRUE(refine_subpixel(t, smooth_image({0.8, 0.5}), {80, 60}, options).converged);
  // Leaving the image is a failure too, and so is a start that is not a number.
  EXPECT_FALSE(refine_subpixel(t, smooth_image({0, 0}), {4, 60}, options).converged);
  EXPECT_FALSE(refine_subpixel(t, smooth_image({0, 0}), {std::nan(""), 60}, options).converged);
  EXPECT_FALSE(refine_subpixel(t, smooth_image({0, 0}), {80, 1e300}, options).converged);
}

// The smooth image has no FAST corners at all (detection off): PTAM's search
// finds nothing, the dense fallback finds the shifted patch near the
// prediction, scoring only pixels within its radius.
TEST(SearchPatch, DenseFallbackFindsAPatchWithoutACornerNearThePrediction) {
  const PatchTemplate t = smooth_image_template();
  ASSERT_TRUE(t.valid());
  const ImagePyramid shifted(smooth_image({2.0, -1.0}), PyramidOptions{{}, false});
  const Eigen::Vector2d truth(82.0, 59.0);
  SearchOptions ptam;
  EXPECT_EQ(search_patch(t, shifted, {80, 60}, 8.0, ptam).outcome, SearchOutcome::kNoCandidate);
  SearchOptions dense;
  dense.dense_radius = 3;
  const PatchSearchResult r = search_patch(t, shifted, {80, 60}, 8.0, dense);
  ASSERT_TRUE(r.found()) << to_string(r.outcome);
  EXPECT_LT((r.pixel_level0 - truth).norm(), 0.05);
  EXPECT_EQ(r.candidates, 49);  // the 7x7 pixels within 3 of the prediction
  // The search radius still bounds the dense window.
  const PatchSearchResult narrow = search_patch(t, shifted, {80, 60}, 1.0, dense);
  EXPECT_LE(narrow.candidates, 9);
}

class SquareSearch : public ::testing::Test {
 protected:
  void SetUp() override {
    pyramid = std::make_shared<const ImagePyramid>(square_image());
    corner = nearest_corner(*pyramid, {100, 80});
    ASSERT_LT((corner - Eigen::Vector2d(100, 80)).norm(), 2.0);
    tpl = make_patch_template(source_at(pyramid, 0, corner), Eigen::Matrix2d::Identity());
    ASSERT_TRUE(tpl.valid());
  }
  std::shared_ptr<const ImagePyramid> pyramid;
  Eigen::Vector2d corner;
  PatchTemplate tpl;
};

TEST_F(SquareSearch, FindsTheCornerFromAnOffPrediction) {
  const PatchSearchResult r = search_patch(tpl, *pyramid, corner + Eigen::Vector2d(3, 4), 8.0);
  ASSERT_TRUE(r.found()) << to_string(r.outcome);
  EXPECT_EQ(r.level, 0);
  EXPECT_LT((r.pixel_level0 - corner).norm(), 1e-3);
  EXPECT_NEAR(r.zmssd, 0.f, 1e-5f * tpl.ssq);
  EXPECT_GE(r.candidates, 1);
}

TEST_F(SquareSearch, IgnoresBrightnessChanges) {
  const ImagePyramid brighter(square_image(35));
  const PatchSearchResult r = search_patch(tpl, brighter, corner + Eigen::Vector2d(-4, 2), 8.0);
  ASSERT_TRUE(r.found()) << to_string(r.outcome);
  EXPECT_LT((r.pixel_level0 - corner).norm(), 0.02);
}

TEST_F(SquareSearch, NoCandidateWhenTheCornerIsOutsideTheRadius) {
  const PatchSearchResult r = search_patch(tpl, *pyramid, corner + Eigen::Vector2d(6, 8), 8.0);
  EXPECT_EQ(r.outcome, SearchOutcome::kNoCandidate);  // the corner is 10 px away
  EXPECT_EQ(r.candidates, 0);
  EXPECT_EQ(search_patch(tpl, *pyramid, corner + Eigen::Vector2d(6, 8), 10.5).outcome, SearchOutcome::kFound);
  EXPECT_EQ(search_patch(tpl, *pyramid, corner, -1.0).outcome, SearchOutcome::kNoCandidate);
}

TEST_F(SquareSearch, RejectsADifferentCorner) {
  // The opposite corner of the square is a mirrored pattern.
  const Eigen::Vector2d other = nearest_corner(*pyramid, {159, 139});
  const PatchSearchResult r = search_patch(tpl, *pyramid, other, 5.0);
  EXPECT_EQ(r.outcome, SearchOutcome::kScoreTooHigh);
  EXPECT_GT(r.zmssd, 64 * 500.f);
}

TEST_F(SquareSearch, RejectsAnInvalidTemplate) {
  PatchTemplate invalid = tpl;
  invalid.status = TemplateStatus::kTextureless;
  EXPECT_EQ(search_patch(invalid, *pyramid, corner, 8.0).outcome, SearchOutcome::kTemplateInvalid);
}

TEST_F(SquareSearch, CoarseOnlyReturnsTheCorner) {
  SearchOptions options;
  options.subpixel = false;
  const PatchSearchResult r = search_patch(tpl, *pyramid, corner + Eigen::Vector2d(2, 2), 5.0, options);
  ASSERT_TRUE(r.found());
  EXPECT_EQ(r.pixel_level0, corner);
  EXPECT_EQ(r.subpixel_iterations, 0);
}

TEST(SearchPatch, TexturelessSourceGivesNoTemplate) {
  const auto flat = std::make_shared<const ImagePyramid>(cv::Mat(240, 320, CV_8UC1, cv::Scalar(80)));
  const PatchTemplate t = make_patch_template(source_at(flat, 0, {100, 100}), Eigen::Matrix2d::Identity());
  EXPECT_EQ(t.status, TemplateStatus::kTextureless);
  EXPECT_EQ(search_patch(t, *flat, {100, 100}, 10.0).outcome, SearchOutcome::kTemplateInvalid);
}

// ---------------------------------------------------------------------------
// Rendered views of a textured plane.

struct SearchCase {
  int source_level;
  double distance;
  double roll_deg;
};

void PrintTo(const SearchCase& c, std::ostream* os) {
  *os << "source level " << c.source_level << ", distance " << c.distance << ", roll " << c.roll_deg;
}

class RenderedSearch : public ::testing::TestWithParam<SearchCase> {};

TEST_P(RenderedSearch, FindsTheTrueProjectionToSubpixelAccuracy) {
  const SearchCase c = GetParam();
  const Camera camera = test::test_camera();
  const test::RenderedPlane plane = test::make_plane();
  const auto source = std::make_shared<const ImagePyramid>(test::render(plane, camera, SE3d()));
  const SE3d T_c_w = test::view_pose(plane, c.distance, c.roll_deg * M_PI / 180.0, 0.0, 0.04, 0.02);
  const ImagePyramid current(test::render(plane, camera, T_c_w));
  const SearchImage frame(current);
  const auto points = test::points_from_source(plane, camera, source, c.source_level, 200);

  int same_with_index = 0;
  int tried = 0, found = 0, outside_found = 0, false_accepts = 0;
  std::vector<double> errors_level0, errors_level;
  int level = -1;
  for (const auto& p : points) {
    const Eigen::Vector2d truth = camera.project(T_c_w * p.geometry.p_w);
    if (!camera.in_image(truth, 40.0)) continue;
    const PatchTemplate t = make_patch_template(p.source, p.geometry, T_c_w, camera);
    if (!t.valid()) continue;
    level = t.search_level;
    ++tried;
    // Prediction 5 level-0 pixels off; radius covers it with 2 pixels to spare.
    const double scale = ImagePyramid::level_scale(t.search_level);
    const Eigen::Vector2d predicted = truth + Eigen::Vector2d(3, 4);
    const PatchSearchResult r = search_patch(t, current, predicted, 5.0 / scale + 2.0);
    // The row-indexed search must give exactly the same answer.
    const PatchSearchResult indexed = search_patch(t, frame, predicted, 5.0 / scale + 2.0);
    if (indexed.outcome == r.outcome && indexed.pixel_level0 == r.pixel_level0 && indexed.candidates == r.candidates)
      ++same_with_index;
    if (r.found()) {
      ++found;
      errors_level0.push_back((r.pixel_level0 - truth).norm());
      errors_level.push_back(errors_level0.back() / scale);
    }
    // The truth 3 search-level pixels beyond a radius of 3: never found there.
    const Eigen::Vector2d far = truth + Eigen::Vector2d(6, 0) * scale;
    const PatchSearchResult miss = search_patch(t, current, far, 3.0);
    if (miss.found() && (miss.pixel_level0 - truth).norm() < 2.0 * scale) ++outside_found;
    if (miss.found()) ++false_accepts;
  }
  ASSERT_GE(tried, 15);
  ASSERT_FALSE(errors_level0.empty());
  std::sort(errors_level0.begin(), errors_level0.end());
  std::sort(errors_level.begin(), errors_level.end());
  const double median = errors_level0[errors_level0.size() / 2];
  const double worst_level = errors_level.back();
  std::printf(
      "[ source level %d, distance %.1f, roll %.0f -> search level %d ] found %d / %d, level-0 error median "
      "%.3f max %.3f px (max %.3f search-level px); truth outside radius: %d false accepts\n",
      c.source_level, c.distance, c.roll_deg, level, found, tried, median, errors_level0.back(), worst_level,
      false_accepts);
  EXPECT_EQ(same_with_index, tried);
  EXPECT_GE(found, tried * 8 / 10);
  EXPECT_EQ(outside_found, 0);
  EXPECT_LE(false_accepts, tried / 20);  // other corners rarely pass the ZMSSD bound
  const double median_level = errors_level[errors_level.size() / 2];
  if (level == 0) {
    EXPECT_LT(errors_level0.back(), 0.1);  // every found point within 0.1 px
  } else {
    // Box-filtered pyramid levels of rotated views are not exact resamplings
    // of each other, so a coarse level is a little less exact, in its own pixels.
    EXPECT_LT(median_level, 0.05);
    EXPECT_LT(worst_level, 0.15);
  }
}

INSTANTIATE_TEST_SUITE_P(Views, RenderedSearch,
                         ::testing::Values(SearchCase{0, 2.0, 0}, SearchCase{0, 2.0, 20}, SearchCase{1, 4.0, 30},
                                           SearchCase{1, 2.0, 10}, SearchCase{1, 1.0, 25}, SearchCase{2, 2.0, 30}));

}  // namespace
}  // namespace facadeslam::patch
