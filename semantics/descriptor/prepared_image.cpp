#include "semantics/descriptor/prepared_image.hpp"

#include <cstring>
#include <string>
#include <vector>

#include <opencv2/imgproc.hpp>

#include "core/util/error.hpp"
#include "semantics/descriptor/colour_conversion.hpp"
#include "semantics/descriptor/colour_invariants.hpp"
#include "semantics/descriptor/edge_distance.hpp"
#include "semantics/descriptor/gradient_angle_plane.hpp"
#include "semantics/descriptor/kernel_support.hpp"
#include "semantics/descriptor/padded_plane.hpp"

namespace facadeslam::semantics {
namespace {

// Adds (equalised Y - Y) to each channel, saturating. 16 pixels at a time:
// their 16 changes are spread over the 48 interleaved channel bytes by
// three constant shuffles (lane i takes change i / 3).
FACADESLAM_KERNEL
void shift_channels(const cv::Mat& bgr, const cv::Mat& luma, const cv::Mat& equalised_luma, cv::Mat& out) {
  using Shorts = short __attribute__((vector_size(16 * sizeof(short))));
  using Bytes = unsigned char __attribute__((vector_size(16)));
  const Shorts zero = {}, top = zero + 255;
  const auto add_saturated = [&](const uchar* in, const Shorts& change, uchar* o) {
    Bytes bytes;
    std::memcpy(&bytes, in, sizeof bytes);
    Shorts v = __builtin_convertvector(bytes, Shorts) + change;
    v = v < zero ? zero : v;
    v = v > top ? top : v;
    bytes = __builtin_convertvector(v, Bytes);
    std::memcpy(o, &bytes, sizeof bytes);
  };
  for (int y = 0; y < bgr.rows; ++y) {
    const uchar* before = luma.ptr<uchar>(y);
    const uchar* after = equalised_luma.ptr<uchar>(y);
    const uchar* in = bgr.ptr<uchar>(y);
    uchar* o = out.ptr<uchar>(y);
    int x = 0;
    for (; x + 16 <= bgr.cols; x += 16) {
      Bytes b, a;
      std::memcpy(&b, before + x, sizeof b);
      std::memcpy(&a, after + x, sizeof a);
      const Shorts d = __builtin_convertvector(a, Shorts) - __builtin_convertvector(b, Shorts);
      const Shorts d0 = __builtin_shufflevector(d, d, 0, 0, 0, 1, 1, 1, 2, 2, 2, 3, 3, 3, 4, 4, 4, 5);
      const Shorts d1 = __builtin_shufflevector(d, d, 5, 5, 6, 6, 6, 7, 7, 7, 8, 8, 8, 9, 9, 9, 10, 10);
      const Shorts d2 = __builtin_shufflevector(d, d, 10, 11, 11, 11, 12, 12, 12, 13, 13, 13, 14, 14, 14, 15, 15, 15);
      add_saturated(in + 3 * x, d0, o + 3 * x);
      add_saturated(in + 3 * x + 16, d1, o + 3 * x + 16);
      add_saturated(in + 3 * x + 32, d2, o + 3 * x + 32);
    }
    for (; x < bgr.cols; ++x) {
      const int delta = after[x] - before[x];
      for (int c = 0; c < 3; ++c) {
        const int v = in[3 * x + c] + delta;
        o[3 * x + c] = static_cast<uchar>(v < 0 ? 0 : v > 255 ? 255 : v);
      }
    }
  }
}

// Thesis IV.4.2 (1): equalise the luma only, so colours keep their hue.
void equalise_luma(const cv::Mat& bgr, PreparedImage::Buffers& buffers) {
  cv::cvtColor(bgr, buffers.luma, cv::COLOR_BGR2GRAY);  // Y of YCrCb (same weights)
  cv::equalizeHist(buffers.luma, buffers.equalised_luma);
  buffers.equalised.create(bgr.size(), CV_8UC3);
  shift_channels(bgr, buffers.luma, buffers.equalised_luma, buffers.equalised);
}

}  // namespace

cv::Mat PreparedImage::interior(PlaneId p) const { return plane_interior(plane(p), border); }

PreparedImage prepare(const cv::Mat& bgr, const DescriptorParams& params) {
  PreparedImage out;
  prepare(bgr, params, out);
  return out;
}

void prepare(const cv::Mat& bgr, const DescriptorParams& params, PreparedImage& out) {
  validate(params);
  if (bgr.empty()) throw Error("descriptor preprocessing: the image is empty");
  if (bgr.type() != CV_8UC3)
    throw Error("descriptor preprocessing: expected an 8-bit 3-channel BGR image, got type " +
                cv::typeToString(bgr.type()));

  out.image_size = bgr.size();
  out.border = params.patch_radius;
  out.params = params;
  out.computed.reset();
  out.edges.release();
  const PlaneSet needed = required_planes(params.activation);
  for (int p = 0; p < kPlaneCount; ++p)
    if (!needed.test(static_cast<std::size_t>(p))) out.planes[static_cast<std::size_t>(p)].release();
  if (needed.none()) return;  // position only: no pixel is read

  PreparedImage::Buffers& buffers = out.buffers;
  equalise_luma(bgr, buffers);
  const cv::Mat* blurred = &buffers.equalised;
  if (params.gaussian_kernel > 1) {
    cv::GaussianBlur(buffers.equalised, buffers.blurred, cv::Size(params.gaussian_kernel, params.gaussian_kernel),
                     params.gaussian_sigma, params.gaussian_sigma, cv::BORDER_REFLECT_101);
    blurred = &buffers.blurred;
  }
  cv::Mat channels[3] = {buffers.b, buffers.g, buffers.r};
  cv::split(*blurred, channels);
  buffers.b = channels[0];
  buffers.g = channels[1];
  buffers.r = channels[2];
  const BgrPlanes split{buffers.b, buffers.g, buffers.r};

  // Allocate every needed plane; the steps below write their interiors.
  std::array<cv::Mat, kPlaneCount> interiors;
  for (int p = 0; p < kPlaneCount; ++p) {
    if (!needed.test(static_cast<std::size_t>(p))) continue;
    make_padded_plane(out.planes[static_cast<std::size_t>(p)], out.image_size, out.border);
    interiors[static_cast<std::size_t>(p)] = plane_interior(out.planes[static_cast<std::size_t>(p)], out.border);
  }
  const auto target = [&](PlaneId p) -> cv::Mat* {
    return needed.test(plane_bit(p)) ? &interiors[plane_bit(p)] : nullptr;
  };

  convert_colour(*blurred, split, params.colour_space,
                 {target(colour_plane(0)), target(colour_plane(1)), target(colour_plane(2))});
  for (int c = 0; c < 3; ++c) {
    if (!target(colour_plane(c))) continue;
    fill_border_reflect101(out.planes[plane_bit(colour_plane(c))], out.border);
    if (cv::Mat* angle = target(angle_plane(c)))
      gradient_angle_plane(out.planes[plane_bit(colour_plane(c))], out.border, params.gradient_operator, *angle);
  }

  if (cv::Mat* distance = target(PlaneId::edge_distance)) {
    cv::cvtColor(*blurred, buffers.grey, cv::COLOR_BGR2GRAY);
    canny_edges(buffers.grey, params.canny_kernel, params.canny_low_threshold, params.canny_high_threshold(), out.edges,
                buffers.canny);
    distance_to_edges(out.edges, *distance);
  }

  ColourInvariantOutputs invariants;
  for (int i = 0; i < 3; ++i) {
    invariants.gevers_l[i] = target(static_cast<PlaneId>(static_cast<int>(PlaneId::gevers_l1) + i));
    invariants.gevers_c[i] = target(static_cast<PlaneId>(static_cast<int>(PlaneId::gevers_c1) + i));
  }
  invariants.geusebroek_h = target(PlaneId::geusebroek_h);
  invariants.geusebroek_c = target(PlaneId::geusebroek_c);
  compute_colour_invariants(split, invariants);

  for (int p = 0; p < kPlaneCount; ++p) {
    const auto id = static_cast<PlaneId>(p);
    const bool colour = p <= static_cast<int>(PlaneId::colour2);  // filled above
    if (needed.test(static_cast<std::size_t>(p)) && !colour)
      fill_border_reflect101(out.planes[plane_bit(id)], out.border);
  }
  out.computed = needed;
}

}  // namespace facadeslam::semantics
