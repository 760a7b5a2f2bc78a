#include "core/patch/search_image.hpp"

#include "core/util/error.hpp"

namespace facadeslam::patch {

SearchImage::SearchImage(const ImagePyramid& pyramid) : pyramid_(&pyramid) {
  for (int l = 0; l < kPyramidLevels; ++l) {
    const PyramidLevel& level = pyramid.level(l);
    const int rows = level.image.rows;
    std::vector<int>& start = row_start_[static_cast<std::size_t>(l)];
    start.assign(static_cast<std::size_t>(rows) + 1, 0);
    int y = 0;  // next row whose start is not set yet
    const int n = static_cast<int>(level.corners.size());
    for (int i = 0; i < n; ++i) {
      const Corner& c = level.corners[static_cast<std::size_t>(i)];
      const Corner* previous = i > 0 ? &level.corners[static_cast<std::size_t>(i) - 1] : nullptr;
      const bool sorted = !previous || previous->y < c.y || (previous->y == c.y && previous->x < c.x);
      if (!sorted || c.y < 0 || c.y >= rows)
        throw Error("search image: the corners of pyramid level " + std::to_string(l) +
                    " must be sorted by row then column and lie inside the image");
      for (; y <= c.y; ++y) start[static_cast<std::size_t>(y)] = i;
    }
    for (; y <= rows; ++y) start[static_cast<std::size_t>(y)] = n;
  }
}

}  // namespace facadeslam::patch
