#include "core/image/fast_detector.hpp"

#include <algorithm>
#include <array>
#include <cstdlib>

#include <opencv2/core/hal/intrin.hpp>
#include <opencv2/features2d.hpp>

#include "core/util/error.hpp"

namespace facadeslam {
namespace {

// Bresenham circle of radius 3 used by FAST, in order around the circle.
constexpr int kCircle[16][2] = {{0, -3}, {1, -3}, {2, -2}, {3, -1}, {3, 0},  {3, 1},   {2, 2},   {1, 3},
                                {0, 3},  {-1, 3}, {-2, 2}, {-3, 1}, {-3, 0}, {-3, -1}, {-2, -2}, {-1, -3}};

// FAST-9 score: the largest t for which some arc of 9 contiguous circle pixels
// is entirely brighter than centre + t or entirely darker than centre - t.
// Along a clean edge several pixels share that score; the fractional part,
// Rosten's sum of absolute differences over the circle scaled below 1, breaks
// the tie in favour of the pixel most unlike its surroundings: the corner itself.
float score_from(int best, unsigned sad) { return static_cast<float>(best) + static_cast<float>(sad) / (16.f * 256.f); }

float fast_score(const std::uint8_t* centre_ptr, const int (&offsets)[16]) {
  int diff[16];
  for (int i = 0; i < 16; ++i) diff[i] = centre_ptr[offsets[i]] - *centre_ptr;
  int best = 0;
  unsigned sad = 0;
  for (int i = 0; i < 16; ++i) {
    int lo = diff[i], hi = diff[i];
    for (int j = 1; j < 9; ++j) {
      lo = std::min(lo, diff[(i + j) & 15]);
      hi = std::max(hi, diff[(i + j) & 15]);
    }
    best = std::max(best, std::max(lo, -hi));
    sad += static_cast<unsigned>(std::abs(diff[i]));
  }
  return score_from(best, sad);
}

// The scores of `count` candidates (centre pixel pointers) into `scores`.
// Every level-0 frame scores ~30 000 candidates, most of the detector's time:
// with OpenCV's universal intrinsics (SSE2 on x86-64, NEON on ARM) eight
// candidates go at once, one per 16-bit lane, and the minimum over each arc
// of 9 is built by doubling (pairs, fours, then four + four + one): 3 min and
// 3 max operations per arc start instead of 8 each. Bit for bit the scalar score.
void fast_scores(const std::uint8_t* const* centres, std::size_t count, const int (&offsets)[16], float* scores) {
  std::size_t i = 0;
#if CV_SIMD128
  using cv::v_int16x8;
  for (; i + 8 <= count; i += 8) {
    alignas(16) std::int16_t diff[16][8];
    for (int c = 0; c < 8; ++c) {
      const std::uint8_t* p = centres[i + static_cast<std::size_t>(c)];
      for (int k = 0; k < 16; ++k) diff[k][c] = static_cast<std::int16_t>(p[offsets[k]] - *p);
    }
    v_int16x8 d[16], lo2[16], hi2[16], lo4[16], hi4[16];
    for (int k = 0; k < 16; ++k) d[k] = cv::v_load(diff[k]);
    for (int k = 0; k < 16; ++k) {
      lo2[k] = cv::v_min(d[k], d[(k + 1) & 15]);
      hi2[k] = cv::v_max(d[k], d[(k + 1) & 15]);
    }
    for (int k = 0; k < 16; ++k) {
      lo4[k] = cv::v_min(lo2[k], lo2[(k + 2) & 15]);
      hi4[k] = cv::v_max(hi2[k], hi2[(k + 2) & 15]);
    }
    v_int16x8 brighter = cv::v_setzero_s16(), darker = cv::v_setzero_s16(), sad = cv::v_setzero_s16();
    for (int k = 0; k < 16; ++k) {
      const v_int16x8 lo = cv::v_min(cv::v_min(lo4[k], lo4[(k + 4) & 15]), d[(k + 8) & 15]);
      const v_int16x8 hi = cv::v_max(cv::v_max(hi4[k], hi4[(k + 4) & 15]), d[(k + 8) & 15]);
      brighter = cv::v_max(brighter, lo);                     // all > centre + t
      darker = cv::v_min(darker, hi);                         // all < centre - t, negated below
      sad = sad + cv::v_reinterpret_as_s16(cv::v_abs(d[k]));  // at most 16 x 255: fits
    }
    alignas(16) std::int16_t best[8], sums[8];
    cv::v_store(best, cv::v_max(brighter, cv::v_setzero_s16() - darker));
    cv::v_store(sums, sad);
    for (int c = 0; c < 8; ++c)
      scores[i + static_cast<std::size_t>(c)] = score_from(best[c], static_cast<std::uint16_t>(sums[c]));
  }
#endif
  for (; i < count; ++i) scores[i] = fast_score(centres[i], offsets);
}

// The candidates of one image row: [first, last) of the raster-ordered list.
struct CandidateRow {
  int y = -1;
  std::size_t first = 0, last = 0;
};

// Non-maximum suppression reads the scores of three rows at a time: kept in
// a ring (a few kB that stay in the L1 cache, where a whole score image did
// not), every pixel that is not a candidate 0.
class ScoreRows {
 public:
  explicit ScoreRows(int cols) {
    for (auto& row : rows_) row.assign(static_cast<std::size_t>(cols), 0.f);
    zeros_.assign(static_cast<std::size_t>(cols), 0.f);
  }
  // Row `next`'s scores replace what its slot held.
  void put(const CandidateRow& next, const std::vector<cv::KeyPoint>& candidates, const std::vector<float>& scores) {
    CandidateRow& held = held_[static_cast<std::size_t>(next.y % 3)];
    std::vector<float>& row = rows_[static_cast<std::size_t>(next.y % 3)];
    for (std::size_t i = held.first; i < held.last; ++i) row[static_cast<std::size_t>(candidates[i].pt.x)] = 0.f;
    for (std::size_t i = next.first; i < next.last; ++i) row[static_cast<std::size_t>(candidates[i].pt.x)] = scores[i];
    held = next;
  }
  const float* row(int y) const {
    const std::size_t s = static_cast<std::size_t>(y % 3);
    return held_[s].y == y ? rows_[s].data() : zeros_.data();
  }

 private:
  std::array<std::vector<float>, 3> rows_;
  std::array<CandidateRow, 3> held_{};
  std::vector<float> zeros_;
};

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
  // Per-thread buffers, reused from frame to frame.
  thread_local std::vector<cv::KeyPoint> candidates;
  thread_local std::vector<const std::uint8_t*> centres;
  thread_local std::vector<float> scores;
  candidates.clear();
  cv::FAST(grey, candidates, options.threshold, /*nonmaxSuppression=*/false, cv::FastFeatureDetector::TYPE_9_16);
  const auto raster_order = [](const cv::KeyPoint& a, const cv::KeyPoint& c) {
    return a.pt.y != c.pt.y ? a.pt.y < c.pt.y : a.pt.x < c.pt.x;
  };
  if (!std::is_sorted(candidates.begin(), candidates.end(), raster_order))
    std::sort(candidates.begin(), candidates.end(), raster_order);

  int offsets[16];
  const int stride = static_cast<int>(grey.step1());
  for (int i = 0; i < 16; ++i) offsets[i] = kCircle[i][1] * stride + kCircle[i][0];
  centres.resize(candidates.size());
  for (std::size_t i = 0; i < candidates.size(); ++i)
    centres[i] = grey.ptr<std::uint8_t>(static_cast<int>(candidates[i].pt.y)) + static_cast<int>(candidates[i].pt.x);
  scores.resize(candidates.size());
  fast_scores(centres.data(), centres.size(), offsets, scores.data());

  const int b = std::max(options.border, 3);  // the FAST circle needs 3 pixels
  // Every candidate is written and the count advanced only for a maximum:
  // whether a candidate is one is a coin toss the branch predictor loses.
  std::vector<Corner> corners(candidates.size());
  std::size_t found = 0;
  thread_local std::vector<CandidateRow> candidate_rows;
  candidate_rows.clear();
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    const int y = static_cast<int>(candidates[i].pt.y);
    if (candidate_rows.empty() || candidate_rows.back().y != y) candidate_rows.push_back({y, i, i});
    candidate_rows.back().last = i + 1;
  }
  ScoreRows rows(grey.cols);
  std::size_t next = 0;  // the next row to put in the ring
  for (const CandidateRow& current : candidate_rows) {
    for (; next < candidate_rows.size() && candidate_rows[next].y <= current.y + 1; ++next)
      rows.put(candidate_rows[next], candidates, scores);
    const int y = current.y;
    if (y < b || y >= grey.rows - b) continue;
    const float* above = rows.row(y - 1);
    const float* row = rows.row(y);
    const float* below = rows.row(y + 1);
    for (std::size_t i = current.first; i < current.last; ++i) {
      const int x = static_cast<int>(candidates[i].pt.x);
      if (x < b || x >= grey.cols - b) continue;
      // Branch-free 3x3 maximum test; ties go to the neighbour that comes
      // first in raster order (strictly greater than the earlier four, not
      // less than the later four), so a plateau keeps exactly one pixel.
      const float earlier = std::max(std::max(above[x - 1], above[x]), std::max(above[x + 1], row[x - 1]));
      const float later = std::max(std::max(row[x + 1], below[x - 1]), std::max(below[x], below[x + 1]));
      corners[found] = {x, y, row[x]};
      found += static_cast<std::size_t>((row[x] > earlier) & (row[x] >= later));
    }
  }
  corners.resize(found);

  if (options.max_per_cell > 0) {
    // Bucket the corners by cell (counting sort: they are few cells and many
    // corners), keep the strongest `max_per_cell` of each bucket, and return
    // the kept ones in the raster order the suppression left them in.
    const int cells_x = (grey.cols + options.cell_size - 1) / options.cell_size;
    const int cells_y = (grey.rows + options.cell_size - 1) / options.cell_size;
    std::vector<std::size_t> cell_begin(static_cast<std::size_t>(cells_x * cells_y) + 1, 0);
    std::vector<int> cell(corners.size());
    for (std::size_t i = 0; i < corners.size(); ++i) {
      cell[i] = (corners[i].y / options.cell_size) * cells_x + corners[i].x / options.cell_size;
      ++cell_begin[static_cast<std::size_t>(cell[i]) + 1];
    }
    for (std::size_t c = 1; c < cell_begin.size(); ++c) cell_begin[c] += cell_begin[c - 1];
    std::vector<std::uint32_t> bucketed(corners.size());
    std::vector<std::size_t> fill(cell_begin.begin(), cell_begin.end() - 1);
    for (std::size_t i = 0; i < corners.size(); ++i)
      bucketed[fill[static_cast<std::size_t>(cell[i])]++] = static_cast<std::uint32_t>(i);

    std::vector<char> keep(corners.size(), 0);
    const auto by_score = [&](std::uint32_t a, std::uint32_t c) { return corners[a].score > corners[c].score; };
    for (std::size_t c = 0; c + 1 < cell_begin.size(); ++c) {
      const auto first = bucketed.begin() + static_cast<std::ptrdiff_t>(cell_begin[c]);
      const auto last = bucketed.begin() + static_cast<std::ptrdiff_t>(cell_begin[c + 1]);
      const auto kept = std::min<std::ptrdiff_t>(last - first, options.max_per_cell);
      std::partial_sort(first, first + kept, last, by_score);
      for (auto i = first; i != first + kept; ++i) keep[*i] = 1;
    }
    std::size_t n = 0;
    for (std::size_t i = 0; i < corners.size(); ++i)
      if (keep[i]) corners[n++] = corners[i];
    corners.resize(n);
  }
  return corners;
}

}  // namespace facadeslam
