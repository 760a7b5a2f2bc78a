#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include <opencv2/imgproc.hpp>

#include "semantics/descriptor/colour_invariants.hpp"
#include "semantics/descriptor/extraction.hpp"
#include "semantics/descriptor/genome.hpp"
#include "semantics/descriptor/edge_distance.hpp"
#include "semantics/descriptor/modules/edge_distance_module.hpp"
#include "semantics/descriptor/modules/gradient_angles_module.hpp"
#include "semantics/descriptor/modules/plane_statistics.hpp"
#include "semantics/descriptor/modules/position_module.hpp"
#include "semantics/descriptor/modules/singular_values_module.hpp"
#include "tests/semantics/semantics_test_util.hpp"

namespace facadeslam::semantics {
namespace {

using test_util::image_with_plane;
using test_util::patch_from;

TEST(PlaneStatistics, ConstantPatchIsExact) {
  const MeanStd s = patch_mean_std(view_of(cv::Mat(15, 15, CV_32F, cv::Scalar(0.3f))));
  EXPECT_EQ(s.mean, static_cast<double>(0.3f));
  EXPECT_EQ(s.std, 0.0);
}

TEST(PlaneStatistics, TwoValuedPatchMatchesClosedForm) {
  // 21 x 21 with the 10 top rows at 0.2 and the 11 others at 0.6.
  const cv::Mat patch = patch_from(10, [](double, double y) { return y < 0 ? 0.2 : 0.6; });
  const double p = 10.0 / 21.0;  // share of 0.2
  const double mean = p * 0.2 + (1 - p) * 0.6;
  const double sigma = 0.4 * std::sqrt(p * (1 - p));  // Bernoulli spread times the step
  const MeanStd s = patch_mean_std(view_of(patch));
  EXPECT_NEAR(s.mean, mean, 1e-6);
  EXPECT_NEAR(s.std, sigma, 1e-6);
}

TEST(PlaneStatistics, LargeOffsetKeepsPrecision) {
  // Distances of a few hundred pixels with a small spread.
  const cv::Mat patch = patch_from(10, [](double x, double) { return 400.0 + (x > 0 ? 0.5 : x < 0 ? -0.5 : 0.0); });
  const MeanStd s = patch_mean_std(view_of(patch));
  EXPECT_NEAR(s.mean, 400.0, 1e-5);
  EXPECT_NEAR(s.std, 0.5 * std::sqrt(20.0 / 21.0), 1e-5);
}

TEST(GradientRegions, MeansOfQuadrantsAndWholePatch) {
  const int r = 4;
  const cv::Mat patch = patch_from(r, [](double x, double y) {
    if (x == 0 || y == 0) return 10.0;  // the centre cross
    if (y < 0) return x < 0 ? 1.0 : 2.0;
    return x < 0 ? 3.0 : 4.0;
  });
  const auto m = gradient_region_means(view_of(patch));
  EXPECT_DOUBLE_EQ(m[1], 1.0);
  EXPECT_DOUBLE_EQ(m[2], 2.0);
  EXPECT_DOUBLE_EQ(m[3], 3.0);
  EXPECT_DOUBLE_EQ(m[4], 4.0);
  const double cross = 4 * r + 1;
  EXPECT_NEAR(m[0], (r * r * (1 + 2 + 3 + 4) + 10 * cross) / 81.0, 1e-12);
}

TEST(GradientRegions, ModuleWritesMeansAndDifferences) {
  const cv::Mat plane = patch_from(5, [](double x, double y) { return (y < 0 ? 1.0 : 3.0) + (x < 0 ? 0.0 : 0.5); });
  const PreparedImage image = image_with_plane(angle_plane(1), plane, 5);
  const std::array<PatchMoments, 3> moments{};
  const ModuleContext context{image, {5, 5}, 5, 5, 5, moments};
  std::array<float, 45> values;
  values.fill(-99.0f);
  // Channel 1: mean of quadrant 12 (top-right) and difference 11-22.
  const std::uint64_t bits = (std::uint64_t{1} << (5 + 2)) | (std::uint64_t{1} << (15 + 10 + 6));
  gradient_angles_module(context, bits, values.data());
  EXPECT_FLOAT_EQ(values[5 + 2], 1.5f);
  EXPECT_FLOAT_EQ(values[15 + 10 + 6], 1.0f - 3.5f);
  int untouched = 0;
  for (const float v : values) untouched += v == -99.0f;
  EXPECT_EQ(untouched, 43) << "only the active values are written";
}

std::array<double, 3> reference_singular_values(const cv::Mat& patch) {
  cv::Mat w;
  cv::SVD::compute(patch, w, cv::SVD::NO_UV);
  return {w.at<float>(0), w.at<float>(1), w.at<float>(2)};
}

TEST(SingularValues, MatchFullSvdOnImagePatches) {
  const cv::Mat image = test_util::textured_image({160, 120}, 3);
  cv::Mat grey;
  cv::cvtColor(image, grey, cv::COLOR_BGR2GRAY);
  grey.convertTo(grey, CV_32F, 1.0 / 255.0);
  cv::GaussianBlur(grey, grey, {5, 5}, 1.1);
  for (int r : {3, 6, 10})
    for (int y = 12; y < 110; y += 17)
      for (int x = 12; x < 150; x += 23) {
        const cv::Mat patch = grey(cv::Rect(x - r, y - r, 2 * r + 1, 2 * r + 1)).clone();
        const auto expected = reference_singular_values(patch);
        double sigma[3];
        top_singular_values(view_of(patch), 3, sigma);
        for (int k = 0; k < 3; ++k)
          EXPECT_NEAR(sigma[k], expected[static_cast<std::size_t>(k)], 1e-4 * expected[0])
              << "sigma" << k + 1 << " r=" << r << " at " << x << "," << y;
      }
}

TEST(SingularValues, StructuredPatches) {
  double sigma[3];
  // Identity: every singular value is 1, and the column-sum start vector
  // spans only one of them (the Krylov space must be restarted).
  top_singular_values(view_of(cv::Mat::eye(9, 9, CV_32F)), 3, sigma);
  EXPECT_NEAR(sigma[0], 1.0, 1e-5);
  EXPECT_NEAR(sigma[1], 1.0, 1e-5);
  EXPECT_NEAR(sigma[2], 1.0, 1e-5);
  // Rank one: u v^T with |u| = 3, |v| = 2.
  const cv::Mat rank_one = patch_from(
      4, [](double x, double y) { return (y == 0 ? 3.0 : 0.0) * (x == 1 || x == -1 ? std::sqrt(2.0) : 0.0); });
  top_singular_values(view_of(rank_one), 3, sigma);
  EXPECT_NEAR(sigma[0], 6.0, 1e-5);
  EXPECT_NEAR(sigma[1], 0.0, 1e-5);
  EXPECT_NEAR(sigma[2], 0.0, 1e-5);
  // Zero patch.
  EXPECT_EQ(top_singular_values(view_of(cv::Mat::zeros(7, 7, CV_32F)), 2, sigma), 0);
  EXPECT_EQ(sigma[0], 0.0);
  EXPECT_EQ(sigma[1], 0.0);
  // Diagonal with distinct values: exact order.
  cv::Mat diag = cv::Mat::zeros(7, 7, CV_32F);
  for (int i = 0; i < 7; ++i) diag.at<float>(i, i) = static_cast<float>(i + 1);
  top_singular_values(view_of(diag), 3, sigma);
  EXPECT_NEAR(sigma[0], 7.0, 1e-4);
  EXPECT_NEAR(sigma[1], 6.0, 1e-4);
  EXPECT_NEAR(sigma[2], 5.0, 1e-4);
}

TEST(SingularValues, ThreeStepsPerWantedValue) {
  const cv::Mat patch = test_util::supersampled_patch(
      10, [](double x, double y) { return 0.5 + 0.3 * std::sin(x * 0.7) * std::cos(y * 0.4) + 0.01 * x * y; });
  double one[3], three[3];
  EXPECT_EQ(top_singular_values(view_of(patch), 1, one), 3);
  EXPECT_EQ(top_singular_values(view_of(patch), 3, three), 9);
  EXPECT_NEAR(one[0], three[0], 1e-5 * three[0]);
  EXPECT_EQ(top_singular_values(view_of(patch(cv::Rect(7, 7, 7, 7)).clone()), 3, three), 7) << "capped at 2r+1: exact";
}

TEST(SingularValues, APatchInABatchEqualsThePatchAlone) {
  // Eight lanes: six textured patches, a zero patch and the identity (whose
  // Krylov space must be restarted), in two different orders; every lane's
  // values and steps are bit-identical to the patch computed alone.
  const cv::Mat image = test_util::textured_image({80, 60}, 4);
  std::vector<cv::Mat> channels;
  cv::split(image, channels);
  std::vector<PatchBuffer> buffers;
  for (int k = 0; k < 6; ++k) {
    cv::Mat c;
    channels[static_cast<std::size_t>(k % 3)].convertTo(c, CV_32F, 1.0 / 255.0);
    buffers.emplace_back(c(cv::Rect(5 + 9 * k, 10 + 3 * k, 21, 21)).clone());
  }
  buffers.emplace_back(cv::Mat(cv::Mat::zeros(21, 21, CV_32F)));
  buffers.emplace_back(cv::Mat(cv::Mat::eye(21, 21, CV_32F)));
  for (const int count : {1, 2, 3}) {
    std::vector<PatchView> patches(buffers.begin(), buffers.end());
    for (int order = 0; order < 2; ++order) {
      if (order == 1) std::reverse(patches.begin(), patches.end());
      double together[kSingularValueLanes][3];
      int steps[kSingularValueLanes];
      top_singular_values(patches.data(), kSingularValueLanes, count, together, steps);
      for (int l = 0; l < kSingularValueLanes; ++l) {
        double alone[3];
        EXPECT_EQ(top_singular_values(patches[static_cast<std::size_t>(l)], count, alone), steps[l]);
        for (int k = 0; k < count; ++k) EXPECT_EQ(together[l][k], alone[k]) << "lane " << l << " sigma" << k + 1;
      }
    }
  }
}

TEST(SingularValues, ModuleAloneEqualsTheExtractorsBatches) {
  // extract() computes the module in batches of lanes; the module called on
  // one keypoint's context computes it alone. Same bits, and only the active
  // values are written.
  DescriptorParams p = Genome::thesis_best().decode();
  p.activation.reset();
  const int first = module_offset(Module::singular_values);
  const int active[] = {0, 3, 4, 8};  // sv1_c0, sv1_c1, sv2_c1, sv3_c2
  for (const int v : active) p.activation.set(static_cast<std::size_t>(first + v));
  const PreparedImage prepared = prepare(test_util::textured_image({96, 72}, 5), p);
  const std::vector<cv::Point2f> points{{10, 10}, {40, 33}, {41, 33}, {95, 71}, {0, 0}, {60, 5}};
  const cv::Mat batch = extract(prepared, points, p);
  ASSERT_EQ(batch.cols, 4);
  const std::array<PatchMoments, 3> moments{};
  for (std::size_t k = 0; k < points.size(); ++k) {
    const int x = cvRound(points[k].x), y = cvRound(points[k].y);
    const ModuleContext context{prepared, points[k], x, y, p.patch_radius, moments};
    std::array<float, kSingularValueCount> values;
    values.fill(-99.0f);
    singular_values_module(context, module_bits(p.activation, Module::singular_values), values.data());
    for (int i = 0; i < kSingularValueCount; ++i) {
      const auto column = std::find(std::begin(active), std::end(active), i) - std::begin(active);
      const float got = values[static_cast<std::size_t>(i)];
      if (column < 4)
        EXPECT_EQ(got, batch.at<float>(static_cast<int>(k), static_cast<int>(column)))
            << "keypoint " << k << " value " << i;
      else
        EXPECT_EQ(got, -99.0f) << "inactive value " << i << " written";
    }
  }
}

TEST(EdgeDistance, ExactEuclideanDistanceToALine) {
  cv::Mat edges = cv::Mat::zeros(30, 40, CV_8U);
  edges.col(12).setTo(255);
  edges.at<uchar>(3, 30) = 255;  // an isolated edge pixel
  cv::Mat distance(edges.size(), CV_32F);
  distance_to_edges(edges, distance);
  for (int y = 0; y < 30; ++y)
    for (int x = 0; x < 40; ++x) {
      const double expected = std::min<double>(std::abs(x - 12), std::hypot(x - 30, y - 3));
      EXPECT_NEAR(distance.at<float>(y, x), expected, 1e-3) << x << "," << y;
    }
}

TEST(EdgeDistance, EqualsBruteForceOnScatteredEdges) {
  // Sparse random edges: empty columns, far and near pixels, image borders.
  cv::Mat edges = cv::Mat::zeros(37, 83, CV_8U);
  cv::RNG rng(7);
  for (int i = 0; i < 25; ++i) {
    const int row = rng.uniform(0, edges.rows);  // one draw a statement: in order
    const int column = rng.uniform(0, edges.cols / 2);
    edges.at<uchar>(row, column) = 255;
  }
  cv::Mat distance(edges.size(), CV_32F);
  distance_to_edges(edges, distance);
  std::vector<cv::Point> points;
  cv::findNonZero(edges, points);
  for (int y = 0; y < edges.rows; ++y)
    for (int x = 0; x < edges.cols; ++x) {
      double best = 1e30;
      for (const cv::Point& p : points) best = std::min(best, std::hypot(p.x - x, p.y - y));
      ASSERT_FLOAT_EQ(distance.at<float>(y, x), static_cast<float>(best)) << x << "," << y;
    }
}

TEST(EdgeDistance, NoEdgeGivesTheDiagonal) {
  cv::Mat distance(30, 40, CV_32F);
  distance_to_edges(cv::Mat::zeros(30, 40, CV_8U), distance);
  EXPECT_FLOAT_EQ(distance.at<float>(7, 9), 50.0f);
}

TEST(EdgeDistance, ModuleMeanAndSigmaNextToAnEdge) {
  // Vertical edge at column 20; the patch centred 3 pixels right of it
  // sees columns at distances 0..6 (radius 3), seven rows each.
  cv::Mat edges = cv::Mat::zeros(40, 40, CV_8U);
  edges.col(20).setTo(255);
  cv::Mat distance(edges.size(), CV_32F);
  distance_to_edges(edges, distance);
  const PreparedImage image = image_with_plane(PlaneId::edge_distance, distance, 3);
  const std::array<PatchMoments, 3> moments{};
  const ModuleContext context{image, {23, 15}, 23, 15, 3, moments};
  float values[2] = {-1, -1};
  edge_distance_module(context, 0b11, values);
  EXPECT_NEAR(values[0], 3.0, 1e-5);             // mean of 0..6
  EXPECT_NEAR(values[1], std::sqrt(4.0), 1e-5);  // population sigma of 0..6
}

TEST(Position, NormalisedByImageSize) {
  PreparedImage image;
  image.image_size = {640, 480};
  const std::array<PatchMoments, 3> moments{};
  const ModuleContext context{image, {160.5f, 120.0f}, 161, 120, 3, moments};
  float values[2] = {-1, -1};
  position_module(context, 0b10, values);
  EXPECT_EQ(values[0], -1.0f) << "inactive value untouched";
  EXPECT_FLOAT_EQ(values[1], 0.25f);
  position_module(context, 0b11, values);
  EXPECT_FLOAT_EQ(values[0], 160.5f / 640.0f);
}

struct InvariantPlanes {
  std::array<cv::Mat, 3> l, c;
  cv::Mat h, cc;
};

InvariantPlanes invariants_of(const cv::Mat& bgr) {
  InvariantPlanes planes;
  ColourInvariantOutputs out;
  for (int i = 0; i < 3; ++i) {
    planes.l[static_cast<std::size_t>(i)].create(bgr.size(), CV_32F);
    planes.c[static_cast<std::size_t>(i)].create(bgr.size(), CV_32F);
    out.gevers_l[i] = &planes.l[static_cast<std::size_t>(i)];
    out.gevers_c[i] = &planes.c[static_cast<std::size_t>(i)];
  }
  planes.h.create(bgr.size(), CV_32F);
  planes.cc.create(bgr.size(), CV_32F);
  out.geusebroek_h = &planes.h;
  out.geusebroek_c = &planes.cc;
  compute_colour_invariants(bgr, out);
  return planes;
}

TEST(ColourInvariants, UnchangedByIntensityScaling) {
  // Doubling 8-bit values below 128 scales R, G, B exactly (eq. III.37, a = 2).
  cv::Mat dark = test_util::textured_image({64, 48}, 9);
  dark = dark * 0.45;  // at most 115, so doubling stays below 256
  const cv::Mat bright = dark * 2;
  const InvariantPlanes a = invariants_of(dark), b = invariants_of(bright);
  const auto max_difference = [](const cv::Mat& x, const cv::Mat& y) { return cv::norm(x, y, cv::NORM_INF); };
  for (int i = 0; i < 3; ++i) {
    EXPECT_LT(max_difference(a.l[static_cast<std::size_t>(i)], b.l[static_cast<std::size_t>(i)]), 1e-5) << "l" << i + 1;
    EXPECT_LT(max_difference(a.c[static_cast<std::size_t>(i)], b.c[static_cast<std::size_t>(i)]), 1e-4) << "c" << i + 1;
  }
  EXPECT_LT(max_difference(a.h, b.h), 1e-4);
  EXPECT_LT(max_difference(a.cc, b.cc), 1e-5);
  // ... while the plain channels do change.
  EXPECT_GT(cv::norm(dark, bright, cv::NORM_INF), 50);
}

TEST(ColourInvariants, KnownPixelValues) {
  // One pixel: R = 200, G = 100, B = 50 (BGR storage).
  const cv::Mat bgr(1, 1, CV_8UC3, cv::Scalar(50, 100, 200));
  const InvariantPlanes p = invariants_of(bgr);
  const double r = 200 / 255.0, g = 100 / 255.0, b = 50 / 255.0;
  const double d = (r - g) * (r - g) + (r - b) * (r - b) + (g - b) * (g - b);
  EXPECT_NEAR(p.l[0].at<float>(0), (r - g) * (r - g) / d, 1e-6);
  EXPECT_NEAR(p.l[1].at<float>(0), (r - b) * (r - b) / d, 1e-6);
  EXPECT_NEAR(p.l[2].at<float>(0), (g - b) * (g - b) / d, 1e-6);
  EXPECT_NEAR(p.l[0].at<float>(0) + p.l[1].at<float>(0) + p.l[2].at<float>(0), 1.0, 1e-6);
  EXPECT_NEAR(p.c[0].at<float>(0), std::atan(r / g), 1e-3);
  EXPECT_NEAR(p.c[1].at<float>(0), std::atan(g / r), 1e-3);
  EXPECT_NEAR(p.c[2].at<float>(0), std::atan(b / r), 1e-3);
  const double e = 0.06 * r + 0.63 * g + 0.27 * b, el = 0.3 * r + 0.04 * g - 0.35 * b,
               ell = 0.34 * r - 0.6 * g + 0.17 * b;
  double h = std::atan2(el, ell);
  if (h < 0) h += 2 * CV_PI;
  EXPECT_NEAR(p.h.at<float>(0), h, 1e-3);
  EXPECT_NEAR(p.cc.at<float>(0), el / e, 1e-6);
}

TEST(ColourInvariants, GreyPixelsHaveNoHueDirection) {
  const InvariantPlanes p = invariants_of(cv::Mat(2, 2, CV_8UC3, cv::Scalar(90, 90, 90)));
  EXPECT_EQ(p.l[0].at<float>(1, 1), 0.0f);
  EXPECT_NEAR(p.c[0].at<float>(1, 1), CV_PI / 4, 1e-3);
  const InvariantPlanes black = invariants_of(cv::Mat(2, 2, CV_8UC3, cv::Scalar(0, 0, 0)));
  EXPECT_EQ(black.cc.at<float>(0, 0), 0.0f);
  EXPECT_EQ(black.c[2].at<float>(0, 0), 0.0f);
}

}  // namespace
}  // namespace facadeslam::semantics
