#include "semantics/descriptor/canny_edges.hpp"

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <vector>

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
      const short *d0 = derivative.ptr<short>(y), *d1 = derivative.ptr<short>(y + 1),
                  *d2 = derivative.ptr<short>(y + 2);
      for (int x = 0; x < width; ++x) {
        gx[x] = static_cast<short>(d0[x] + 2 * d1[x] + d2[x]);
        gy[x] = static_cast<short>(s2[x] - s0[x]);
      }
    } else {
      const short *s0 = smooth.ptr<short>(y), *s1 = smooth.ptr<short>(y + 1), *s3 = smooth.ptr<short>(y + 3),
                  *s4 = smooth.ptr<short>(y + 4);
      const short *d0 = derivative.ptr<short>(y), *d1 = derivative.ptr<short>(y + 1),
                  *d2 = derivative.ptr<short>(y + 2), *d3 = derivative.ptr<short>(y + 3),
                  *d4 = derivative.ptr<short>(y + 4);
      for (int x = 0; x < width; ++x) {
        gx[x] = static_cast<short>(d0[x] + 4 * (d1[x] + d3[x]) + 6 * d2[x] + d4[x]);
        gy[x] = static_cast<short>(s4[x] - s0[x] + 2 * (s3[x] - s1[x]));
      }
    }
  }
}

// Map values of the edge tracing, as in OpenCV's Canny: 0 = a local
// maximum above the low threshold (an edge if connected to a strong one),
// 1 = not an edge, 2 = an edge.
constexpr uchar kWeak = 0, kNone = 1, kEdge = 2;
constexpr int kShift = 15;
constexpr int kTan22 = 13573;  // tan(22.5 deg) << 15, rounded: OpenCV's TG22

// L1 magnitude |dx| + |dy| into a buffer with a zero border of one pixel
// (and zero slack after each row for the vector loads).
FACADESLAM_KERNEL void magnitudes(const cv::Mat& dx, const cv::Mat& dy, cv::Mat& magnitude) {
  magnitude.row(0).setTo(0);  // the border; the interior is written below
  magnitude.row(magnitude.rows - 1).setTo(0);
  for (int y = 1; y + 1 < magnitude.rows; ++y) {
    int* m = magnitude.ptr<int>(y);
    m[0] = 0;
    std::fill(m + dx.cols + 1, m + magnitude.cols, 0);  // right border and the read slack
  }
  for (int y = 0; y < dx.rows; ++y) {
    const short* gx = dx.ptr<short>(y);
    const short* gy = dy.ptr<short>(y);
    int* m = magnitude.ptr<int>(y + 1) + 1;
    for (int x = 0; x < dx.cols; ++x) m[x] = std::abs(static_cast<int>(gx[x])) + std::abs(static_cast<int>(gy[x]));
  }
}

// Non-maximum suppression along the gradient direction, quantised to
// horizontal, vertical or one of the diagonals by OpenCV's integer tests
// (tan 22.5 and tan 67.5 in 15-bit fixed point), with its tie rules (>
// before, >= after); then the thresholds. Branch-free over 8 pixels.
// Strong maxima are collected as the seeds of the tracing.
FACADESLAM_KERNEL void suppress_non_maxima(const cv::Mat& dx, const cv::Mat& dy, const cv::Mat& magnitude, int low,
                                           int high, cv::Mat& map, std::vector<uchar*>& seeds,
                                           std::vector<uchar*>& row_buffer) {
  using ByteLanes = unsigned char __attribute__((vector_size(kLanes)));
  const auto load_ints = [](IntLanes& v, const int* p) { std::memcpy(&v, p, sizeof v); };
  // One row is enough: at the start of a block the row has at most x seeds,
  // so the block writes below x + kLanes <= cols.
  row_buffer.resize(static_cast<std::size_t>(dx.cols));
  uchar** const row_seeds = row_buffer.data();
  for (int y = 0; y < dx.rows; ++y) {
    const short* gx = dx.ptr<short>(y);
    const short* gy = dy.ptr<short>(y);
    const int* above = magnitude.ptr<int>(y) + 1;
    const int* here = magnitude.ptr<int>(y + 1) + 1;
    const int* below = magnitude.ptr<int>(y + 2) + 1;
    uchar* out = map.ptr<uchar>(y + 1) + 1;
    std::size_t row_count = 0;
    int x = 0;
    for (; x + kLanes <= dx.cols; x += kLanes) {
      using ShortLanes = short __attribute__((vector_size(kLanes * sizeof(short))));
      ShortLanes sx, sy;
      std::memcpy(&sx, gx + x, sizeof sx);
      std::memcpy(&sy, gy + x, sizeof sy);
      const IntLanes xs = __builtin_convertvector(sx, IntLanes), ys = __builtin_convertvector(sy, IntLanes);
      IntLanes m, left, right, up, down, up_left, up_right, down_left, down_right;
      load_ints(m, here + x);
      load_ints(left, here + x - 1);
      load_ints(right, here + x + 1);
      load_ints(up, above + x);
      load_ints(down, below + x);
      load_ints(up_left, above + x - 1);
      load_ints(up_right, above + x + 1);
      load_ints(down_left, below + x - 1);
      load_ints(down_right, below + x + 1);
      const IntLanes ax = xs < 0 ? -xs : xs;
      const IntLanes ay = (ys < 0 ? -ys : ys) << kShift;
      const IntLanes tan22 = ax * kTan22;
      const IntLanes tan67 = tan22 + (ax << (kShift + 1));
      const IntLanes horizontal = ay < tan22;
      const IntLanes vertical = ay > tan67;
      const IntLanes same_sign = (xs ^ ys) >= 0;  // s = +1: up-left / down-right
      const IntLanes along_x = (m > left) & (m >= right);
      const IntLanes along_y = (m > up) & (m >= down);
      const IntLanes diagonal = same_sign ? ((m > up_left) & (m > down_right)) : ((m > up_right) & (m > down_left));
      const IntLanes maximum = (m > low) & (horizontal ? along_x : vertical ? along_y : diagonal);
      const IntLanes value = maximum ? ((m > high) ? IntLanes{} + kEdge : IntLanes{} + kWeak) : IntLanes{} + kNone;
      const ByteLanes bytes = __builtin_convertvector(value, ByteLanes);
      std::memcpy(out + x, &bytes, sizeof bytes);
      // Every lane is written to the row's seed list and the count grows by
      // the edge lanes only: no branch on the data (a loop over the edge
      // lanes mispredicted on every block that had one).
      const ByteLanes is_edge = (bytes == kEdge) & 1;
      for (int lane = 0; lane < kLanes; ++lane) {
        row_seeds[row_count] = out + x + lane;
        row_count += is_edge[lane];
      }
    }
    for (; x < dx.cols; ++x) {
      const int xs = gx[x], ys = gy[x], m = here[x];
      bool maximum = false;
      if (m > low) {
        const int ax = std::abs(xs), ay = std::abs(ys) << kShift;
        const int tan22 = ax * kTan22, tan67 = tan22 + (ax << (kShift + 1));
        if (ay < tan22)
          maximum = m > here[x - 1] && m >= here[x + 1];
        else if (ay > tan67)
          maximum = m > above[x] && m >= below[x];
        else if ((xs ^ ys) >= 0)
          maximum = m > above[x - 1] && m > below[x + 1];
        else
          maximum = m > above[x + 1] && m > below[x - 1];
      }
      out[x] = maximum ? (m > high ? kEdge : kWeak) : kNone;
      if (out[x] == kEdge) row_seeds[row_count++] = out + x;
    }
    seeds.insert(seeds.end(), row_seeds, row_seeds + row_count);
  }
}

FACADESLAM_KERNEL void edge_bytes(const uchar* __restrict map, uchar* __restrict edges, int count) {
  for (int x = 0; x < count; ++x) edges[x] = map[x] == kEdge ? 255 : 0;
}

// Hysteresis: every weak maximum 8-connected to an edge becomes an edge;
// `stack` starts with the strong maxima.
void trace_edges(cv::Mat& map, std::vector<uchar*>& stack) {
  const std::ptrdiff_t step = static_cast<std::ptrdiff_t>(map.step);
  const std::ptrdiff_t neighbours[8] = {-step - 1, -step, -step + 1, -1, 1, step - 1, step, step + 1};
  while (!stack.empty()) {
    uchar* p = stack.back();
    stack.pop_back();
    for (const std::ptrdiff_t d : neighbours)
      if (p[d] == kWeak) {
        p[d] = kEdge;
        stack.push_back(p + d);
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
  if (h == 1)
    sobel<1>(b.padded, b.smooth, b.derivative, b.dx, b.dy);
  else
    sobel<2>(b.padded, b.smooth, b.derivative, b.dx, b.dy);
  // cv::Canny's integer thresholds: floor, low <= high, compared with >.
  const int low_threshold = cvFloor(std::min(low, high)), high_threshold = cvFloor(std::max(low, high));
  b.magnitude.create(grey.rows + 2, grey.cols + 2 + kLanes, CV_32S);
  magnitudes(b.dx, b.dy, b.magnitude);
  b.map.create(grey.rows + 2, grey.cols + 2, CV_8U);
  b.map.setTo(kNone);  // the border: never an edge
  b.stack.clear();
  suppress_non_maxima(b.dx, b.dy, b.magnitude, low_threshold, high_threshold, b.map, b.stack, b.row_seeds);
  trace_edges(b.map, b.stack);
  edges.create(grey.size(), CV_8U);
  for (int y = 0; y < grey.rows; ++y) edge_bytes(b.map.ptr<uchar>(y + 1) + 1, edges.ptr<uchar>(y), grey.cols);
}

}  // namespace facadeslam::semantics
