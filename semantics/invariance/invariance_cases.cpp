#include "semantics/invariance/invariance_cases.hpp"

#include <cmath>
#include <cstdio>
#include <string>

#include "core/util/error.hpp"
#include "semantics/invariance/geometric_transforms.hpp"
#include "semantics/invariance/photometric_transforms.hpp"
#include "semantics/text.hpp"

namespace facadeslam::semantics {
namespace {

std::string number_text(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", v);
  return text;
}

struct Limits {
  double lo, hi;
  bool integer;
  bool odd;
};

Limits limits_of(InvarianceCase id) {
  switch (id) {
    case InvarianceCase::blur: return {1, 99, true, true};
    case InvarianceCase::rotation: return {-360, 360, false, false};
    case InvarianceCase::resize: return {0.1, 4, false, false};
    case InvarianceCase::affine: return {0, kAffineCaseCount, true, false};
    case InvarianceCase::intensity_scale: return {0.01, 10, false, false};
    case InvarianceCase::intensity_shift: return {-255, 255, false, false};
    case InvarianceCase::temperature: return {1000, 40000, false, false};
    case InvarianceCase::jpeg: return {0, 100, true, false};
  }
  throw Error("invariance: unknown case");
}

std::string expectation(const Limits& l) {
  std::string text = l.odd ? "an odd integer" : l.integer ? "an integer" : "a number";
  return text.append(" from ").append(number_text(l.lo)).append(" to ").append(number_text(l.hi));
}

}  // namespace

const InvarianceCaseInfo& case_info(InvarianceCase id) {
  for (const InvarianceCaseInfo& info : kInvarianceCases)
    if (info.id == id) return info;
  throw Error("invariance: unknown case");
}

InvarianceCase case_by_name(std::string_view name) {
  std::string known;
  for (const InvarianceCaseInfo& info : kInvarianceCases) {
    if (info.name == name) return info.id;
    known.append(known.empty() ? "" : ", ").append(info.name);
  }
  throw Error(cat("unknown invariance case '", name, "' (expected one of ", known, ")"));
}

std::vector<double> default_case_values(InvarianceCase id) {
  switch (id) {
    case InvarianceCase::blur: return {1, 3, 5, 7, 9, 11, 15};
    case InvarianceCase::rotation: return {0, 10, 20, 30, 45, 90, 180};
    case InvarianceCase::resize: return {0.25, 0.5, 0.75, 1, 1.25, 1.5, 2};
    case InvarianceCase::affine: return {0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10};
    case InvarianceCase::intensity_scale: return {0.25, 0.5, 0.75, 1, 1.5, 2, 3};
    case InvarianceCase::intensity_shift: return {-100, -50, -25, 0, 25, 50, 100};
    case InvarianceCase::temperature: return {2500, 3000, 3800, 5000, 6500, 8000, 10000};
    case InvarianceCase::jpeg: return {10, 20, 30, 50, 70, 90, 100};
  }
  throw Error("invariance: unknown case");
}

void check_case_values(InvarianceCase id, const std::vector<double>& values) {
  const std::string_view name = case_info(id).name;
  if (values.empty()) throw Error(cat(name, ": expected at least one value"));
  const Limits l = limits_of(id);
  for (const double v : values) {
    const bool in_range = std::isfinite(v) && v >= l.lo && v <= l.hi;
    const bool integral = !l.integer || (in_range && v == std::round(v));
    const bool odd = !l.odd || (integral && static_cast<long>(v) % 2 != 0);
    if (!(in_range && integral && odd))
      throw Error(cat(name, ": ", number_text(v), " is not a valid ", case_info(id).parameter, " (expected ",
                      expectation(l), ")"));
  }
}

TransformedImage apply_case(InvarianceCase id, double value, const cv::Mat& bgr) {
  check_case_values(id, {value});
  const int whole = static_cast<int>(std::lround(value));
  switch (id) {
    case InvarianceCase::blur: return same_geometry(blur_image(bgr, whole));
    case InvarianceCase::rotation: return rotate_image(bgr, value);
    case InvarianceCase::resize: return resize_image(bgr, value);
    case InvarianceCase::affine: return affine_image(bgr, whole);
    case InvarianceCase::intensity_scale: return same_geometry(scale_intensity(bgr, value));
    case InvarianceCase::intensity_shift: return same_geometry(shift_intensity(bgr, value));
    case InvarianceCase::temperature: return same_geometry(change_illuminant(bgr, value));
    case InvarianceCase::jpeg: return same_geometry(jpeg_round_trip(bgr, whole));
  }
  throw Error("invariance: unknown case");
}

}  // namespace facadeslam::semantics
