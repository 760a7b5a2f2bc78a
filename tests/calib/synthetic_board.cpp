#include "tests/calib/synthetic_board.hpp"

#include <array>
#include <cmath>
#include <cstdint>
#include <numbers>

#include <Eigen/Geometry>
#include <opencv2/imgproc.hpp>

namespace facadeslam::test {
namespace {

constexpr double kBlack = 25.0, kWhite = 230.0, kBackground = 120.0;

double board_intensity(const calib::BoardSpec& board, double x, double y) {
  const double ix = std::floor(x / board.square);
  const double iy = std::floor(y / board.square);
  if (ix >= -1 && ix <= board.cols - 1 && iy >= -1 && iy <= board.rows - 1)
    return (static_cast<long>(ix + iy) % 2 == 0) ? kBlack : kWhite;
  if (ix >= -2 && ix <= board.cols && iy >= -2 && iy <= board.rows) return kWhite;  // margin
  return kBackground;
}

// A deterministic value in [0, 1) per pixel and sample (a 64-bit integer
// hash, SplitMix64's finaliser), so renders are identical on every run.
double jitter(int x, int y, int k) {
  std::uint64_t z =
      (static_cast<std::uint64_t>(y) << 40) ^ (static_cast<std::uint64_t>(x) << 16) ^ static_cast<std::uint64_t>(k);
  z += 0x9e3779b97f4a7c15ULL;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  z ^= z >> 31;
  return static_cast<double>(z >> 11) * 0x1.0p-53;
}

}  // namespace

std::vector<cv::Mat> render_board_views(const Camera& camera, const calib::BoardSpec& board,
                                        const std::vector<SE3d>& T_c_b, int samples_per_axis,
                                        double optics_blur_sigma) {
  const int n = samples_per_axis;
  std::vector<cv::Mat> images;
  for (std::size_t v = 0; v < T_c_b.size(); ++v) images.emplace_back(camera.height(), camera.width(), CV_8UC1);
  // Per view: the plane normal in the camera frame, its offset, and the
  // inverse pose to take intersections back to board coordinates.
  std::vector<Eigen::Vector3d> normals;
  std::vector<double> offsets;
  std::vector<SE3d> T_b_c;
  for (const SE3d& pose : T_c_b) {
    normals.push_back(pose.rotation_matrix().col(2));
    offsets.push_back(normals.back().dot(pose.translation()));
    T_b_c.push_back(pose.inverse());
  }
  std::vector<double> sums(T_c_b.size());
  for (int y = 0; y < camera.height(); ++y)
    for (int x = 0; x < camera.width(); ++x) {
      std::fill(sums.begin(), sums.end(), 0.0);
      for (int sy = 0; sy < n; ++sy)
        for (int sx = 0; sx < n; ++sx) {
          // The pixel's area is [x - 0.5, x + 0.5], split into n x n cells
          // with one sample at a jittered place in each: on a regular grid
          // every pixel along an edge would quantise its position the same
          // way, biasing the detected corners by up to 1/(2n) px.
          const double jx = jitter(x, y, 2 * (sy * n + sx));
          const double jy = jitter(x, y, 2 * (sy * n + sx) + 1);
          const Eigen::Vector2d px(x - 0.5 + (sx + jx) / n, y - 0.5 + (sy + jy) / n);
          const Eigen::Vector3d ray = camera.unproject(px);
          for (std::size_t v = 0; v < T_c_b.size(); ++v) {
            const double denominator = normals[v].dot(ray);
            const double lambda = std::abs(denominator) > 1e-12 ? offsets[v] / denominator : -1.0;
            if (lambda <= 0.0) {
              sums[v] += kBackground;
              continue;
            }
            const Eigen::Vector3d p_b = T_b_c[v] * (lambda * ray);
            sums[v] += board_intensity(board, p_b.x(), p_b.y());
          }
        }
      for (std::size_t v = 0; v < T_c_b.size(); ++v)
        images[v].at<unsigned char>(y, x) = cv::saturate_cast<unsigned char>(sums[v] / (n * n));
    }
  if (optics_blur_sigma > 0.0)
    for (cv::Mat& image : images) cv::GaussianBlur(image, image, cv::Size(0, 0), optics_blur_sigma);
  return images;
}

std::vector<SE3d> varied_board_poses(const Camera& camera, const calib::BoardSpec& board, int count,
                                     double width_fraction) {
  // Aim points (fractions of the image) and tilts (degrees about the board's
  // x and y axes, and roll about the optical axis).
  struct Layout {
    double u, v, tilt_x, tilt_y, roll;
  };
  constexpr std::array<Layout, 12> kLayouts = {{{0.50, 0.50, 0, 25, 0},
                                                {0.30, 0.32, 20, -20, 10},
                                                {0.70, 0.32, 20, 25, -10},
                                                {0.30, 0.68, -25, -20, -5},
                                                {0.70, 0.68, -20, 20, 5},
                                                {0.50, 0.30, 35, 0, 15},
                                                {0.50, 0.70, -30, 5, -15},
                                                {0.28, 0.50, 5, -35, 20},
                                                {0.72, 0.50, -5, 30, -20},
                                                {0.50, 0.50, 15, -15, 40},
                                                {0.40, 0.42, -15, 10, -30},
                                                {0.60, 0.58, 10, -10, 25}}};
  const double deg = std::numbers::pi / 180.0;
  const double board_width = (board.cols + 3) * board.square;  // squares plus the margin
  const double depth = camera.fx() * board_width / (width_fraction * camera.width());
  const Eigen::Vector3d centre_b((board.cols - 1) * board.square / 2.0, (board.rows - 1) * board.square / 2.0, 0.0);
  std::vector<SE3d> poses;
  for (int i = 0; i < count && i < static_cast<int>(kLayouts.size()); ++i) {
    const Layout& l = kLayouts[i];
    const Eigen::Matrix3d r = (Eigen::AngleAxisd(l.roll * deg, Eigen::Vector3d::UnitZ()) *
                               Eigen::AngleAxisd(l.tilt_x * deg, Eigen::Vector3d::UnitX()) *
                               Eigen::AngleAxisd(l.tilt_y * deg, Eigen::Vector3d::UnitY()))
                                  .toRotationMatrix();
    const Eigen::Vector3d aim = depth * camera.unproject({l.u * (camera.width() - 1), l.v * (camera.height() - 1)});
    poses.emplace_back(r, aim - r * centre_b);
  }
  return poses;
}

}  // namespace facadeslam::test
