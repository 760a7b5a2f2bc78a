#pragma once
// The current frame as the patch search sees it: its pyramid plus, for every
// level, where each image row's FAST corners start in the level's corner list
// (sorted by row, then column). Built once per frame (O(rows + corners) per
// level, a few microseconds), it lets a search visit only the rows and
// columns of its window instead of every corner of those rows.
#include <array>
#include <span>
#include <vector>

#include "core/image/image_pyramid.hpp"

namespace facadeslam::patch {

class SearchImage {
 public:
  // Keeps a reference: `pyramid` must outlive this object.
  explicit SearchImage(const ImagePyramid& pyramid);

  const ImagePyramid& pyramid() const { return *pyramid_; }

  // The corners of `level` (0..3) on row y (empty outside the image). Inline:
  // every search calls it once per row of its window.
  std::span<const Corner> row(int level, int y) const {
    const std::vector<int>& start = row_start_[static_cast<std::size_t>(level)];
    if (y < 0 || y + 1 >= static_cast<int>(start.size())) return {};
    const Corner* corners = pyramid_->level(level).corners.data();
    const int b = start[static_cast<std::size_t>(y)], e = start[static_cast<std::size_t>(y) + 1];
    return {corners + b, static_cast<std::size_t>(e - b)};
  }

 private:
  const ImagePyramid* pyramid_;
  // row_start_[l][y] = index of the first corner of level l with row >= y,
  // for y = 0..rows (the last entry is the corner count).
  std::array<std::vector<int>, kPyramidLevels> row_start_;
};

}  // namespace facadeslam::patch
