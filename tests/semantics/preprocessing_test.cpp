#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstdint>

#include <cmath>

#include <opencv2/imgproc.hpp>

#include "core/util/error.hpp"
#include "semantics/descriptor/canny_edges.hpp"
#include "semantics/descriptor/colour_conversion.hpp"
#include "semantics/descriptor/edge_distance.hpp"
#include "semantics/descriptor/gradient_angle_plane.hpp"
#include "semantics/descriptor/genome.hpp"
#include "semantics/descriptor/padded_plane.hpp"
#include "semantics/descriptor/prepared_image.hpp"
#include "tests/semantics/semantics_test_util.hpp"

namespace facadeslam::semantics {
namespace {

using ::testing::HasSubstr;

using test_util::with_values;

std::array<cv::Mat, 3> converted(const cv::Mat& bgr, ColourSpace space) {
  std::array<cv::Mat, 3> planes;
  for (auto& p : planes) p.create(bgr.size(), CV_32F);
  convert_colour(bgr, space, {&planes[0], &planes[1], &planes[2]});
  return planes;
}

TEST(ColourConversion, EveryChannelIsANonNegativeIntensity) {
  cv::Mat image(16, 16, CV_8UC3);
  cv::RNG(2).fill(image, cv::RNG::UNIFORM, 0, 256);
  image.at<cv::Vec3b>(0, 0) = {255, 0, 0};  // saturated blue: the largest Z
  image.at<cv::Vec3b>(0, 1) = {255, 255, 255};
  image.at<cv::Vec3b>(0, 2) = {0, 0, 0};
  for (const ColourSpace space : kColourSpaces) {
    const auto planes = converted(image, space);
    for (int c = 0; c < 3; ++c) {
      double lo, hi;
      cv::minMaxLoc(planes[static_cast<std::size_t>(c)], &lo, &hi);
      // Up to float rounding of the linear maps.
      EXPECT_GE(lo, -1e-6) << colour_space_name(space) << " channel " << c;
      EXPECT_LE(hi, (space == ColourSpace::xyz ? 1.09 : 1.0) + 1e-6) << colour_space_name(space) << " channel " << c;
    }
  }
}

TEST(ColourConversion, ByteTablesGiveTheSameFloats) {
  // Wider than a vector block, so OpenCV's vector and scalar paths both run.
  const cv::Mat image = test_util::textured_image({97, 13}, 8);
  for (const ColourSpace space : {ColourSpace::lab, ColourSpace::luv, ColourSpace::hsv, ColourSpace::hls}) {
    const auto planes = converted(image, space);
    cv::Mat bytes;
    convert_colour_bytes(image, space, bytes);
    for (int y = 0; y < image.rows; ++y)
      for (int x = 0; x < image.cols; ++x)
        for (int c = 0; c < 3; ++c)
          ASSERT_EQ(planes[static_cast<std::size_t>(c)].at<float>(y, x), byte_values()[bytes.at<cv::Vec3b>(y, x)[c]])
              << colour_space_name(space) << " channel " << c << " at " << x << ", " << y;
  }
}

TEST(ColourConversion, MatchesTheDocumentedFormulas) {
  const cv::Mat bgr(1, 1, CV_8UC3, cv::Scalar(30, 120, 210));  // B, G, R
  const double r = 210 / 255.0, g = 120 / 255.0, b = 30 / 255.0;
  const auto at = [](const std::array<cv::Mat, 3>& p, int c) { return p[static_cast<std::size_t>(c)].at<float>(0); };
  auto rgb = converted(bgr, ColourSpace::rgb);
  EXPECT_NEAR(at(rgb, 0), r, 1e-6);
  EXPECT_NEAR(at(rgb, 2), b, 1e-6);
  auto opp = converted(bgr, ColourSpace::opponent);
  EXPECT_NEAR(at(opp, 0), (r - g) / 2 + 0.5, 1e-6);
  EXPECT_NEAR(at(opp, 1), (r + g - 2 * b) / 4 + 0.5, 1e-6);
  EXPECT_NEAR(at(opp, 2), (r + g + b) / 3, 1e-6);
  auto ycc = converted(bgr, ColourSpace::ycrcb);
  const double y = 0.299 * r + 0.587 * g + 0.114 * b;
  EXPECT_NEAR(at(ycc, 0), y, 1e-6);
  EXPECT_NEAR(at(ycc, 1), 0.713 * (r - y) + 0.5, 1e-6);
  EXPECT_NEAR(at(ycc, 2), 0.564 * (b - y) + 0.5, 1e-6);
  // XYZ agrees with OpenCV's float conversion.
  cv::Mat f, xyz;
  bgr.convertTo(f, CV_32F, 1 / 255.0);
  cv::cvtColor(f, xyz, cv::COLOR_BGR2XYZ);
  auto ours = converted(bgr, ColourSpace::xyz);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(at(ours, c), xyz.at<cv::Vec3f>(0)[c], 1e-5) << c;
  // The 8-bit spaces are OpenCV's 8-bit conversions / 255.
  for (const auto& [space, code] : {std::pair{ColourSpace::lab, cv::COLOR_BGR2Lab},
                                    {ColourSpace::hsv, cv::COLOR_BGR2HSV_FULL},
                                    {ColourSpace::luv, cv::COLOR_BGR2Luv},
                                    {ColourSpace::hls, cv::COLOR_BGR2HLS_FULL}}) {
    cv::Mat reference;
    cv::cvtColor(bgr, reference, code);
    auto planes = converted(bgr, space);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(at(planes, c), reference.at<cv::Vec3b>(0)[c] / 255.0, 1e-6);
  }
}

TEST(PaddedPlane, BorderReflectsLikeOpenCv) {
  cv::Mat interior(5, 7, CV_32F);
  cv::RNG(1).fill(interior, cv::RNG::UNIFORM, 0, 1);
  for (const int border : {1, 3, 6}) {  // 6 exceeds the height: reflection must still be defined
    cv::Mat padded = make_padded_plane(interior.size(), border);
    interior.copyTo(plane_interior(padded, border));
    fill_border_reflect101(padded, border);
    cv::Mat expected;
    cv::copyMakeBorder(interior, expected, border, border, border, border, cv::BORDER_REFLECT_101);
    const cv::Mat without_slack = padded.colRange(0, padded.cols - PatchView::kReadSlack);
    EXPECT_EQ(cv::norm(without_slack, expected, cv::NORM_INF), 0.0) << "border " << border;
    EXPECT_EQ(cv::countNonZero(padded.colRange(without_slack.cols, padded.cols)), 0) << "zeroed slack";
  }
}

TEST(Prepare, ComputesOnlyTheNeededPlanes) {
  const cv::Mat image = test_util::textured_image({80, 60});
  const DescriptorParams thesis = Genome::thesis_best().decode();
  const PreparedImage prepared = prepare(image, thesis);
  EXPECT_EQ(prepared.computed.count(), 14u);  // all but Gevers l2
  EXPECT_FALSE(prepared.has(PlaneId::gevers_l2));
  EXPECT_TRUE(prepared.plane(PlaneId::gevers_l2).empty());
  EXPECT_TRUE(prepared.has(PlaneId::edge_distance));
  EXPECT_EQ(prepared.border, 10);
  EXPECT_EQ(prepared.plane(PlaneId::colour0).size(), cv::Size(100 + PatchView::kReadSlack, 80));
  EXPECT_EQ(prepared.interior(PlaneId::colour0).size(), image.size());

  const PreparedImage angles_only = prepare(image, with_values({"angle12_c1"}));
  EXPECT_EQ(angles_only.computed.count(), 2u);  // the channel and its angles
  EXPECT_TRUE(angles_only.has(colour_plane(1)));
  EXPECT_TRUE(angles_only.has(angle_plane(1)));
  EXPECT_TRUE(angles_only.edges.empty()) << "no Canny without the edge-distance module";

  const PreparedImage position_only = prepare(image, with_values({"x_norm", "y_norm"}));
  EXPECT_TRUE(position_only.computed.none());
  EXPECT_EQ(position_only.image_size, image.size());
}

TEST(Prepare, EqualisesLuminanceBeforeBlurring) {
  // A low-contrast image (grey levels 100..120) spans the range after equalisation.
  cv::Mat image(40, 60, CV_8UC3);
  for (int x = 0; x < 60; ++x) image.col(x).setTo(cv::Scalar::all(100 + x / 3));
  const PreparedImage prepared = prepare(image, with_values({"mean_c0"}));  // RGB, no blur
  double lo, hi;
  cv::minMaxLoc(prepared.interior(PlaneId::colour0), &lo, &hi);
  EXPECT_LT(lo, 0.1);
  EXPECT_GT(hi, 0.95);
}

TEST(Prepare, BlurFollowsTheGenome) {
  cv::Mat image(31, 31, CV_8UC3, cv::Scalar::all(0));
  image.at<cv::Vec3b>(15, 15) = {255, 255, 255};
  DescriptorParams p = with_values({"mean_c0"});
  const PreparedImage sharp = prepare(image, p);
  EXPECT_EQ(sharp.interior(PlaneId::colour0).at<float>(15, 17), sharp.interior(PlaneId::colour0).at<float>(0, 0));
  p.gaussian_kernel = 7;
  p.gaussian_sigma = 1.5;
  const PreparedImage blurred = prepare(image, p);
  EXPECT_GT(blurred.interior(PlaneId::colour0).at<float>(15, 17), blurred.interior(PlaneId::colour0).at<float>(0, 0));
  EXPECT_LT(blurred.interior(PlaneId::colour0).at<float>(15, 15), sharp.interior(PlaneId::colour0).at<float>(15, 15));
}

TEST(Prepare, GradientAnglesPointUpTheRamp) {
  cv::Mat horizontal(30, 30, CV_8UC3), vertical(30, 30, CV_8UC3);
  for (int i = 0; i < 30; ++i) {
    horizontal.col(i).setTo(cv::Scalar::all(40 + 5 * i));
    vertical.row(i).setTo(cv::Scalar::all(40 + 5 * i));
  }
  for (const GradientOperator op : kGradientOperators) {
    DescriptorParams p = with_values({"angle00_c0"});
    p.gradient_operator = op;
    const PreparedImage h = prepare(horizontal, p), v = prepare(vertical, p);
    const float right = h.interior(angle_plane(0)).at<float>(15, 15);
    const float down = v.interior(angle_plane(0)).at<float>(15, 15);
    EXPECT_TRUE(right < 0.01f || right > 2 * CV_PI - 0.01f) << "increasing to the right: angle 0, got " << right;
    EXPECT_NEAR(down, CV_PI / 2, 0.01) << "increasing downwards (y down): angle pi/2";
  }
}

TEST(Prepare, EdgeDistanceMeasuresFromTheCannyEdge) {
  cv::Mat image(40, 60, CV_8UC3, cv::Scalar::all(30));
  image.colRange(30, 60).setTo(cv::Scalar::all(220));
  DescriptorParams p = with_values({"mean_edge_distance"});
  const PreparedImage prepared = prepare(image, p);
  ASSERT_FALSE(prepared.edges.empty());
  int edge_column = -1;
  for (int x = 0; x < 60; ++x)
    if (prepared.edges.at<uchar>(20, x)) edge_column = x;
  ASSERT_TRUE(edge_column == 29 || edge_column == 30) << edge_column;
  const cv::Mat d = prepared.interior(PlaneId::edge_distance);
  EXPECT_FLOAT_EQ(d.at<float>(20, edge_column), 0.0f);
  EXPECT_FLOAT_EQ(d.at<float>(20, edge_column - 10), 10.0f);
  EXPECT_FLOAT_EQ(d.at<float>(5, edge_column + 7), 7.0f);
}

TEST(Prepare, RejectsBadImages) {
  const DescriptorParams p = with_values({"mean_c0"});
  EXPECT_THAT([&] { prepare(cv::Mat(), p); }, ::testing::ThrowsMessage<Error>(HasSubstr("empty")));
  EXPECT_THAT([&] { prepare(cv::Mat(10, 10, CV_8U, cv::Scalar(0)), p); },
              ::testing::ThrowsMessage<Error>(HasSubstr("8-bit 3-channel BGR")));
  EXPECT_THAT([&] { prepare(cv::Mat(10, 10, CV_32FC3, cv::Scalar::all(0)), p); },
              ::testing::ThrowsMessage<Error>(HasSubstr("32FC3")));
  DescriptorParams bad = p;
  bad.patch_radius = 2;
  EXPECT_THAT([&] { prepare(cv::Mat(10, 10, CV_8UC3, cv::Scalar::all(0)), bad); },
              ::testing::ThrowsMessage<Error>(HasSubstr("patch_radius")));
}

TEST(Prepare, IsDeterministic) {
  const cv::Mat image = test_util::textured_image({64, 48}, 4);
  const DescriptorParams p = Genome::thesis_best().decode();
  const PreparedImage a = prepare(image, p), b = prepare(image, p);
  for (int i = 0; i < kPlaneCount; ++i) {
    if (a.planes[static_cast<std::size_t>(i)].empty()) continue;
    EXPECT_EQ(cv::norm(a.planes[static_cast<std::size_t>(i)], b.planes[static_cast<std::size_t>(i)], cv::NORM_INF), 0.0)
        << plane_name(static_cast<PlaneId>(i));
  }
}

}  // namespace
}  // namespace facadeslam::semantics

namespace facadeslam::semantics {
namespace {

TEST(CannyEdges, IdenticalToOpenCvCanny) {
  // Two sizes (vector blocks and a scalar tail), noise-free and noisy
  // texture (many ties and weak maxima), every genome aperture.
  CannyBuffers buffers;
  for (const cv::Size size : {cv::Size(97, 61), cv::Size(322, 241)})
    for (const bool noisy : {false, true}) {
      cv::Mat grey;
      cv::cvtColor(test_util::textured_image(size, 6), grey, cv::COLOR_BGR2GRAY);
      if (noisy) {
        cv::Mat noise(grey.size(), CV_8U);
        cv::randu(noise, 0, 24);
        grey += noise;
      }
      cv::GaussianBlur(grey, grey, {3, 3}, 0.8);
      for (const int aperture : {3, 5})
        for (const int low : {5, 15, 45, 85}) {
          cv::Mat ours, reference;
          canny_edges(grey, aperture, low, 3 * low, ours, buffers);
          cv::Canny(grey, reference, low, 3 * low, aperture, false);
          EXPECT_EQ(cv::countNonZero(ours != reference), 0)
              << size << (noisy ? " noisy" : "") << " aperture " << aperture << " low " << low;
          EXPECT_GT(cv::countNonZero(reference), 50) << "the test image must have edges";
        }
    }
}

TEST(GradientAnglePlane, MatchesOpenCvDerivativesAndPhase) {
  cv::Mat image = test_util::textured_image({64, 48}, 7);
  cv::Mat channel;
  cv::cvtColor(image, channel, cv::COLOR_BGR2GRAY);
  channel.convertTo(channel, CV_32F, 1 / 255.0);
  cv::Mat padded = make_padded_plane(channel.size(), 3);
  channel.copyTo(plane_interior(padded, 3));
  fill_border_reflect101(padded, 3);
  for (const GradientOperator op : kGradientOperators) {
    cv::Mat angle(channel.size(), CV_32F), gx, gy, reference;
    gradient_angle_plane(padded, 3, op, angle);
    if (op == GradientOperator::sobel) {
      cv::Sobel(channel, gx, CV_32F, 1, 0, 3, 1, 0, cv::BORDER_REFLECT_101);
      cv::Sobel(channel, gy, CV_32F, 0, 1, 3, 1, 0, cv::BORDER_REFLECT_101);
    } else {
      cv::Scharr(channel, gx, CV_32F, 1, 0, 1, 0, cv::BORDER_REFLECT_101);
      cv::Scharr(channel, gy, CV_32F, 0, 1, 1, 0, cv::BORDER_REFLECT_101);
    }
    cv::phase(gx, gy, reference);
    int compared = 0;
    for (int y = 0; y < angle.rows; ++y)
      for (int x = 0; x < angle.cols; ++x) {
        const float g = std::hypot(gx.at<float>(y, x), gy.at<float>(y, x));
        if (g < 1e-3f) continue;  // flat: the direction is noise
        float d = std::abs(angle.at<float>(y, x) - reference.at<float>(y, x));
        d = std::min(d, static_cast<float>(2 * CV_PI) - d);  // 0 and 2 pi are the same direction
        EXPECT_LT(d, 2e-4) << gradient_operator_name(op) << " at " << x << "," << y;
        ++compared;
      }
    EXPECT_GT(compared, 2000);
  }
}

TEST(EdgeDistance, MatchesOpenCvExactTransform) {
  cv::Mat edges(57, 83, CV_8U);
  cv::RNG(3).fill(edges, cv::RNG::UNIFORM, 0, 100);
  edges = edges > 97;  // sparse random edge pixels
  cv::Mat ours(edges.size(), CV_32F), reference;
  distance_to_edges(edges, ours);
  cv::distanceTransform(edges == 0, reference, cv::DIST_L2, cv::DIST_MASK_PRECISE, CV_32F);
  EXPECT_LT(cv::norm(ours, reference, cv::NORM_INF), 1e-3);
}

TEST(EdgeDistance, ExactForEveryWidthAndFarEdges) {
  // Widths below, at and past a vector block (and below the 4 steps every
  // block takes first), with one or two edge pixels, so that some blocks
  // search to the far end of the row: the distances are the exact ones,
  // bit for bit.
  for (int width = 1; width <= 19; ++width)
    for (const bool two : {false, true}) {
      cv::Mat edges = cv::Mat::zeros(7, width, CV_8U);
      edges.at<uchar>(1, 0) = 255;
      if (two) edges.at<uchar>(6, width - 1) = 255;
      cv::Mat ours(edges.size(), CV_32F);
      distance_to_edges(edges, ours);
      for (int y = 0; y < edges.rows; ++y)
        for (int x = 0; x < width; ++x) {
          int best = INT32_MAX;
          for (int ey = 0; ey < edges.rows; ++ey)
            for (int ex = 0; ex < width; ++ex)
              if (edges.at<uchar>(ey, ex)) best = std::min(best, (x - ex) * (x - ex) + (y - ey) * (y - ey));
          ASSERT_EQ(ours.at<float>(y, x), static_cast<float>(std::sqrt(static_cast<double>(best))))
              << "width " << width << (two ? ", two edges" : ", one edge") << " at " << x << ", " << y;
        }
    }
}

}  // namespace
}  // namespace facadeslam::semantics

namespace facadeslam::semantics {
namespace {

TEST(Prepare, ReusingAPreparedImageGivesTheSameResultInTheSameMemory) {
  const cv::Mat first = test_util::textured_image({80, 60}, 11);
  const cv::Mat second = test_util::textured_image({80, 60}, 12);
  const DescriptorParams thesis = Genome::thesis_best().decode();
  PreparedImage reused = prepare(first, thesis);
  const uchar* memory = reused.plane(PlaneId::geusebroek_h).data;
  prepare(second, thesis, reused);
  EXPECT_EQ(reused.plane(PlaneId::geusebroek_h).data, memory) << "same size: no new allocation";
  const PreparedImage fresh = prepare(second, thesis);
  EXPECT_EQ(reused.computed, fresh.computed);
  for (int p = 0; p < kPlaneCount; ++p) {
    if (!fresh.computed.test(static_cast<std::size_t>(p))) continue;
    EXPECT_EQ(
        cv::norm(reused.planes[static_cast<std::size_t>(p)], fresh.planes[static_cast<std::size_t>(p)], cv::NORM_INF),
        0.0)
        << plane_name(static_cast<PlaneId>(p));
  }
  // Fewer planes next time: the others are released, not left stale.
  prepare(second, with_values({"std_c2"}, thesis), reused);
  EXPECT_EQ(reused.computed.count(), 1u);
  EXPECT_TRUE(reused.plane(PlaneId::geusebroek_h).empty());
  EXPECT_TRUE(reused.edges.empty());
  // A different image size reallocates.
  prepare(test_util::textured_image({50, 40}, 13), thesis, reused);
  EXPECT_EQ(reused.interior(PlaneId::colour0).size(), cv::Size(50, 40));
}

}  // namespace
}  // namespace facadeslam::semantics
