#pragma once
// The invariance cases of thesis IV.5, each a curve over one parameter:
//
// | name              | parameter                 | default values                      |
// |-------------------|---------------------------|-------------------------------------|
// | blur              | Gaussian kernel size (px) | 1 3 5 7 9 11 15                     |
// | rotation          | angle (deg, ccw)          | 0 10 20 30 45 90 180                |
// | resize            | scale factor              | 0.25 0.5 0.75 1 1.25 1.5 2          |
// | affine            | case (geometric_transforms.hpp) | 0 (identity) 1 .. 10          |
// | intensity-scale   | factor a (eq. III.37)     | 0.25 0.5 0.75 1 1.5 2 3             |
// | intensity-shift   | offset o1 (eq. III.38)    | -100 -50 -25 0 25 50 100            |
// | temperature       | illuminant (K)            | 2500 3000 3800 5000 6500 8000 10000 |
// | jpeg              | JPEG quality              | 10 20 30 50 70 90 100               |
//
// Every default list holds the case's identity (blur 1, angle 0, factor 1,
// affine 0, offset 0, 6500 K) where one exists, so each curve shows its own
// reference; JPEG has no identity (quality 100 is the nearest).
#include <array>
#include <string_view>
#include <vector>

#include <opencv2/core.hpp>

#include "semantics/invariance/transformed_image.hpp"

namespace facadeslam::semantics {

enum class InvarianceCase { blur, rotation, resize, affine, intensity_scale, intensity_shift, temperature, jpeg };

struct InvarianceCaseInfo {
  InvarianceCase id;
  std::string_view name;       // as in reports and on the command line
  std::string_view title;      // plot title
  std::string_view parameter;  // axis label
};

inline constexpr std::array<InvarianceCaseInfo, 8> kInvarianceCases{{
    {InvarianceCase::blur, "blur", "Gaussian blur", "kernel size (px)"},
    {InvarianceCase::rotation, "rotation", "Rotation", "angle (deg)"},
    {InvarianceCase::resize, "resize", "Resize", "scale factor"},
    {InvarianceCase::affine, "affine", "Affine (tilt)", "case (0 = identity)"},
    {InvarianceCase::intensity_scale, "intensity-scale", "Light intensity scale", "factor a"},
    {InvarianceCase::intensity_shift, "intensity-shift", "Light intensity shift", "offset o1"},
    {InvarianceCase::temperature, "temperature", "Illuminant colour", "colour temperature (K)"},
    {InvarianceCase::jpeg, "jpeg", "JPEG compression", "quality"},
}};

const InvarianceCaseInfo& case_info(InvarianceCase id);
// Throws Error naming the known cases for an unknown name.
InvarianceCase case_by_name(std::string_view name);

std::vector<double> default_case_values(InvarianceCase id);

// Throws Error ("<case name>: <value> ... expected ...") for an empty list or
// a value the case cannot use: blur kernel odd 1..99; angle -360..360; resize
// factor 0.1..4; affine case integer 0..10; intensity factor 0.01..10; shift
// -255..255; temperature 1000..40000 K; JPEG quality integer 0..100.
void check_case_values(InvarianceCase id, const std::vector<double>& values);

// `bgr` changed by case `id` at `value` (a value check_case_values accepts).
TransformedImage apply_case(InvarianceCase id, double value, const cv::Mat& bgr);

}  // namespace facadeslam::semantics
