#pragma once
// A PatchSource on `pyramid` at a pixel given in `level`'s coordinates.
#include <memory>
#include <utility>

#include <Eigen/Core>

#include "core/image/image_pyramid.hpp"
#include "core/map/map_point.hpp"

namespace facadeslam::patch {

inline PatchSource source_at(std::shared_ptr<const ImagePyramid> pyramid, int level, Eigen::Vector2d pixel_level) {
  PatchSource s;
  s.pyramid = std::move(pyramid);
  s.level = level;
  s.pixel_level0 = ImagePyramid::level_to_level0(pixel_level, level);
  return s;
}

}  // namespace facadeslam::patch
