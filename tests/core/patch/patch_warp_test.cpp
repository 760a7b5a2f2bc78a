#include "core/patch/patch_warp.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <ostream>
#include <vector>

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

#include "core/util/error.hpp"
#include "tests/core/patch/patch_source_at.hpp"
#include "tests/support/rendered_plane.hpp"
#include "core/patch/patch_search.hpp"

namespace facadeslam::patch {
namespace {

// A pyramid over random noise, so that every template pixel is distinct.
std::shared_ptr<const ImagePyramid> noise_pyramid(int seed = 3) {
  cv::Mat image(240, 320, CV_8UC1);
  cv::RNG rng(static_cast<std::uint64_t>(seed));
  rng.fill(image, cv::RNG::UNIFORM, 0, 256);
  PyramidOptions options;
  options.detect_corners = false;
  return std::make_shared<const ImagePyramid>(image, options);
}

float pixel(const ImagePyramid& p, int level, int x, int y) { return p.level(level).image.at<std::uint8_t>(y, x); }

TEST(ChooseSearchLevel, RoundsLog4OfTheDeterminantAndClampsToTheRange) {
  // Level switches at det = 2 * 4^l (round(log4 det)).
  EXPECT_EQ(choose_search_level(1.0), 0);
  EXPECT_EQ(choose_search_level(1.99), 0);
  EXPECT_EQ(choose_search_level(2.0), 1);
  EXPECT_EQ(choose_search_level(4.0), 1);
  EXPECT_EQ(choose_search_level(7.99), 1);
  EXPECT_EQ(choose_search_level(8.0), 2);
  EXPECT_EQ(choose_search_level(31.9), 2);
  EXPECT_EQ(choose_search_level(32.0), 3);
  EXPECT_EQ(choose_search_level(256.0), 3);  // det / 64 = 4: still accepted
  EXPECT_EQ(choose_search_level(0.25), 0);   // det = 1/4: still accepted
}

TEST(ChooseSearchLevel, RejectsScalesOutsideTheRangeAndBadDeterminants) {
  EXPECT_EQ(choose_search_level(257.0), -1);  // level 3 would magnify by > 2
  EXPECT_EQ(choose_search_level(0.24), -1);   // level 0 would minify by > 2
  EXPECT_EQ(choose_search_level(0.0), -1);
  EXPECT_EQ(choose_search_level(-1.0), -1);  // mirrored
  EXPECT_EQ(choose_search_level(std::numeric_limits<double>::quiet_NaN()), -1);
  EXPECT_EQ(choose_search_level(std::numeric_limits<double>::infinity()), -1);
}

TEST(ChooseSearchLevel, HonoursTheMaximumLevel) {
  TemplateOptions options;
  options.max_search_level = 1;
  EXPECT_EQ(choose_search_level(3.0, options), 1);
  EXPECT_EQ(choose_search_level(12.0, options), 1);   // det / 4 = 3 is within [1/4, 4]
  EXPECT_EQ(choose_search_level(20.0, options), -1);  // det / 4 = 5 is not, and level 2 is barred
  options.max_search_det = 8.0;
  EXPECT_EQ(choose_search_level(20.0, options), 1);
}

TEST(MakePatchTemplate, IdentityWarpCopiesTheSourcePixelsExactly) {
  const auto pyramid = noise_pyramid();
  const PatchTemplate t = make_patch_template(source_at(pyramid, 0, {100, 80}), Eigen::Matrix2d::Identity());
  ASSERT_TRUE(t.valid()) << to_string(t.status);
  EXPECT_EQ(t.search_level, 0);
  double sum = 0, ssq = 0;
  for (int j = 0; j < 8; ++j)
    for (int i = 0; i < 8; ++i) sum += pixel(*pyramid, 0, 100 - 4 + i, 80 - 4 + j);
  const double mean = sum / 64;
  for (int j = 0; j < 8; ++j)
    for (int i = 0; i < 8; ++i) {
      const int x = 100 - 4 + i, y = 80 - 4 + j;
      const std::size_t k = static_cast<std::size_t>(j * 8 + i);
      EXPECT_NEAR(t.values[k], pixel(*pyramid, 0, x, y) - mean, 1e-3);
      EXPECT_NEAR(t.grad_x[k], 0.5 * (pixel(*pyramid, 0, x + 1, y) - pixel(*pyramid, 0, x - 1, y)), 1e-4);
      EXPECT_NEAR(t.grad_y[k], 0.5 * (pixel(*pyramid, 0, x, y + 1) - pixel(*pyramid, 0, x, y - 1)), 1e-4);
      ssq += (pixel(*pyramid, 0, x, y) - mean) * (pixel(*pyramid, 0, x, y) - mean);
    }
  EXPECT_NEAR(t.mean, mean, 1e-3);
  EXPECT_NEAR(t.ssq, ssq, 1e-2 * ssq / 1000);
}

TEST(MakePatchTemplate, MagnifiedWarpIsSearchedOneLevelUpAtSourceResolution) {
  // A = 2 I: one source pixel covers 2x2 current level-0 pixels, i.e. exactly
  // one level-1 pixel, so the level-1 template is the source block itself.
  const auto pyramid = noise_pyramid();
  const PatchTemplate t = make_patch_template(source_at(pyramid, 1, {60, 50}), 2.0 * Eigen::Matrix2d::Identity());
  ASSERT_TRUE(t.valid());
  EXPECT_EQ(t.search_level, 1);
  EXPECT_TRUE(t.search_to_source.isApprox(Eigen::Matrix2d::Identity()));
  const float v00 = pixel(*pyramid, 1, 56, 46), v73 = pixel(*pyramid, 1, 63, 49);
  EXPECT_NEAR(t.values[0] - t.values[3 * 8 + 7], v00 - v73, 1e-3);
}

TEST(MakePatchTemplate, RotatedWarpRotatesThePatch) {
  // A rotates source steps by +90 degrees: right -> down, down -> left. The
  // template pixel at offset d samples the source at A^-1 d = (d.y, -d.x).
  const auto pyramid = noise_pyramid();
  Eigen::Matrix2d A;
  A << 0, -1, 1, 0;
  const PatchTemplate t = make_patch_template(source_at(pyramid, 0, {120, 90}), A);
  ASSERT_TRUE(t.valid());
  const float mean = t.mean;
  for (int j = 0; j < 8; ++j)
    for (int i = 0; i < 8; ++i) {
      const int dx = i - 4, dy = j - 4;
      EXPECT_NEAR(t.values[static_cast<std::size_t>(j * 8 + i)] + mean, pixel(*pyramid, 0, 120 + dy, 90 - dx), 1e-3);
    }
}

TEST(MakePatchTemplate, ReportsWhyATemplateCannotBeMade) {
  const auto pyramid = noise_pyramid();
  EXPECT_EQ(make_patch_template(source_at(pyramid, 0, {3, 80}), Eigen::Matrix2d::Identity()).status,
            TemplateStatus::kOutsideSource);
  EXPECT_EQ(make_patch_template(source_at(pyramid, 0, {100, 235}), Eigen::Matrix2d::Identity()).status,
            TemplateStatus::kOutsideSource);
  // Far inside at level 0, but at level 2 (80x60) the same spot is the edge.
  EXPECT_EQ(make_patch_template(source_at(pyramid, 2, {77, 30}), Eigen::Matrix2d::Identity()).status,
            TemplateStatus::kOutsideSource);
  Eigen::Matrix2d mirror;
  mirror << -1, 0, 0, 1;
  EXPECT_EQ(make_patch_template(source_at(pyramid, 0, {100, 80}), mirror).status, TemplateStatus::kBadWarp);
  EXPECT_EQ(make_patch_template(source_at(pyramid, 0, {100, 80}), 0.4 * Eigen::Matrix2d::Identity()).status,
            TemplateStatus::kBadWarp);

  cv::Mat flat(240, 320, CV_8UC1, cv::Scalar(90));
  flat.at<std::uint8_t>(80, 100) = 93;  // a little, not enough, texture
  const auto flat_pyramid = std::make_shared<const ImagePyramid>(flat);
  EXPECT_EQ(make_patch_template(source_at(flat_pyramid, 0, {100, 80}), Eigen::Matrix2d::Identity()).status,
            TemplateStatus::kTextureless);

  PatchSource missing;
  EXPECT_THROW(make_patch_template(missing, Eigen::Matrix2d::Identity()), Error);
}

TEST(MakePatchTemplate, PointBehindTheCameraHasNoTemplate) {
  const auto pyramid = noise_pyramid();
  PointGeometry g;
  g.p_w = {0, 0, -1};
  g.right_w = {0.01, 0, 0};
  g.down_w = {0, 0.01, 0};
  const PatchTemplate t = make_patch_template(source_at(pyramid, 0, {100, 80}), g, SE3d(), test::test_camera());
  EXPECT_EQ(t.status, TemplateStatus::kBehindCamera);
}

TEST(PatchWarp, SourceViewGivesTheLevelScaleAndDoublingTheDistanceHalvesIt) {
  const Camera camera = test::test_camera();
  const test::RenderedPlane plane{cv::Mat(), 0.004, 2.0};
  const Eigen::Vector2d xl(40, 30);
  const int level = 2;
  const Eigen::Vector2d x0 = ImagePyramid::level_to_level0(xl, level);
  const PointGeometry g = fronto_parallel_geometry(
      Eigen::Matrix3d::Identity(), Eigen::Vector3d::Zero(), camera.unproject(x0),
      camera.unproject(ImagePyramid::level_to_level0(xl + Eigen::Vector2d(1, 0), level)),
      camera.unproject(ImagePyramid::level_to_level0(xl + Eigen::Vector2d(0, 1), level)), plane.plane_depth);
  const Eigen::Matrix2d A_source = patch_warp(g.p_w, Eigen::Matrix3d::Identity(), g, camera);
  EXPECT_TRUE(A_source.isApprox(4.0 * Eigen::Matrix2d::Identity(), 1e-12)) << A_source;
  // From twice the distance (camera moved back along its axis).
  const Eigen::Vector3d t(0, 0, 2.0);
  const Eigen::Matrix2d A_far = patch_warp(g.p_w + t, Eigen::Matrix3d::Identity(), g, camera);
  EXPECT_TRUE(A_far.isApprox(2.0 * Eigen::Matrix2d::Identity(), 1e-12)) << A_far;
}

// ---------------------------------------------------------------------------
// Rendered views of a textured plane.

struct WarpCase {
  int source_level;
  double distance;  // current camera to plane; the source is at 2.0
  double roll_deg;
  double tilt_deg;
  int expected_level;
};

// Readable parameters in test output (gtest would otherwise dump raw bytes).
void PrintTo(const WarpCase& c, std::ostream* os) {
  *os << "source level " << c.source_level << ", distance " << c.distance << ", roll " << c.roll_deg << ", tilt "
      << c.tilt_deg << " -> level " << c.expected_level;
}

class RenderedWarp : public ::testing::TestWithParam<WarpCase> {};

TEST_P(RenderedWarp, TemplateMatchesTheCurrentViewAtTheTrueProjection) {
  const WarpCase c = GetParam();
  const Camera camera = test::test_camera();
  const test::RenderedPlane plane = test::make_plane();
  const auto source = std::make_shared<const ImagePyramid>(test::render(plane, camera, SE3d()));
  const double roll = c.roll_deg * M_PI / 180.0, tilt = c.tilt_deg * M_PI / 180.0;
  const SE3d T_c_w = test::view_pose(plane, c.distance, roll, tilt, 0.05, -0.03);
  const ImagePyramid current(test::render(plane, camera, T_c_w));
  // The same view warped as if there were no roll: the control that shows
  // the measurement can tell a right warp from a wrong one.
  const SE3d T_wrong = test::view_pose(plane, c.distance, 0.0, tilt, 0.05, -0.03);

  const auto points = test::points_from_source(plane, camera, source, c.source_level, 200);
  // The exact map from source-level pixels to current level-0 pixels (through
  // the plane), whose derivative the warp approximates.
  auto exact = [&](const Eigen::Vector2d& u) {
    const Eigen::Vector3d ray = camera.unproject(ImagePyramid::level_to_level0(u, c.source_level));
    return camera.project(T_c_w * Eigen::Vector3d(ray * plane.plane_depth));
  };
  int used = 0, textureless = 0, level_ok = 0, discriminative = 0, control_worse = 0;
  double worst_warp_error = 0.0;
  std::vector<double> per_pixel;
  for (const auto& p : points) {
    const Eigen::Vector2d truth = camera.project(T_c_w * p.geometry.p_w);
    if (!camera.in_image(truth, 40.0)) continue;
    const PatchTemplate t = make_patch_template(p.source, p.geometry, T_c_w, camera);
    // Weak FAST corners can fall under the variance floor once resampled.
    if (t.status == TemplateStatus::kTextureless) {
      ++textureless;
      continue;
    }
    ASSERT_TRUE(t.valid()) << to_string(t.status);
    ++used;

    const Eigen::Vector2d u = ImagePyramid::level0_to_level(p.source.pixel_level0, c.source_level);
    const double h = 1e-3;
    Eigen::Matrix2d numeric;
    numeric.col(0) = (exact(u + Eigen::Vector2d(h, 0)) - exact(u - Eigen::Vector2d(h, 0))) / (2 * h);
    numeric.col(1) = (exact(u + Eigen::Vector2d(0, h)) - exact(u - Eigen::Vector2d(0, h))) / (2 * h);
    worst_warp_error = std::max(worst_warp_error, (t.warp - numeric).norm() / numeric.norm());

    if (t.search_level == c.expected_level) ++level_ok;
    const double det_at_level = t.warp_det / std::pow(4.0, t.search_level);
    EXPECT_TRUE((det_at_level >= 0.5 || t.search_level == 0) && (det_at_level < 2.0 || t.search_level == 3))
        << "det(A) / 4^l = " << det_at_level << " at level " << t.search_level;

    const cv::Mat& image = current.level(t.search_level).image;
    const Eigen::Vector2d at = ImagePyramid::level0_to_level(truth, t.search_level);
    const double right = zmssd_at_subpixel(t, image, at);
    double wrong = std::numeric_limits<double>::infinity();
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx)
        if (dx || dy) wrong = std::min<double>(wrong, zmssd_at_subpixel(t, image, at + 3.0 * Eigen::Vector2d(dx, dy)));
    per_pixel.push_back(right / 64.0);
    if (wrong > 4.0 * right) ++discriminative;
    if (c.roll_deg != 0.0) {
      PatchTemplate unrolled = make_patch_template(p.source, p.geometry, T_wrong, camera);
      if (unrolled.valid() && unrolled.search_level == t.search_level &&
          zmssd_at_subpixel(unrolled, image, at) > 2.0 * right)
        ++control_worse;
    }
  }
  ASSERT_GE(used, 15) << "too few points visible in the current view";
  std::sort(per_pixel.begin(), per_pixel.end());
  const double median = per_pixel[per_pixel.size() / 2], p90 = per_pixel[per_pixel.size() * 9 / 10];
  std::printf(
      "[ level %d -> %d, distance %.1f, roll %.0f, tilt %.0f ] %d points (%d textureless), warp error %.1e, "
      "ZMSSD/px median %.1f p90 %.1f, discriminative %d, control worse %d\n",
      c.source_level, c.expected_level, c.distance, c.roll_deg, c.tilt_deg, used, textureless, worst_warp_error, median,
      p90, discriminative, control_worse);
  EXPECT_LE(textureless, (used + textureless) / 10);
  EXPECT_LT(worst_warp_error, 2e-3);
  if (c.tilt_deg == 0.0) {
    EXPECT_EQ(level_ok, used) << "search level differs from the expected one";
  } else {
    // A tilted plane changes scale across the view: most points, not all.
    EXPECT_GE(level_ok, used * 9 / 10);
  }
  EXPECT_LT(median, 15.0);  // grey levels^2 per pixel: RMS below ~4 grey levels
  EXPECT_LT(p90, 40.0);
  EXPECT_GE(discriminative, used * 9 / 10);
  if (c.roll_deg >= 15.0) {
    EXPECT_GE(control_worse, used * 8 / 10);
  }
}

INSTANTIATE_TEST_SUITE_P(DepthScaleRollAndTilt, RenderedWarp,
                         ::testing::Values(WarpCase{1, 2.0, 0, 0, 1}, WarpCase{1, 1.0, 0, 0, 2},
                                           WarpCase{1, 4.0, 0, 0, 0}, WarpCase{1, 2.0, 30, 0, 1},
                                           WarpCase{1, 1.0, 30, 0, 2}, WarpCase{1, 4.0, 30, 0, 0},
                                           WarpCase{1, 1.6, 15, 0, 1}, WarpCase{0, 2.0, 30, 0, 0},
                                           WarpCase{0, 1.0, 20, 0, 1}, WarpCase{2, 2.0, 30, 0, 2},
                                           WarpCase{2, 1.0, 30, 0, 3}, WarpCase{2, 4.0, 30, 0, 1},
                                           WarpCase{1, 2.0, 20, 25, 1}, WarpCase{0, 1.0, 30, 20, 1}));

}  // namespace
}  // namespace facadeslam::patch
