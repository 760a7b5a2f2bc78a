#pragma once
// Synthetic patches and images for the descriptor tests.
#include <cmath>
#include <functional>
#include <initializer_list>

#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include "semantics/descriptor/descriptor_params.hpp"
#include "semantics/descriptor/module_layout.hpp"
#include "semantics/descriptor/padded_plane.hpp"
#include "semantics/descriptor/prepared_image.hpp"
#include "tests/support/random_rectangles.hpp"

namespace facadeslam::semantics::test_util {

// `base` with exactly the named values active.
inline DescriptorParams with_values(std::initializer_list<const char*> names, DescriptorParams base = {}) {
  base.activation.reset();
  for (const char* name : names) base.activation.set(static_cast<std::size_t>(value_index(name).value()));
  return base;
}

// A (2r+1)^2 CV_32F patch with f(dx, dy) at offset (dx, dy) from the centre.
inline cv::Mat patch_from(int r, const std::function<double(double, double)>& f) {
  cv::Mat p(2 * r + 1, 2 * r + 1, CV_32F);
  for (int y = 0; y < p.rows; ++y)
    for (int x = 0; x < p.cols; ++x) p.at<float>(y, x) = static_cast<float>(f(x - r, y - r));
  return p;
}

// The average of f over each pixel (s x s samples), for smooth shapes whose
// moments should not depend on where pixel centres fall.
inline cv::Mat supersampled_patch(int r, const std::function<double(double, double)>& f, int s = 8) {
  return patch_from(r, [&](double x, double y) {
    double sum = 0;
    for (int i = 0; i < s; ++i)
      for (int j = 0; j < s; ++j) sum += f(x - 0.5 + (i + 0.5) / s, y - 0.5 + (j + 0.5) / s);
    return sum / (s * s);
  });
}

// A deterministic textured BGR image: smooth colour gradients, rectangles and noise.
inline cv::Mat textured_image(cv::Size size, unsigned seed = 1) {
  cv::Mat image(size, CV_8UC3);
  cv::RNG rng(seed);
  for (int y = 0; y < size.height; ++y)
    for (int x = 0; x < size.width; ++x)
      image.at<cv::Vec3b>(y, x) =
          cv::Vec3b(static_cast<uchar>(40 + (x * 3) % 160), static_cast<uchar>(60 + (y * 2) % 150),
                    static_cast<uchar>(90 + ((x + y) % 120)));
  test::paint_random_rectangles(image, rng, 60, 0, 3, 30);
  cv::Mat noise(size, CV_8UC3);
  rng.fill(noise, cv::RNG::UNIFORM, cv::Scalar::all(0), cv::Scalar::all(12));
  cv::add(image, noise, image);
  return image;
}

// A prepared image holding one hand-made plane (interior = `plane`).
inline PreparedImage image_with_plane(PlaneId id, const cv::Mat& plane, int border) {
  PreparedImage image;
  image.image_size = plane.size();
  image.border = border;
  image.params.patch_radius = border;
  cv::Mat padded = make_padded_plane(plane.size(), border);
  plane.copyTo(plane_interior(padded, border));
  fill_border_reflect101(padded, border);
  image.planes[plane_bit(id)] = padded;
  image.computed.set(plane_bit(id));
  return image;
}

}  // namespace facadeslam::semantics::test_util
