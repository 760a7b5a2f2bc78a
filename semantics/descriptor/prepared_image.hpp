#pragma once
// Per-image preprocessing shared by all keypoints (thesis IV.4.2), computing
// only what the active values need:
//   1. histogram equalisation of the luma Y (of YCrCb), back to BGR (always,
//      unless no plane is needed at all). Converting to YCrCb, replacing Y
//      and converting back adds the same Y' - Y to B, G and R, which is how
//      it is computed (up to the 8-bit rounding of the round trip);
//   2. Gaussian blur with the genome's kernel and sigma (kernel 1 = none);
//   3. colour-space conversion of the blurred image (colour_conversion.hpp);
//   4. Canny on the grey blurred image (genome aperture, low, 3 x low) and
//      the Euclidean distance of every pixel to the nearest edge;
//   5. gradients (Sobel 3x3 or Scharr) of each needed colour channel and
//      their angles atan2(gy, gx) in [0, 2pi) (image y axis points down;
//      gradient_angle_plane.hpp);
//   6. the colour invariants of the blurred RGB (colour_invariants.hpp).
// Every plane is CV_32F with a reflected border as wide as the patch radius
// (padded_plane.hpp): a keypoint's patch is the (2r+1)^2 block centred on the
// pixel nearest to it, and near the image edge it continues the image by
// reflection (BORDER_REFLECT_101) instead of shrinking.
#include <array>

#include <opencv2/core.hpp>

#include "semantics/descriptor/canny_edges.hpp"
#include "semantics/descriptor/descriptor_params.hpp"
#include "semantics/descriptor/modules/patch_view.hpp"
#include "semantics/descriptor/planes.hpp"

namespace facadeslam::semantics {

struct PreparedImage {
  cv::Size image_size;
  int border = 0;                           // reflected pixels around every plane
  DescriptorParams params;                  // the parameters it was prepared for
  PlaneSet computed;                        // which planes hold data
  std::array<cv::Mat, kPlaneCount> planes;  // padded CV_32F, empty when not computed
  cv::Mat edges;                            // CV_8U Canny edges (255 = edge), when edge distance was needed

  // Intermediate images, kept so that preparing the next image of the same
  // size reuses their memory.
  struct Buffers {
    cv::Mat luma, equalised_luma, equalised, blurred, b, g, r, grey;
    CannyBuffers canny;
  } buffers;

  bool has(PlaneId p) const { return computed.test(plane_bit(p)); }
  const cv::Mat& plane(PlaneId p) const { return planes[plane_bit(p)]; }
  // The image-sized part of a plane.
  cv::Mat interior(PlaneId p) const;
  // The (2r+1)^2 patch of plane p centred on pixel (x, y) of the image;
  // requires has(p), 0 <= x < width, 0 <= y < height and r <= border.
  PatchView patch(PlaneId p, int x, int y, int r) const {
    const cv::Mat& m = plane(p);
    return {m.ptr<float>(y + border - r) + (x + border - r), static_cast<std::ptrdiff_t>(m.step1()), r};
  }
};

// `bgr` must be a non-empty CV_8UC3 image; throws Error otherwise or when
// `params` holds a value outside its table.
PreparedImage prepare(const cv::Mat& bgr, const DescriptorParams& params);

// The same into `image`, reusing its memory when the image size and patch
// radius are unchanged (one PreparedImage per video or keyframe stream).
void prepare(const cv::Mat& bgr, const DescriptorParams& params, PreparedImage& image);

}  // namespace facadeslam::semantics
