#pragma once
// FAST-9 corners with grid bucketing. Plain FAST clusters on textured areas
// (a window frame gives hundreds of corners, a plain wall none); the tracker
// and the map maker need corners spread over the image, so the image is cut
// into square cells and each cell keeps only its strongest corners.
#include <vector>

#include <opencv2/core.hpp>

namespace facadeslam {

struct Corner {
  int x = 0;  // pixel coordinates at the corner's pyramid level
  int y = 0;
  float score = 0.f;  // FAST score (higher = stronger)
};

struct FastOptions {
  int threshold = 10;     // FAST intensity threshold at this level
  int cell_size = 32;     // bucketing cell in pixels at this level
  int max_per_cell = 20;  // strongest corners kept per cell (0 = no bucketing)
  int border = 4;         // corners closer than this to the edge are dropped
};

// Detects FAST-9 corners with non-maximum suppression on an 8-bit grey image,
// then keeps the `max_per_cell` strongest of each cell. The output is sorted by
// row, then column (the tracker relies on row order for fast lookups).
std::vector<Corner> detect_fast(const cv::Mat& grey, const FastOptions& options);

}  // namespace facadeslam
