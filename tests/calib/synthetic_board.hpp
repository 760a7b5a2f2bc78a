#pragma once
// Chessboard images rendered through a known camera, for calibration tests
// with exact ground truth. Each output pixel is split into n x n samples;
// each sample's ray (the camera's own unproject(), so the image is warped by
// exactly the model being calibrated) is intersected with the board plane
// and takes the colour of the board there. The mean over the samples
// anti-aliases the edges, so the detector's sub-pixel corners land within a
// few hundredths of a pixel of the true projections.
//
// The board: (cols + 1) x (rows + 1) black and white squares around the
// inner corners (corner (i, j) at (i s, j s, 0) as calib::board_corner), a
// white margin one square wide, and a mid-grey background beyond.
#include <vector>

#include <opencv2/core.hpp>

#include "calib/board.hpp"
#include "core/camera/camera.hpp"
#include "core/lie/se3.hpp"

namespace facadeslam::test {

// One 8-bit grey image per pose, all rendered in one pass over the pixels
// (the rays do not depend on the pose). `optics_blur_sigma` (pixels, 0 =
// none) then blurs the image with a Gaussian, standing in for a real lens's
// point spread: real boards show 2.5-3.5 px wide edges (OpenCV's samples),
// and razor-sharp edges bias cv::cornerSubPix more than real images do.
std::vector<cv::Mat> render_board_views(const Camera& camera, const calib::BoardSpec& board,
                                        const std::vector<SE3d>& T_c_b, int samples_per_axis = 3,
                                        double optics_blur_sigma = 1.0);

// `count` (<= 12) board poses with the board's centre aimed at points
// spread over the image and tilted by 15-35 degrees in varying directions, at
// a distance where the board spans about `width_fraction` of the image
// width; the whole board with its margin stays inside the image.
std::vector<SE3d> varied_board_poses(const Camera& camera, const calib::BoardSpec& board, int count,
                                     double width_fraction = 0.55);

}  // namespace facadeslam::test
