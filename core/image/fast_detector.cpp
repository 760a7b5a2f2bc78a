#include "core/image/fast_detector.hpp"

#include <algorithm>
#include <cstdlib>

#include <opencv2/core/hal/intrin.hpp>
#include <opencv2/features2d.hpp>

#include "core/util/error.hpp"

namespace facadeslam {
namespace {

// Bresenham circle of radius 3 used by FAST, in order around the circle.
constexpr int kCircle[16][2] = {{0, -3}, {1, -3}, {2, -2}, {3, -1}, {3, 0},  {3, 1},  {2, 2},  {1, 3},
                                {0, 3},  {-1, 3}, {-2, 2}, {-3, 1}, {-3, 0}, {-3, -1}, {-2, -2}, {-1, -3}};

// FAST-9 score: the largest t for which some arc of 9 contiguous circle pixels
// is entirely brighter than centre + t or entirely darker than centre - t.
// Along a clean edge several pixels share that score; the fractional part,
// Rosten's sum of absolute differences over the circle scaled below 1, breaks
// the tie in favour of the pixel most unlike its surroundings: the corner itself.
//
// Eight arc starts at a time in 16-bit lanes (OpenCV's universal intrinsics:
// SSE2 on x86-64, NEON on ARM): the minimum and maximum over an arc are
// running min/max over nine shifted loads of the circle, written out to 25
// values so no load wraps. Every level-0 frame scores ~30 000 candidates:
// this is most of the detector's time (the scalar loops took ~70 ns each).
float fast_score(const std::uint8_t* centre_ptr, const int (&offsets)[16]) {
  const int centre = *centre_ptr;
  alignas(16) std::int16_t diff[32];
  for (int i = 0; i < 16; ++i) diff[i] = static_cast<std::int16_t>(centre_ptr[offsets[i]] - centre);
  for (int i = 16; i < 32; ++i) diff[i] = diff[i - 16];
#if CV_SIMD128
  cv::v_int16x8 brighter = cv::v_setzero_s16(), darker = cv::v_setzero_s16();
  for (int k = 0; k < 16; k += 8) {
    cv::v_int16x8 lo = cv::v_load(diff + k), hi = lo;
    for (int j = 1; j < 9; ++j) {
      const cv::v_int16x8 v = cv::v_load(diff + k + j);
      lo = cv::v_min(lo, v);
      hi = cv::v_max(hi, v);
    }
    brighter = cv::v_max(brighter, lo);                         // all > centre + t
    darker = cv::v_max(darker, cv::v_setzero_s16() - hi);       // all < centre - t
  }
  const int best = cv::v_reduce_max(cv::v_max(brighter, darker));
  const unsigned sad =
      cv::v_reduce_sum(cv::v_abs(cv::v_load(diff))) + cv::v_reduce_sum(cv::v_abs(cv::v_load(diff + 8)));
#else
  int best = 0;
  unsigned sad = 0;
  for (int i = 0; i < 16; ++i) {
    int lo = diff[i], hi = diff[i];
    for (int j = 1; j < 9; ++j) {
      lo = std::min<int>(lo, diff[i + j]);
      hi = std::max<int>(hi, diff[i + j]);
    }
    best = std::max(best, std::max(lo, -hi));
    sad += static_cast<unsigned>(std::abs(diff[i]));
  }
#endif
  return static_cast<float>(best) + static_cast<float>(sad) / (16.f * 256.f);
}

}  // namespace

std::vector<Corner> detect_fast(const cv::Mat& grey, const FastOptions& options) {
  if (grey.type() != CV_8UC1) throw Error("detect_fast: expected an 8-bit single-channel image");
  if (options.threshold < 1 || options.cell_size < 1 || options.max_per_cell < 0 || options.border < 0)
    throw Error("detect_fast: invalid options (threshold and cell_size >= 1, max_per_cell and border >= 0)");

  // OpenCV's segment test finds the candidates (fast, vectorised). Its own
  // non-maximum suppression needs a strict maximum, so a corner whose score
  // ties with a neighbour's (common on rendered or clean synthetic images)
  // vanishes entirely; we score the candidates and suppress with a raster-order
  // tie-break instead, keeping exactly one pixel of every plateau.
  // Per-thread buffers, reused from frame to frame: a fresh 1.2 MB score
  // image per level-0 call cost more in page faults than the scoring itself.
  // One zeroed score image per image size (a pyramid's levels alternate
  // sizes, and a cv::Mat re-created for another size is new memory): only
  // the candidates' pixels are written, and reset to zero after use.
  thread_local std::vector<cv::KeyPoint> candidates;
  thread_local std::vector<cv::Mat> score_images;
  candidates.clear();
  cv::FAST(grey, candidates, options.threshold, /*nonmaxSuppression=*/false, cv::FastFeatureDetector::TYPE_9_16);

  int offsets[16];
  const int stride = static_cast<int>(grey.step1());
  for (int i = 0; i < 16; ++i) offsets[i] = kCircle[i][1] * stride + kCircle[i][0];

  auto found = std::find_if(score_images.begin(), score_images.end(),
                            [&](const cv::Mat& m) { return m.size() == grey.size(); });
  if (found == score_images.end()) {
    score_images.emplace_back(grey.size(), CV_32FC1, cv::Scalar(0));
    found = score_images.end() - 1;
  }
  cv::Mat& scores = *found;
  for (const auto& kp : candidates) {
    const int x = static_cast<int>(kp.pt.x), y = static_cast<int>(kp.pt.y);
    scores.ptr<float>(y)[x] = fast_score(grey.ptr<std::uint8_t>(y) + x, offsets);
  }

  const int b = std::max(options.border, 3);  // the FAST circle needs 3 pixels
  std::vector<Corner> corners;
  corners.reserve(candidates.size() / 4);
  for (const auto& kp : candidates) {
    const int x = static_cast<int>(kp.pt.x), y = static_cast<int>(kp.pt.y);
    if (x < b || y < b || x >= grey.cols - b || y >= grey.rows - b) continue;
    const float* above = scores.ptr<float>(y - 1) + x;
    const float* row = scores.ptr<float>(y) + x;
    const float* below = scores.ptr<float>(y + 1) + x;
    // Branch-free 3x3 maximum test; ties go to the neighbour that comes first
    // in raster order (strictly greater than the earlier four, not less than
    // the later four), so a plateau keeps exactly one pixel.
    const float earlier = std::max(std::max(above[-1], above[0]), std::max(above[1], row[-1]));
    const float later = std::max(std::max(row[1], below[-1]), std::max(below[0], below[1]));
    if ((row[0] > earlier) & (row[0] >= later)) corners.push_back({x, y, row[0]});
  }
  for (const auto& kp : candidates) scores.ptr<float>(static_cast<int>(kp.pt.y))[static_cast<int>(kp.pt.x)] = 0.f;

  if (options.max_per_cell > 0) {
    // Bucket the corners by cell (counting sort: they are few cells and many
    // corners), then keep the strongest `max_per_cell` of each bucket.
    const int cells_x = (grey.cols + options.cell_size - 1) / options.cell_size;
    const int cells_y = (grey.rows + options.cell_size - 1) / options.cell_size;
    std::vector<std::size_t> cell_begin(static_cast<std::size_t>(cells_x * cells_y) + 1, 0);
    std::vector<int> cell(corners.size());
    for (std::size_t i = 0; i < corners.size(); ++i) {
      cell[i] = (corners[i].y / options.cell_size) * cells_x + corners[i].x / options.cell_size;
      ++cell_begin[static_cast<std::size_t>(cell[i]) + 1];
    }
    for (std::size_t c = 1; c < cell_begin.size(); ++c) cell_begin[c] += cell_begin[c - 1];
    std::vector<Corner> bucketed(corners.size());
    std::vector<std::size_t> fill(cell_begin.begin(), cell_begin.end() - 1);
    for (std::size_t i = 0; i < corners.size(); ++i) bucketed[fill[static_cast<std::size_t>(cell[i])]++] = corners[i];

    std::vector<Corner> kept;
    kept.reserve(corners.size());
    const auto by_score = [](const Corner& a, const Corner& c) { return a.score > c.score; };
    for (std::size_t c = 0; c + 1 < cell_begin.size(); ++c) {
      const auto first = bucketed.begin() + static_cast<std::ptrdiff_t>(cell_begin[c]);
      const auto last = bucketed.begin() + static_cast<std::ptrdiff_t>(cell_begin[c + 1]);
      const auto keep = std::min<std::ptrdiff_t>(last - first, options.max_per_cell);
      std::partial_sort(first, first + keep, last, by_score);
      kept.insert(kept.end(), first, first + keep);
    }
    corners.swap(kept);
  }

  std::sort(corners.begin(), corners.end(),
            [](const Corner& a, const Corner& c) { return a.y != c.y ? a.y < c.y : a.x < c.x; });
  return corners;
}

}  // namespace facadeslam
