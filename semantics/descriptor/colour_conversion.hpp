#pragma once
// Colour-space conversion of the blurred 8-bit image into three float
// planes, each mapped into [0, 1] so that every channel is a non-negative
// "intensity" the moment modules can weight with:
//
//   RGB          R/255, G/255, B/255
//   XYZ          OpenCV's sRGB/D65 matrix on RGB in [0,1]:
//                X in [0, 0.951], Y in [0, 1], Z in [0, 1.089]
//   YCrCb        thesis eq. III.9 on RGB in [0,1] (delta 0.5): Y, Cr, Cb in [0, 1]
//   OpponentRGB  eq. III.12 rescaled: (R-G)/2 + 1/2, (R+G-2B)/4 + 1/2, (R+G+B)/3
//   Lab, Luv, HSV, HLS
//                OpenCV's 8-bit conversions (sRGB input; HSV/HLS with the
//                full 0..255 hue range) divided by 255:
//                Lab: L/100, (a+128)/255, (b+128)/255;
//                Luv: L/100, (u+134)/354, (v+140)/262;
//                HSV: H, S, V;  HLS: H, L, S, where H is OpenCV's
//                full-range hue byte (256 per turn) / 255, i.e. ~hue / 360.
// (Linear maps may leave a float rounding error of ~1e-7 outside [0, 1].)
#include <array>

#include <opencv2/core.hpp>

#include "semantics/descriptor/descriptor_params.hpp"

namespace facadeslam::semantics {

// The blurred image as three 8-bit planes (cv::split of the BGR image).
struct BgrPlanes {
  cv::Mat b, g, r;
};

// Converts into the channels whose `outputs[c]` is not null; each output
// must already be a CV_32F matrix of the image size (typically the interior
// of a padded plane) and is written in place. `bgr` is the interleaved
// image, `planes` the same split (linear spaces read the planes).
void convert_colour(const cv::Mat& bgr, const BgrPlanes& planes, ColourSpace space,
                    const std::array<cv::Mat*, 3>& outputs);

// Convenience for tools and tests: splits `bgr` itself.
void convert_colour(const cv::Mat& bgr, ColourSpace space, const std::array<cv::Mat*, 3>& outputs);

// The non-linear spaces (Lab, Luv, HSV, HLS) are OpenCV's 8-bit conversion
// of `bgr` (CV_8UC3, into `bytes`) with each byte then scaled to a float:
// byte_values()[k] is the float convert_colour makes of byte k. Callers
// that need these channels as tables (EDD) use the two so that they cannot
// drift from convert_colour.
void convert_colour_bytes(const cv::Mat& bgr, ColourSpace space, cv::Mat& bytes);
const std::array<float, 256>& byte_values();

// Channel names of a colour space ("X", "Y", "Z"; "O1", "O2", "O3"; ...).
std::array<const char*, 3> channel_names(ColourSpace space);

}  // namespace facadeslam::semantics
