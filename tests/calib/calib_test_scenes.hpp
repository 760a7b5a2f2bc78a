#pragma once
// The cameras, board and rendered views shared by the calibration tests.
// Rendering is the slow part, so each camera's views are rendered once per
// ctest run (cached in the build tree, see CMakeLists.txt) and kept in memory.
#include <cstddef>
#include <filesystem>
#include <vector>

#include <opencv2/core.hpp>

#include "calib/board.hpp"
#include "calib/view_collection.hpp"
#include "core/camera/camera.hpp"
#include "core/lie/se3.hpp"

namespace facadeslam::test {

// 9 x 6 inner corners, 30 mm squares.
calib::BoardSpec test_board();

// 640 x 480, fx 520, fy 516, cx 323.5, cy 238.2, k1 -0.22, k2 0.07,
// p1 0.0008, p2 -0.0006, k3 0.
Camera true_pinhole();

// 640 x 480, fx 410, fy 408, cx 318, cy 242, w 0.9.
Camera true_atan();

// The board poses used for `camera` (test::varied_board_poses, 10 views).
std::vector<SE3d> scene_poses(const Camera& camera);

// Ten views of test_board() rendered through `camera` at scene_poses().
const std::vector<cv::Mat>& rendered_views(const Camera& camera);

// Writes a PNG (fails the current test if it cannot).
void write_png(const std::filesystem::path& path, const cv::Mat& image);

// view_00.png, view_01.png, ... in `folder`: the first `count` images.
void write_views(const std::filesystem::path& folder, const std::vector<cv::Mat>& images, std::size_t count);

// Views whose corners are the exact projections of the board at `poses`,
// plus Gaussian noise of `noise_px` (fixed seed): calibration input without
// any image (fast tests of the fits and the reports).
std::vector<calib::AcceptedView> projected_views(const Camera& camera, const std::vector<SE3d>& poses, double noise_px);

}  // namespace facadeslam::test
