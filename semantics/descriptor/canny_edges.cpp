#include "semantics/descriptor/canny_edges.hpp"

#include <opencv2/imgproc.hpp>

#include "semantics/descriptor/kernel_support.hpp"

namespace facadeslam::semantics {
namespace {

// Sobel of aperture 2h+1 as two separable passes on the replicate-padded
// image (border h): each row is filtered across with the smoothing and the
// derivative kernel, then the columns are combined down the other way.
// Smoothing (1 2 1) / (1 4 6 4 1), derivative (-1 0 1) / (-1 -2 0 2 1);
// every sum fits in 16 bits for 8-bit input (|d| <= 24480).
template <int H>
FACADESLAM_KERNEL void sobel(const cv::Mat& padded, cv::Mat& smooth, cv::Mat& derivative, cv::Mat& dx, cv::Mat& dy) {
  const int width = padded.cols - 2 * H;
  const int height = padded.rows - 2 * H;
  for (int y = 0; y < padded.rows; ++y) {
    const uchar* p = padded.ptr<uchar>(y) + H;
    short* s = smooth.ptr<short>(y);
    short* d = derivative.ptr<short>(y);
    for (int x = 0; x < width; ++x) {
      if constexpr (H == 1) {
        s[x] = static_cast<short>(p[x - 1] + 2 * p[x] + p[x + 1]);
        d[x] = static_cast<short>(p[x + 1] - p[x - 1]);
      } else {
        s[x] = static_cast<short>(p[x - 2] + 4 * (p[x - 1] + p[x + 1]) + 6 * p[x] + p[x + 2]);
        d[x] = static_cast<short>(p[x + 2] - p[x - 2] + 2 * (p[x + 1] - p[x - 1]));
      }
    }
  }
  for (int y = 0; y < height; ++y) {
    short* gx = dx.ptr<short>(y);
    short* gy = dy.ptr<short>(y);
    if constexpr (H == 1) {
      const short *s0 = smooth.ptr<short>(y), *s2 = smooth.ptr<short>(y + 2);
      const short *d0 = derivative.ptr<short>(y), *d1 = derivative.ptr<short>(y + 1), *d2 = derivative.ptr<short>(y + 2);
      for (int x = 0; x < width; ++x) {
        gx[x] = static_cast<short>(d0[x] + 2 * d1[x] + d2[x]);
        gy[x] = static_cast<short>(s2[x] - s0[x]);
      }
    } else {
      const short *s0 = smooth.ptr<short>(y), *s1 = smooth.ptr<short>(y + 1), *s3 = smooth.ptr<short>(y + 3),
                  *s4 = smooth.ptr<short>(y + 4);
      const short *d0 = derivative.ptr<short>(y), *d1 = derivative.ptr<short>(y + 1), *d2 = derivative.ptr<short>(y + 2),
                  *d3 = derivative.ptr<short>(y + 3), *d4 = derivative.ptr<short>(y + 4);
      for (int x = 0; x < width; ++x) {
        gx[x] = static_cast<short>(d0[x] + 4 * (d1[x] + d3[x]) + 6 * d2[x] + d4[x]);
        gy[x] = static_cast<short>(s4[x] - s0[x] + 2 * (s3[x] - s1[x]));
      }
    }
  }
}

}  // namespace

void canny_edges(const cv::Mat& grey, int aperture, double low, double high, cv::Mat& edges, CannyBuffers& b) {
  CV_Assert(grey.type() == CV_8U && (aperture == 3 || aperture == 5));
  const int h = aperture / 2;
  cv::copyMakeBorder(grey, b.padded, h, h, h, h, cv::BORDER_REPLICATE);
  b.smooth.create(b.padded.rows, grey.cols, CV_16S);
  b.derivative.create(b.padded.rows, grey.cols, CV_16S);
  b.dx.create(grey.size(), CV_16S);
  b.dy.create(grey.size(), CV_16S);
  if (h == 1) sobel<1>(b.padded, b.smooth, b.derivative, b.dx, b.dy);
  else sobel<2>(b.padded, b.smooth, b.derivative, b.dx, b.dy);
  cv::Canny(b.dx, b.dy, edges, low, high, false);
}

}  // namespace facadeslam::semantics
