// Board description, image listing, view checks and coverage figures.
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

#include "calib/board.hpp"
#include "calib/board_detection.hpp"
#include "calib/coverage.hpp"
#include "calib/image_files.hpp"
#include "calib/view_quality.hpp"
#include "core/util/error.hpp"
#include "tests/calib/calib_test_scenes.hpp"
#include "tests/support/test_support.hpp"

namespace facadeslam::calib {
namespace {

using ::testing::HasSubstr;

std::string board_error(const std::string& text, double square = 0.025) {
  try {
    parse_board_size(text, square);
  } catch (const Error& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(BoardSpec, ParsesInnerCornerCounts) {
  const BoardSpec board = parse_board_size("9x6", 0.025);
  EXPECT_EQ(board.cols, 9);
  EXPECT_EQ(board.rows, 6);
  EXPECT_EQ(board.square, 0.025);
  EXPECT_EQ(board.corner_count(), 54);
  EXPECT_EQ(board.size_text(), "9x6");
  EXPECT_EQ(parse_board_size("2X2", 1.0).corner_count(), 4);
}

TEST(BoardSpec, RejectsMalformedSizes) {
  for (const std::string bad : {"", "9", "9x", "x6", "9x6x2", "9 x 6", "9x-6", "1x6", "9x1", "ax6", "9.5x6", "9,6"})
    EXPECT_THAT(board_error(bad), HasSubstr("expected WxH")) << "'" << bad << "'";
}

TEST(BoardSpec, RejectsNonPositiveSquares) {
  EXPECT_THAT(board_error("9x6", 0.0), HasSubstr("expected a length > 0"));
  EXPECT_THAT(board_error("9x6", -0.02), HasSubstr("expected a length > 0"));
  EXPECT_THAT(board_error("9x6", std::nan("")), HasSubstr("expected a length > 0"));
}

TEST(BoardSpec, CornersRowByRow) {
  const BoardSpec board{4, 3, 0.5};
  const std::vector<cv::Point3f> points = board_object_points(board);
  ASSERT_EQ(points.size(), 12u);
  EXPECT_EQ(points[1], cv::Point3f(0.5f, 0.0f, 0.0f));
  EXPECT_EQ(points[4], cv::Point3f(0.0f, 0.5f, 0.0f));
  EXPECT_EQ(points[11], cv::Point3f(1.5f, 1.0f, 0.0f));
  EXPECT_EQ(board_corner(board, 11), Eigen::Vector3d(1.5, 1.0, 0.0));
  EXPECT_EQ(board_corner(board, 5), Eigen::Vector3d(0.5, 0.5, 0.0));
}

TEST(ImageFiles, ListsImagesSortedAndSkipsOtherFiles) {
  test::TempDir dir;
  for (const char* name : {"b.PNG", "a.jpg", "c.jpeg", "d.bmp", "notes.txt", "e.tiff", "camera.yaml"})
    test::write_text(dir / name, "x");
  std::filesystem::create_directory(dir / "sub.png");  // a folder, not a file
  test::write_text(dir / "sub.png" / "f.png", "x");
  const auto files = list_image_files(dir.path());
  ASSERT_EQ(files.size(), 4u);
  EXPECT_EQ(files[0].filename(), "a.jpg");
  EXPECT_EQ(files[1].filename(), "b.PNG");
  EXPECT_EQ(files[2].filename(), "c.jpeg");
  EXPECT_EQ(files[3].filename(), "d.bmp");
}

std::string listing_error(const std::filesystem::path& path) {
  try {
    list_image_files(path);
  } catch (const Error& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(ImageFiles, ErrorsNameTheFolder) {
  test::TempDir dir;
  EXPECT_THAT(listing_error(dir / "missing"), HasSubstr("missing: no such folder"));
  test::write_text(dir / "file.png", "x");
  EXPECT_THAT(listing_error(dir / "file.png"), HasSubstr("file.png: not a folder"));
  std::filesystem::create_directory(dir / "empty");
  EXPECT_THAT(listing_error(dir / "empty"), HasSubstr("empty: no image files"));
}

TEST(ViewQuality, CornerDistanceIgnoresNumberingDirection) {
  const std::vector<cv::Point2f> a = {{0, 0}, {10, 0}, {20, 0}, {30, 0}};
  std::vector<cv::Point2f> shifted = a;
  for (auto& p : shifted) p += cv::Point2f(0, 2);
  EXPECT_NEAR(mean_corner_distance(a, shifted), 2.0, 1e-6);
  const std::vector<cv::Point2f> reversed(shifted.rbegin(), shifted.rend());
  EXPECT_NEAR(mean_corner_distance(a, reversed), 2.0, 1e-6);
  EXPECT_THROW(mean_corner_distance(a, {{0, 0}}), Error);
}

TEST(ViewQuality, EdgeWidthGrowsWithBlur) {
  const cv::Mat& sharp = test::rendered_views(test::true_pinhole())[0];
  const auto detection = detect_board(sharp, test::test_board());
  ASSERT_TRUE(detection.has_value());
  const double sharp_width = board_edge_width(sharp, test::test_board(), detection->corners);
  cv::Mat blurred;
  cv::GaussianBlur(sharp, blurred, cv::Size(0, 0), 3.0);
  const double blurred_width = board_edge_width(blurred, test::test_board(), detection->corners);
  EXPECT_LT(sharp_width, QualityThresholds{}.max_edge_width_px);
  EXPECT_GT(blurred_width, QualityThresholds{}.max_edge_width_px);
}

TEST(BoardDetection, RefinedCornersLieNearTheTrueProjections) {
  const Camera camera = test::true_pinhole();
  const auto poses = test::scene_poses(camera);
  const BoardSpec board = test::test_board();
  for (std::size_t v = 0; v < poses.size(); ++v) {
    const auto detection = detect_board(test::rendered_views(camera)[v], board);
    ASSERT_TRUE(detection.has_value()) << "view " << v;
    // Corners may be numbered from either end: compare with the nearer order.
    double straight = 0.0, reversed = 0.0;
    const int n = board.corner_count();
    for (int k = 0; k < n; ++k) {
      const cv::Point2f& c = detection->corners[k];
      const Eigen::Vector2d found(c.x, c.y);
      straight += (found - camera.project(poses[v] * board_corner(board, k))).squaredNorm();
      reversed += (found - camera.project(poses[v] * board_corner(board, n - 1 - k))).squaredNorm();
    }
    EXPECT_LT(std::sqrt(std::min(straight, reversed) / n), 0.1) << "view " << v;
  }
}

TEST(BoardDetection, SubpixelWindowFollowsCornerSpacing) {
  const BoardSpec board{3, 2, 1.0};
  const auto grid = [&](float dx, float dy) {
    std::vector<cv::Point2f> corners;
    for (int j = 0; j < board.rows; ++j)
      for (int i = 0; i < board.cols; ++i) corners.emplace_back(i * dx, j * dy);
    return corners;
  };
  EXPECT_EQ(subpixel_half_window(grid(100, 100), board), 11);  // capped
  EXPECT_EQ(subpixel_half_window(grid(30, 20), board), 7);     // 0.35 x the shorter spacing
  EXPECT_EQ(subpixel_half_window(grid(5, 5), board), 3);       // floor
}

TEST(BoardDetection, NoBoardInAPlainImage) {
  EXPECT_FALSE(detect_board(cv::Mat(240, 320, CV_8UC1, cv::Scalar(90)), test::test_board()).has_value());
  EXPECT_THROW(detect_board(cv::Mat(240, 320, CV_8UC3, cv::Scalar(90, 90, 90)), test::test_board()), Error);
}

AcceptedView view_with(std::vector<cv::Point2f> corners) {
  AcceptedView view;
  view.corners = std::move(corners);
  return view;
}

TEST(Coverage, CountsCellsAndAreas) {
  const cv::Size size(800, 600);  // 100 x 100 px cells
  // Two corners in the top-left cell, one in the bottom-right one.
  const std::vector<AcceptedView> views = {view_with({{10, 10}, {90, 90}}), view_with({{790, 590}})};
  const CoverageFigures c = compute_coverage(views, size);
  EXPECT_DOUBLE_EQ(c.cell_fraction, 2.0 / 48.0);
  EXPECT_EQ(c.cell_counts[0], 2);
  EXPECT_EQ(c.cell_counts[47], 1);
  EXPECT_NEAR(c.bounding_box_fraction, 780.0 * 580.0 / (800.0 * 600.0), 1e-9);
  EXPECT_NEAR(c.hull_fraction, 8000.0 / (800.0 * 600.0), 1e-9);  // the triangle of the three corners
}

TEST(Coverage, CellOfPixelUsesPixelCentreConvention) {
  const cv::Size size(80, 60);  // 10 x 10 px cells
  EXPECT_EQ(coverage_cell({-0.5f, -0.5f}, size), cv::Point(0, 0));
  EXPECT_EQ(coverage_cell({9.4f, 9.4f}, size), cv::Point(0, 0));
  EXPECT_EQ(coverage_cell({9.6f, 9.6f}, size), cv::Point(1, 1));
  EXPECT_EQ(coverage_cell({79.5f, 59.5f}, size), cv::Point(7, 5));
  EXPECT_EQ(coverage_cell({500.0f, -40.0f}, size), cv::Point(7, 0));  // clamped
}

TEST(Coverage, FullFrameAndEmpty) {
  std::vector<cv::Point2f> corners;
  for (int y = 0; y < 6; ++y)
    for (int x = 0; x < 8; ++x) corners.emplace_back(x * 100.0f + 50.0f, y * 100.0f + 50.0f);
  corners.push_back({-0.5f, -0.5f});
  corners.push_back({799.5f, -0.5f});
  corners.push_back({-0.5f, 599.5f});
  corners.push_back({799.5f, 599.5f});
  const CoverageFigures full = compute_coverage({view_with(corners)}, {800, 600});
  EXPECT_DOUBLE_EQ(full.cell_fraction, 1.0);
  EXPECT_NEAR(full.bounding_box_fraction, 1.0, 1e-9);
  EXPECT_NEAR(full.hull_fraction, 1.0, 1e-9);
  const CoverageFigures none = compute_coverage({}, {800, 600});
  EXPECT_EQ(none.cell_fraction, 0.0);
  EXPECT_EQ(none.cell_counts.size(), 48u);
}

}  // namespace
}  // namespace facadeslam::calib
