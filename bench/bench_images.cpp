#include "bench/bench_images.hpp"

#include <cstdlib>
#include <filesystem>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "tests/support/random_rectangles.hpp"

namespace facadeslam::bench {

cv::Mat facade_image(cv::Size size, std::string* source) {
  const char* root = std::getenv("FACADESLAM_SOURCE_DIR");
  const std::filesystem::path photo =
      std::filesystem::path(root ? root : ".") / "../shared/data/opencv-samples/building.jpg";
  cv::Mat image = cv::imread(photo.string(), cv::IMREAD_COLOR);
  if (!image.empty()) {
    cv::resize(image, image, size, 0, 0, cv::INTER_AREA);
    if (source) *source = photo.lexically_normal().string();
    return image;
  }
  image.create(size, CV_8UC3);
  cv::RNG rng(12345);
  rng.fill(image, cv::RNG::UNIFORM, cv::Scalar::all(90), cv::Scalar::all(160));
  test::paint_random_rectangles(image, rng, 400, 0, 4, 40);
  cv::GaussianBlur(image, image, cv::Size(3, 3), 0.8);
  if (source) *source = "synthetic texture";
  return image;
}

std::vector<cv::Point2f> grid_points(cv::Size size, int step) {
  std::vector<cv::Point2f> points;
  for (int y = 0; y < size.height; y += step)
    for (int x = 0; x < size.width; x += step) points.emplace_back(static_cast<float>(x), static_cast<float>(y));
  return points;
}

}  // namespace facadeslam::bench
