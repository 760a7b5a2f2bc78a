#pragma once
// Random filled rectangles, the corner-rich texture several tests draw on.
#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

namespace facadeslam::test {

// Paints `count` filled rectangles of random colour on `image`: the top-left
// corner uniform in [origin_lo, cols) x [origin_lo, rows), the sides in
// [side_lo, side_hi). The numbers are drawn one statement at a time, in
// reading order: drawn as the arguments of one call, their order would be
// the compiler's (GCC right to left, clang left to right), and the test's
// image with it.
inline void paint_random_rectangles(cv::Mat& image, cv::RNG& rng, int count, int origin_lo, int side_lo, int side_hi) {
  for (int i = 0; i < count; ++i) {
    const int x = rng.uniform(origin_lo, image.cols);
    const int y = rng.uniform(origin_lo, image.rows);
    const int width = rng.uniform(side_lo, side_hi);
    const int height = rng.uniform(side_lo, side_hi);
    const int blue = rng.uniform(0, 255);
    const int green = rng.uniform(0, 255);
    const int red = rng.uniform(0, 255);
    cv::rectangle(image, cv::Rect(x, y, width, height), cv::Scalar(blue, green, red), cv::FILLED);
  }
}

}  // namespace facadeslam::test
