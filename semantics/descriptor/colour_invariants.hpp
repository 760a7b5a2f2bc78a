#pragma once
// Photometric colour invariants of the blurred RGB image (thesis III.4.2):
//
//   Gevers l:  l1 = (R-G)^2 / D, l2 = (R-B)^2 / D, l3 = (G-B)^2 / D with
//              D = (R-G)^2 + (R-B)^2 + (G-B)^2. The thesis prints D with minus
//              signs, a transcription slip: Gevers & Smeulders (1999) sum
//              the three terms, so l1 + l2 + l3 = 1. Achromatic pixels
//              (D = 0) have no hue direction and get l = 0.
//   Gevers c:  c1 = atan(R / max(G, B)), c2 = atan(G / max(R, B)),
//              c3 = atan(B / max(R, G)), radians in [0, pi/2]
//              (computed as atan2, so 0/0 gives 0 and R/0 gives pi/2).
//   Arctangents use fast_math.hpp (error below 1.2e-5 rad).
//   Geusebroek: E, E_l, E_ll = the Gaussian colour model (eq. III.27) of RGB;
//              H = atan2(E_l, E_ll) in [0, 2pi): the thesis' ratio
//              E_l / E_ll (eq. III.28) as an angle, which keeps its
//              invariance but stays bounded where E_ll crosses zero, so one
//              pixel cannot dominate a patch mean (Geusebroek et al. 2001
//              also read the ratio as a hue angle);
//              C = E_l / E (eq. III.29), 0 where E = 0 (black).
// All are unchanged when R, G, B are scaled by a common factor.
#include <opencv2/core.hpp>

#include "semantics/descriptor/colour_conversion.hpp"

namespace facadeslam::semantics {

// Pointers to the destinations (CV_32F, image size, written in place);
// null entries are not computed.
struct ColourInvariantOutputs {
  cv::Mat* gevers_l[3] = {nullptr, nullptr, nullptr};
  cv::Mat* gevers_c[3] = {nullptr, nullptr, nullptr};
  cv::Mat* geusebroek_h = nullptr;
  cv::Mat* geusebroek_c = nullptr;

  bool any() const;
};

// From the blurred image split into 8-bit planes (the invariants do not
// depend on the scale of R, G, B, so they use the 0..255 values directly).
void compute_colour_invariants(const BgrPlanes& planes, const ColourInvariantOutputs& outputs);
// Convenience for tools and tests: splits the CV_8UC3 `bgr` itself.
void compute_colour_invariants(const cv::Mat& bgr, const ColourInvariantOutputs& outputs);

}  // namespace facadeslam::semantics
