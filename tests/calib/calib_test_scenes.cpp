#include "tests/calib/calib_test_scenes.hpp"

#include <cstdio>
#include <string>
#include <utility>

#include <gtest/gtest.h>
#include <opencv2/imgcodecs.hpp>

#include "core/util/atomic_write.hpp"
#include "tests/calib/synthetic_board.hpp"

namespace facadeslam::test {

calib::BoardSpec test_board() { return {9, 6, 0.03}; }

Camera true_pinhole() {
  PinholeRadTan m;
  m.fx = 520.0;
  m.fy = 516.0;
  m.cx = 323.5;
  m.cy = 238.2;
  m.k1 = -0.22;
  m.k2 = 0.07;
  m.p1 = 0.0008;
  m.p2 = -0.0006;
  return Camera(640, 480, m);
}

Camera true_atan() {
  return Camera(640, 480, AtanCamera{.fx = 410.0, .fy = 408.0, .cx = 318.0, .cy = 242.0, .w = 0.9});
}

std::vector<SE3d> scene_poses(const Camera& camera) { return varied_board_poses(camera, test_board(), 10); }

namespace {

std::filesystem::path cached_view_path(const Camera& camera, std::size_t view) {
  char name[32];
  std::snprintf(name, sizeof name, "view_%02zu.png", view);
  return std::filesystem::path(FACADESLAM_CALIB_RENDER_CACHE) / camera.model_name() / name;
}

// The views another test process of this ctest run already rendered, or an
// empty vector. PNG is lossless, so a cached view equals a fresh render.
std::vector<cv::Mat> load_cached_views(const Camera& camera, std::size_t count) {
  std::vector<cv::Mat> images;
  for (std::size_t v = 0; v < count; ++v) {
    cv::Mat image = cv::imread(cached_view_path(camera, v).string(), cv::IMREAD_UNCHANGED);
    if (image.empty() || image.cols != camera.width() || image.rows != camera.height()) return {};
    images.push_back(image);
  }
  return images;
}

// Each file appears whole or not at all (temporary file + rename), so a
// process reading while another writes sees either nothing or a full image.
void store_cached_views(const Camera& camera, const std::vector<cv::Mat>& images) {
  for (std::size_t v = 0; v < images.size(); ++v)
    write_file_atomically(cached_view_path(camera, v),
                          [&](const std::filesystem::path& tmp) { cv::imwrite(tmp.string(), images[v]); });
}

}  // namespace

const std::vector<cv::Mat>& rendered_views(const Camera& camera) {
  static std::vector<std::pair<std::string, std::vector<cv::Mat>>> cache;
  for (const auto& [name, images] : cache)
    if (name == camera.model_name()) return images;
  const std::vector<SE3d> poses = scene_poses(camera);
  std::vector<cv::Mat> images = load_cached_views(camera, poses.size());
  if (images.empty()) {
    images = render_board_views(camera, test_board(), poses);
    store_cached_views(camera, images);
  }
  cache.emplace_back(camera.model_name(), std::move(images));
  return cache.back().second;
}

void write_png(const std::filesystem::path& path, const cv::Mat& image) {
  ASSERT_TRUE(cv::imwrite(path.string(), image)) << path;
}

void write_views(const std::filesystem::path& folder, const std::vector<cv::Mat>& images, std::size_t count) {
  for (std::size_t i = 0; i < count && i < images.size(); ++i) {
    char name[32];
    std::snprintf(name, sizeof name, "view_%02zu.png", i);
    write_png(folder / name, images[i]);
  }
}

std::vector<calib::AcceptedView> projected_views(const Camera& camera, const std::vector<SE3d>& poses,
                                                 double noise_px) {
  const calib::BoardSpec board = test_board();
  cv::RNG rng(12345);
  std::vector<calib::AcceptedView> views;
  for (std::size_t v = 0; v < poses.size(); ++v) {
    calib::AcceptedView view;
    view.file = "projected_" + std::to_string(v) + ".png";
    view.edge_width_px = 2.0;
    for (int k = 0; k < board.corner_count(); ++k) {
      const Eigen::Vector2d px = camera.project(poses[v] * calib::board_corner(board, k));
      view.corners.emplace_back(static_cast<float>(px.x() + rng.gaussian(noise_px)),
                                static_cast<float>(px.y() + rng.gaussian(noise_px)));
    }
    views.push_back(std::move(view));
  }
  return views;
}

}  // namespace facadeslam::test
