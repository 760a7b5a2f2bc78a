#include "core/image/small_blurry_image.hpp"

#include <cmath>

#include <Eigen/Dense>
#include <opencv2/imgproc.hpp>

#include "core/image/half_sample.hpp"
#include "core/util/error.hpp"

namespace facadeslam {

cv::Mat make_small_blurry_image(const ImagePyramid& pyramid, const SmallBlurryImageOptions& options) {
  const cv::Mat small = half_sample(pyramid.level(kPyramidLevels - 1).image);
  cv::Mat sbi;
  small.convertTo(sbi, CV_32F);
  cv::GaussianBlur(sbi, sbi, cv::Size(0, 0), options.blur_sigma, options.blur_sigma, cv::BORDER_REPLICATE);
  sbi -= cv::mean(sbi)[0];
  return sbi;
}

double sbi_difference(const cv::Mat& a, const cv::Mat& b) {
  if (a.size() != b.size() || a.type() != CV_32FC1 || b.type() != CV_32FC1)
    throw Error("sbi_difference: small blurry images of different sizes or types");
  return cv::norm(a, b, cv::NORM_L2SQR);
}

namespace {

float sample(const cv::Mat& img, double x, double y) {
  // Bilinear, clamped at the border (the SBI is blurred, so clamping is mild).
  x = std::clamp(x, 0.0, img.cols - 1.001);
  y = std::clamp(y, 0.0, img.rows - 1.001);
  const int x0 = static_cast<int>(x), y0 = static_cast<int>(y);
  const float fx = static_cast<float>(x - x0), fy = static_cast<float>(y - y0);
  const float* r0 = img.ptr<float>(y0);
  const float* r1 = img.ptr<float>(y0 + 1);
  return (1 - fy) * ((1 - fx) * r0[x0] + fx * r0[x0 + 1]) + fy * ((1 - fx) * r1[x0] + fx * r1[x0 + 1]);
}

}  // namespace

Se2Motion align_small_blurry_images(const cv::Mat& reference, const cv::Mat& current, int iterations) {
  if (reference.size() != current.size()) throw Error("align_small_blurry_images: size mismatch");
  cv::Mat gx, gy;
  cv::Sobel(reference, gx, CV_32F, 1, 0, 3, 1.0 / 8.0);
  cv::Sobel(reference, gy, CV_32F, 0, 1, 3, 1.0 / 8.0);
  const Eigen::Vector2d c((reference.cols - 1) / 2.0, (reference.rows - 1) / 2.0);

  // Parameters: theta, tx, ty, and a brightness offset; Gauss-Newton with the
  // reference gradients warped along (a forward-additive scheme, fine for the
  // small motions the blur makes visible).
  Eigen::Vector4d params = Eigen::Vector4d::Zero();
  double rms = 0;
  for (int it = 0; it < iterations; ++it) {
    Eigen::Matrix4d H = Eigen::Matrix4d::Zero();
    Eigen::Vector4d g = Eigen::Vector4d::Zero();
    const double ct = std::cos(params[0]), st = std::sin(params[0]);
    double sum_sq = 0;
    int n = 0;
    // Skip a margin: near the edges the blur has mixed in replicated border
    // pixels, which do not move with the scene.
    constexpr int kMargin = 3;
    for (int y = kMargin; y < current.rows - kMargin; ++y)
      for (int x = kMargin; x < current.cols - kMargin; ++x) {
        const Eigen::Vector2d d(x - c.x(), y - c.y());
        const Eigen::Vector2d w(ct * d.x() - st * d.y() + c.x() + params[1],
                                st * d.x() + ct * d.y() + c.y() + params[2]);
        const double r = sample(reference, w.x(), w.y()) + params[3] - current.at<float>(y, x);
        const Eigen::Vector2d grad(sample(gx, w.x(), w.y()), sample(gy, w.x(), w.y()));
        // d w / d theta = (-st dx - ct dy, ct dx - st dy)
        const Eigen::Vector2d dw_dtheta(-st * d.x() - ct * d.y(), ct * d.x() - st * d.y());
        const Eigen::Vector4d J(grad.dot(dw_dtheta), grad.x(), grad.y(), 1.0);
        H += J * J.transpose();
        g += J * r;
        sum_sq += r * r;
        ++n;
      }
    rms = std::sqrt(sum_sq / std::max(n, 1));
    const Eigen::Vector4d step = H.ldlt().solve(-g);
    if (!step.allFinite()) break;
    params += step;
    if (step.head<3>().norm() < 1e-6) break;
  }
  return {params[0], params.segment<2>(1), rms};
}

}  // namespace facadeslam
