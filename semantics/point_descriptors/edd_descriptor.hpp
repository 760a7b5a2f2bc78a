#pragma once
// The thesis' first descriptor, EDD (Environment Dedicated Descriptor,
// thesis IV.3.1; Takacs et al. 2016): 113 values from the 9 x 9 patch
// around each keypoint, in this order:
//   [0, 2)    position: x / width, y / height;
//   [2, 8)    patch means of R, G, B and S (RGB and HSV in [0, 1]) and the
//             means of sin(hue) and cos(hue) (hue as an angle, so that
//             red at 0 and 359 degrees agree);
//   [8, 32)   third-order central moments mu30 mu21 mu12 mu03 of each of
//             R, G, B, H, S, V (H as in colour_conversion.hpp, ~hue / 360),
//             in that channel order;
//   [32, 113) the distance (pixels) of each of the 81 patch pixels, row by
//             row, to the nearest Canny edge of the grey image.
// Choices where the text is silent or inconsistent:
//  - the moments weight each pixel with the paper's normalised intensity
//    I_norm = (I_max - I) / mean(I_max - I) over the patch (a flat patch
//    gets uniform weights, whose third-order moments are 0);
//  - the means use the raw channel values: the mean of I_norm is 1 by
//    construction, so "normalise before the colour values" cannot apply;
//  - Canny: thresholds 50 / 150, 3 x 3 aperture, no blur (the papers give
//    none); an image without edges gets its diagonal as distance
//    (edge_distance.hpp);
//  - near the image edge the patch continues the image by reflection
//    (BORDER_REFLECT_101), as the modular descriptor does.
// How it is computed (the thesis times EDD at 26x faster than Opponent
// SIFT; bench_semantics_modules reports opponent_sift_over_edd): each
// channel is a function of one byte, so the planes come from tables built
// through the same conversions; the eight channels (R G B H S V sin cos)
// are interleaved per pixel, and edd_patch_moments.hpp takes a patch's
// maxima and raw moments as vector sums, the weighted central moments from
// those. edd_descriptor_test.cpp checks every value against the definition
// computed pixel by pixel.
#include <memory>

#include "semantics/point_descriptors/point_descriptor.hpp"

namespace facadeslam::semantics {

class EddDescriptor : public PointDescriptor {
 public:
  EddDescriptor();
  ~EddDescriptor() override;

  static constexpr int kRadius = 4;  // 9 x 9 patch
  static constexpr int kWidth = 113;

  std::string_view name() const override { return "edd"; }
  int width() const override { return kWidth; }
  cv::Mat compute(const cv::Mat& bgr, const std::vector<cv::Point2f>& keypoints) override;

 private:
  struct Planes;  // the per-image planes, kept between calls (no page faults per image)
  std::unique_ptr<Planes> planes_;
};

}  // namespace facadeslam::semantics
