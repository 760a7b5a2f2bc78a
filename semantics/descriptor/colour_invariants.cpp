#include "semantics/descriptor/colour_invariants.hpp"

#include <vector>

#include "semantics/descriptor/kernel_support.hpp"

namespace facadeslam::semantics {
namespace {

// One output plane per pass: each loop is straight-line float code the
// compiler vectorises (the selects in fast_math.hpp included).
template <typename PixelFunction>
[[gnu::always_inline]] inline void for_each_pixel(const BgrPlanes& in, cv::Mat& out, PixelFunction f) {
  for (int y = 0; y < out.rows; ++y) {
    const uchar* b = in.b.ptr<uchar>(y);
    const uchar* g = in.g.ptr<uchar>(y);
    const uchar* r = in.r.ptr<uchar>(y);
    float* o = out.ptr<float>(y);
    for (int x = 0; x < out.cols; ++x)
      o[x] = f(static_cast<float>(r[x]), static_cast<float>(g[x]), static_cast<float>(b[x]));
  }
}

template <int Which>
FACADESLAM_KERNEL void gevers_l_plane(const BgrPlanes& in, cv::Mat& out) {
  for_each_pixel(in, out, [](float r, float g, float b) {
    const float rg = (r - g) * (r - g), rb = (r - b) * (r - b), gb = (g - b) * (g - b);
    const float d = rg + rb + gb;  // 0 only for grey pixels, whose numerator is 0 too
    const float numerator = Which == 0 ? rg : Which == 1 ? rb : gb;
    return numerator / (d > 0.0f ? d : 1.0f);  // no trapping division: the loop vectorises
  });
}

template <int Which>
FACADESLAM_KERNEL void gevers_c_plane(const BgrPlanes& in, cv::Mat& out) {
  for_each_pixel(in, out, [](float r, float g, float b) {
    const float self = Which == 0 ? r : Which == 1 ? g : b;
    const float u = Which == 0 ? g : r;
    const float v = Which == 2 ? g : b;
    return atan2_first_quadrant(self, u > v ? u : v);
  });
}

FACADESLAM_KERNEL void geusebroek_h_plane(const BgrPlanes& in, cv::Mat& out) {
  for_each_pixel(in, out, [](float r, float g, float b) {
    const float e_l = 0.30f * r + 0.04f * g - 0.35f * b;
    const float e_ll = 0.34f * r - 0.60f * g + 0.17f * b;
    return angle_2pi(e_l, e_ll);
  });
}

FACADESLAM_KERNEL void geusebroek_c_plane(const BgrPlanes& in, cv::Mat& out) {
  for_each_pixel(in, out, [](float r, float g, float b) {
    const float e = 0.06f * r + 0.63f * g + 0.27f * b;  // 0 only for black, where e_l is 0 too
    const float e_l = 0.30f * r + 0.04f * g - 0.35f * b;
    return e_l / (e > 0.0f ? e : 1.0f);
  });
}

}  // namespace

bool ColourInvariantOutputs::any() const {
  for (int i = 0; i < 3; ++i)
    if (gevers_l[i] || gevers_c[i]) return true;
  return geusebroek_h || geusebroek_c;
}

void compute_colour_invariants(const BgrPlanes& in, const ColourInvariantOutputs& out) {
  if (out.gevers_l[0]) gevers_l_plane<0>(in, *out.gevers_l[0]);
  if (out.gevers_l[1]) gevers_l_plane<1>(in, *out.gevers_l[1]);
  if (out.gevers_l[2]) gevers_l_plane<2>(in, *out.gevers_l[2]);
  if (out.gevers_c[0]) gevers_c_plane<0>(in, *out.gevers_c[0]);
  if (out.gevers_c[1]) gevers_c_plane<1>(in, *out.gevers_c[1]);
  if (out.gevers_c[2]) gevers_c_plane<2>(in, *out.gevers_c[2]);
  if (out.geusebroek_h) geusebroek_h_plane(in, *out.geusebroek_h);
  if (out.geusebroek_c) geusebroek_c_plane(in, *out.geusebroek_c);
}

void compute_colour_invariants(const cv::Mat& bgr, const ColourInvariantOutputs& outputs) {
  CV_Assert(bgr.type() == CV_8UC3);
  std::vector<cv::Mat> split;
  cv::split(bgr, split);
  compute_colour_invariants(BgrPlanes{split[0], split[1], split[2]}, outputs);
}

}  // namespace facadeslam::semantics
