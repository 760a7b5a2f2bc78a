// Labels and depth against an independent CPU ray caster: for every pixel,
// the ray of its centre is intersected with the same quads, and the class is
// read from the label map at the texel hit. Pixels next to a label or
// surface boundary are left out (the renderer and the reference may
// legitimately round a ray lying on a boundary to either side).
#include <algorithm>
#include <cmath>
#include <memory>
#include <iostream>
#include <random>

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

#include "render/distortion_resampler.hpp"
#include "render/offscreen_renderer.hpp"
#include "tests/render/render_test_scenes.hpp"

namespace facadeslam {
namespace {

// A label map of random rectangles and ellipses over a building-class
// background, the way facade label maps look.
cv::Mat random_label_map(int width, int height, unsigned seed, bool with_holes) {
  std::mt19937 rng(seed);
  cv::Mat labels(height, width, CV_8UC1, cv::Scalar(1));
  std::uniform_int_distribution<int> x(0, width - 1), y(0, height - 1), size(4, width / 5), cls(0, 8);
  for (int i = 0; i < 60; ++i) {
    const cv::Point p(x(rng), y(rng));
    const int value = cls(rng);
    if (i % 2)
      cv::rectangle(labels, cv::Rect(p, cv::Size(size(rng), size(rng))), value, cv::FILLED);
    else
      cv::ellipse(labels, p, cv::Size(size(rng), size(rng)), 30.0 * i, 0, 360, value, cv::FILLED);
  }
  if (with_holes) cv::circle(labels, {width / 2, height / 2}, width / 4, render::kTransparentLabel, cv::FILLED);
  return labels;
}

struct Agreement {
  long compared = 0;
  long agreeing = 0;
  double worst_depth_error = 0.0;  // relative
  double share() const { return compared ? double(agreeing) / compared : 0.0; }
};

// Depth is resampled at the nearest pixel of the wider pinhole image for a
// distorted camera (`resampler` not null): its reference is the ray of that
// virtual pixel.
Eigen::Vector3d depth_ray(const Camera& camera, const render::DistortionResampler* resampler, int x, int y) {
  if (!resampler) return camera.unproject(Eigen::Vector2d(x, y));
  const render::PinholeIntrinsics& v = resampler->virtual_camera();
  const cv::Vec2d s = resampler->source(x, y);
  const double sx = std::floor(s[0] + 0.5), sy = std::floor(s[1] + 0.5);
  return {(sx - v.cx) / v.fx, (sy - v.cy) / v.fy, 1.0};
}

Agreement compare_with_reference(const Camera& camera, const Eigen::Isometry3d& T_w_c, int border,
                                 const std::vector<test::ReferenceQuad>& quads) {
  render::Renderer renderer;
  render::Scene scene;
  scene.background_label = 200;
  for (const auto& q : quads) {
    const cv::Mat texture(std::max(q.labels.rows, 4), std::max(q.labels.cols, 4), CV_8UC3, cv::Scalar(90, 90, 90));
    const auto labels = q.labels.empty() ? render::TextureId{} : renderer.add_label_texture(q.labels);
    scene.meshes.push_back(
        render::make_textured_quad(q.top_left, q.right, q.down, renderer.add_colour_texture(texture), labels, q.label));
  }
  const auto out = renderer.render(scene, camera, T_w_c);

  std::unique_ptr<render::DistortionResampler> resampler;
  if (render::needs_resampling(camera)) resampler = std::make_unique<render::DistortionResampler>(camera);
  cv::Mat ref_label(camera.height(), camera.width(), CV_8UC1), ref_quad(ref_label.size(), CV_32SC1);
  cv::Mat ref_z(ref_label.size(), CV_64FC1);
  for (int y = 0; y < camera.height(); ++y)
    for (int x = 0; x < camera.width(); ++x) {
      const test::ReferenceHit hit = test::cast_ray(quads, camera, T_w_c, x, y);
      ref_label.at<std::uint8_t>(y, x) = hit.quad >= 0 ? hit.label : 200;
      ref_quad.at<int>(y, x) = hit.quad;
      ref_z.at<double>(y, x) = test::cast_ray(quads, T_w_c, depth_ray(camera, resampler.get(), x, y)).z;
    }
  Agreement result;
  for (int y = border; y < camera.height() - border; ++y)
    for (int x = border; x < camera.width() - border; ++x) {
      bool interior = true;
      for (int dy = -border; dy <= border && interior; ++dy)
        for (int dx = -border; dx <= border && interior; ++dx)
          interior = ref_label.at<std::uint8_t>(y + dy, x + dx) == ref_label.at<std::uint8_t>(y, x) &&
                     ref_quad.at<int>(y + dy, x + dx) == ref_quad.at<int>(y, x);
      if (!interior) continue;
      ++result.compared;
      if (out.labels.at<std::uint8_t>(y, x) == ref_label.at<std::uint8_t>(y, x)) ++result.agreeing;
      const double z = ref_z.at<double>(y, x);
      const double got = out.depth.at<float>(y, x);
      const double error = z == 0.0 ? std::abs(got) : std::abs(got - z) / z;
      result.worst_depth_error = std::max(result.worst_depth_error, error);
    }
  return result;
}

std::vector<test::ReferenceQuad> street_corner() {
  return {
      // A facade along the x axis facing -y, and another turned by 30 degrees.
      {{0, 6, 9}, {14, 0, 0}, {0, 0, -9}, random_label_map(700, 450, 1, false), 0},
      {{14, 6, 9}, {10 * std::cos(0.52), -10 * std::sin(0.52), 0}, {0, 0, -9}, random_label_map(500, 450, 2, false), 0},
      // The road.
      {{-5, 6, 0}, {30, 0, 0}, {0, -14, 0}, {}, 5},
      // A cut-out in front (a tree with a hole in the middle).
      {{6, 2, 4}, {4, 0, 0}, {0, 0, -4}, random_label_map(200, 200, 3, true), 0},
  };
}

TEST(LabelDepth, PinholeAgreesWithTheRayCaster) {
  const Camera camera(640, 480, PinholeRadTan{.fx = 500, .fy = 500, .cx = 319.5, .cy = 239.5});
  const Eigen::Isometry3d T_w_c = test::look_at({2, -1.5, 1.6}, {10, 5, 3});
  const Agreement a = compare_with_reference(camera, T_w_c, 1, street_corner());
  std::cout << "[ labels ] pinhole: " << 100.0 * a.share() << " % of " << a.compared
            << " interior pixels agree; worst relative depth error " << a.worst_depth_error << "\n";
  EXPECT_GT(a.compared, 640 * 480 / 2);
  EXPECT_GE(a.share(), 0.999);
  EXPECT_LT(a.worst_depth_error, 1e-5);
}

TEST(LabelDepth, DistortedCameraAgreesWithTheRayCaster) {
  const Camera camera(
      640, 480,
      PinholeRadTan{
          .fx = 480, .fy = 482, .cx = 322.4, .cy = 236.8, .k1 = -0.28, .k2 = 0.09, .p1 = 0.001, .p2 = -0.0008});
  const Eigen::Isometry3d T_w_c = test::look_at({1, -2, 1.4}, {12, 4, 2.5});
  // Nearest-pixel resampling moves a sample by up to half a virtual pixel,
  // so the boundary band for labels is wider.
  const Agreement a = compare_with_reference(camera, T_w_c, 2, street_corner());
  std::cout << "[ labels ] distorted: " << 100.0 * a.share() << " % of " << a.compared
            << " interior pixels agree; worst relative depth error " << a.worst_depth_error << "\n";
  EXPECT_GT(a.compared, 640 * 480 / 2);
  EXPECT_GE(a.share(), 0.995);
  EXPECT_LT(a.worst_depth_error, 1e-5);
}

}  // namespace
}  // namespace facadeslam
