#pragma once
// Degree/radian conversion: configs and reports speak degrees, the maths
// radians.
#include <numbers>

namespace facadeslam {

constexpr double deg_to_rad(double degrees) { return degrees * (std::numbers::pi / 180.0); }
constexpr double rad_to_deg(double radians) { return radians * (180.0 / std::numbers::pi); }

}  // namespace facadeslam
