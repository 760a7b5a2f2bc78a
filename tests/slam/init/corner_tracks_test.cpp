// KLT corner tracks on rendered plane sequences, where the true motion of
// every pixel is known.
#include "slam/init/corner_tracks.hpp"

#include <algorithm>
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

struct Sequence {
  Camera camera = test::plain_camera();
  test::TexturedPlane plane = test::facade_plane(test::synthetic_facade_texture(1000, 750, 7), 10.0, 0.0035);
  cv::Mat frame(int k) const { return test::render(camera, plane, test::sliding_camera(k)); }
};

TEST(CornerTracks, FollowTheTrueMotionOfAPlane) {
  const Sequence seq;
  const cv::Mat frame0 = seq.frame(0);
  const ImagePyramid pyramid(frame0);
  CornerTracks tracks;
  tracks.reset(frame0, pyramid.level(0).corners);
  const std::size_t started = tracks.size();
  ASSERT_GT(started, 300u);
  EXPECT_LE(started, 1000u);
  constexpr int kFrames = 12;
  for (int k = 1; k <= kFrames; ++k) tracks.track(seq.frame(k));
  EXPECT_EQ(tracks.frames_tracked(), kFrames);
  ASSERT_GT(tracks.size(), 0.8 * started);
  std::vector<double> errors;
  for (std::size_t i = 0; i < tracks.size(); ++i) {
    const Eigen::Vector2d truth = test::transfer(seq.camera, seq.plane, test::sliding_camera(0),
                                                 test::sliding_camera(kFrames), tracks.reference_pixels()[i]);
    errors.push_back((tracks.current_pixels()[i] - truth).norm());
  }
  const double median = test::percentile(errors, 0.5), p95 = test::percentile(errors, 0.95);
  std::printf("[ measured ] %zu of %zu tracks after %d frames, error median %.3f px, p95 %.3f px, motion %.1f px\n",
              tracks.size(), started, kFrames, median, p95, tracks.median_motion_px());
  EXPECT_LT(median, 0.15);
  EXPECT_LT(p95, 0.5);
  EXPECT_GT(tracks.median_motion_px(), 10.0);
  // The corner indices point back at the corners the tracks started from.
  for (std::size_t i = 0; i < tracks.size(); ++i) {
    const Corner& c = pyramid.level(0).corners[static_cast<std::size_t>(tracks.corner_indices()[i])];
    EXPECT_EQ(tracks.reference_pixels()[i], Eigen::Vector2d(c.x, c.y));
  }
}

// A region that changes completely (an occluder) kills the tracks inside it
// through the forward-backward check and keeps the others.
TEST(CornerTracks, OccludedTracksDie) {
  const Sequence seq;
  const cv::Mat frame0 = seq.frame(0);
  CornerTracks tracks;
  tracks.reset(frame0, ImagePyramid(frame0).level(0).corners);
  const std::vector<Eigen::Vector2d> before = tracks.reference_pixels();
  cv::Mat frame1 = frame0.clone();
  const cv::Rect occluder(200, 120, 240, 240);
  test::synthetic_facade_texture(occluder.width, occluder.height, 99).copyTo(frame1(occluder));
  tracks.track(frame1);
  const auto inside = [&](const Eigen::Vector2d& p, int margin) {
    return p.x() >= occluder.x + margin && p.y() >= occluder.y + margin &&
           p.x() < occluder.x + occluder.width - margin && p.y() < occluder.y + occluder.height - margin;
  };
  int inside_before = 0, outside_before = 0, inside_after = 0, outside_after = 0;
  // Tracks within a KLT half-window of the occluder's edge see both textures;
  // only those clearly inside or outside are counted.
  for (const Eigen::Vector2d& p : before) {
    inside_before += inside(p, 10) ? 1 : 0;
    outside_before += !inside(p, -10) ? 1 : 0;
  }
  for (const Eigen::Vector2d& p : tracks.reference_pixels()) {
    inside_after += inside(p, 10) ? 1 : 0;
    outside_after += !inside(p, -10) ? 1 : 0;
  }
  std::printf("[ measured ] occluded: %d of %d inside tracks survive, %d of %d outside\n", inside_after, inside_before,
              outside_after, outside_before);
  ASSERT_GT(inside_before, 30);
  EXPECT_LT(inside_after, 0.1 * inside_before);
  EXPECT_GT(outside_after, 0.97 * outside_before);
}

// The view slides over a larger texture by 25 px a frame (fast, for KLT's
// four levels): tracks that leave the image die, the others follow the
// slide exactly and respect the border.
TEST(CornerTracks, TracksLeavingTheImageDie) {
  const cv::Mat texture = test::synthetic_facade_texture(1000, 750, 7);
  constexpr int kFrames = 8;
  constexpr int kStep = 25;
  const auto frame = [&](int k) { return texture(cv::Rect(20 + kStep * k, 100, 640, 480)).clone(); };
  const cv::Mat frame0 = frame(0);
  CornerTrackOptions options;
  options.border_px = 3.0;
  CornerTracks tracks(options);
  const ImagePyramid pyramid(frame0);
  tracks.reset(frame0, pyramid.level(0).corners);
  const std::vector<Eigen::Vector2d> started = tracks.reference_pixels();
  for (int k = 1; k <= kFrames; ++k) tracks.track(frame(k));
  const double shift = kStep * kFrames;
  // Corners that stay clear of both edges (a KLT window from the left edge
  // after the slide, two windows from the right edge, where each frame's new
  // content enters) must survive.
  const auto well_inside = [&](const Eigen::Vector2d& p) { return p.x() - shift >= 15.0 && p.x() <= 600.0; };
  int inside_started = 0, inside_alive = 0;
  for (const Eigen::Vector2d& p : started) inside_started += well_inside(p) ? 1 : 0;
  for (const Eigen::Vector2d& p : tracks.reference_pixels()) inside_alive += well_inside(p) ? 1 : 0;
  std::printf("[ measured ] after sliding %.0f px: %zu of %zu tracks alive, %d of %d well inside\n", shift,
              tracks.size(), started.size(), inside_alive, inside_started);
  EXPECT_GE(inside_alive, 0.95 * inside_started);
  int left_the_image = 0;
  for (const Eigen::Vector2d& p : started) left_the_image += p.x() - shift < options.border_px ? 1 : 0;
  ASSERT_GT(left_the_image, 100);
  EXPECT_LE(tracks.size(), started.size() - left_the_image);
  for (std::size_t i = 0; i < tracks.size(); ++i) {
    const Eigen::Vector2d& p = tracks.current_pixels()[i];
    EXPECT_GE(p.x(), options.border_px);
    EXPECT_LE(p.x(), frame0.cols - 1 - options.border_px);
    EXPECT_NEAR(p.x(), tracks.reference_pixels()[i].x() - shift, 0.3);
    EXPECT_NEAR(p.y(), tracks.reference_pixels()[i].y(), 0.3);
  }
}

TEST(CornerTracks, KeepsAtMostMaxCornersSpreadOverTheImage) {
  const Sequence seq;
  const cv::Mat frame0 = seq.frame(0);
  const ImagePyramid pyramid(frame0);
  const std::vector<Corner>& corners = pyramid.level(0).corners;
  CornerTrackOptions options;
  options.max_corners = 100;
  CornerTracks tracks(options);
  tracks.reset(frame0, corners);
  ASSERT_GT(corners.size(), 100u);
  EXPECT_EQ(tracks.size(), 100u);
  // Spread: every quarter of the image holds some of them.
  int quarter[4] = {0, 0, 0, 0};
  for (const Eigen::Vector2d& p : tracks.reference_pixels())
    ++quarter[(p.x() < frame0.cols / 2.0 ? 0 : 1) + (p.y() < frame0.rows / 2.0 ? 0 : 2)];
  for (int q : quarter) EXPECT_GT(q, 10);
}

TEST(SpreadStrongestCorners, TakesEveryCellsBestBeforeAnyCellsSecond) {
  // Cell (0,0) holds five strong corners, cell (1,0) two weak ones.
  std::vector<Corner> corners;
  corners.reserve(7);
  for (int i = 0; i < 5; ++i) corners.push_back({2 + i, 3, 100.f - i});
  corners.push_back({45, 3, 5.f});
  corners.push_back({46, 9, 4.f});
  const std::vector<int> chosen = spread_strongest_corners(corners, 4, 40);
  EXPECT_EQ(chosen, (std::vector<int>{0, 5, 1, 6}));
  EXPECT_EQ(spread_strongest_corners(corners, 100, 40).size(), 7u);
  EXPECT_TRUE(spread_strongest_corners(corners, 0, 40).empty());
}

TEST(SpreadStrongestCorners, EqualScoresAreOrderedByPosition) {
  const std::vector<Corner> corners{{30, 5, 1.f}, {10, 5, 1.f}, {20, 1, 1.f}};
  EXPECT_EQ(spread_strongest_corners(corners, 3, 100), (std::vector<int>{2, 1, 0}));
}

TEST(CornerTracksDeathTest, TrackBeforeResetIsAnInternalError) {
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  CornerTracks tracks;
  const cv::Mat grey(480, 640, CV_8UC1, cv::Scalar(0));
  EXPECT_DEATH(tracks.track(grey), "internal error.*reset\\(\\) on a reference before track\\(\\)");
}

TEST(CornerTracks, WrongImagesThrow) {
  CornerTracks tracks;
  const cv::Mat grey(480, 640, CV_8UC1, cv::Scalar(0));
  EXPECT_NE(error_of([&] { tracks.reset(cv::Mat(), {}); }).find("8-bit single-channel"), std::string::npos);
  EXPECT_NE(error_of([&] { tracks.reset(cv::Mat(480, 640, CV_8UC3), {}); }).find("8-bit single-channel"),
            std::string::npos);
  tracks.reset(grey, {});
  EXPECT_NE(error_of([&] { tracks.track(cv::Mat(240, 320, CV_8UC1, cv::Scalar(0))); }).find("320x240"),
            std::string::npos);
  EXPECT_NE(error_of([&] { tracks.track(cv::Mat(480, 640, CV_16UC1)); }).find("8-bit single-channel"),
            std::string::npos);
  // No corners: tracking works and keeps nothing.
  EXPECT_EQ(tracks.track(grey), 0u);
  EXPECT_EQ(tracks.median_motion_px(), 0.0);
}

TEST(CornerTracks, CornerOutsideTheImageThrows) {
  CornerTracks tracks;
  const cv::Mat grey(480, 640, CV_8UC1, cv::Scalar(0));
  EXPECT_NE(error_of([&] { tracks.reset(grey, {{640, 10, 1.f}}); }).find("outside the 640x480"), std::string::npos);
  EXPECT_NE(error_of([&] { tracks.reset(grey, {{3, -1, 1.f}}); }).find("outside"), std::string::npos);
}

TEST(CornerTracks, OptionsOutOfRangeThrow) {
  CornerTrackOptions even_window;
  even_window.window_size = 20;
  EXPECT_NE(error_of([&] { CornerTracks t(even_window); }).find("tracking.window_size"), std::string::npos);
  CornerTrackOptions no_fb;
  no_fb.max_forward_backward_px = 0.0;
  EXPECT_NE(error_of([&] { CornerTracks t(no_fb); }).find("tracking.max_forward_backward_px"), std::string::npos);
  CornerTrackOptions levels;
  levels.max_level = -1;
  EXPECT_NE(error_of([&] { CornerTracks t(levels); }).find("tracking.max_level"), std::string::npos);
}

}  // namespace
}  // namespace facadeslam
