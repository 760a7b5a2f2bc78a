#include "semantics/descriptor/extraction.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <vector>

#include "core/util/error.hpp"
#include "semantics/descriptor/module_registry.hpp"
#include "semantics/descriptor/modules/affine_invariants_module.hpp"
#include "semantics/descriptor/modules/singular_values_module.hpp"
#include "semantics/descriptor/modules/strip_sums.hpp"

namespace facadeslam::semantics {
namespace {

// Bits of a channel-major module that belong to channel c.
std::uint64_t channel_bits(std::uint64_t bits, int per_channel, int c) {
  return (bits >> (per_channel * c)) & ((std::uint64_t{1} << per_channel) - 1);
}

void check_compatible(const PreparedImage& image, const DescriptorParams& params) {
  const DescriptorParams& p = image.params;
  if (p.colour_space != params.colour_space || p.gaussian_kernel != params.gaussian_kernel ||
      p.gaussian_sigma != params.gaussian_sigma || p.canny_kernel != params.canny_kernel ||
      p.canny_low_threshold != params.canny_low_threshold || p.gradient_operator != params.gradient_operator)
    throw Error(
        "descriptor extraction: the image was prepared with other preprocessing parameters "
        "(colour space, blur, Canny or gradient operator) than the descriptor's");
  if (params.patch_radius > image.border)
    throw Error("descriptor extraction: patch radius " + std::to_string(params.patch_radius) +
                " exceeds the prepared border of " + std::to_string(image.border) + " pixels");
  const PlaneSet missing = required_planes(params.activation) & ~image.computed;
  for (int p = 0; p < kPlaneCount; ++p)
    if (missing.test(static_cast<std::size_t>(p)))
      throw Error("descriptor extraction: the prepared image lacks the " +
                  std::string(plane_name(static_cast<PlaneId>(p))) + " plane the active values need");
}

void check_keypoint(const cv::Point2f& kp, std::size_t index, cv::Size size) {
  const bool finite = std::isfinite(kp.x) && std::isfinite(kp.y);
  const bool inside =
      finite && cvRound(kp.x) >= 0 && cvRound(kp.x) < size.width && cvRound(kp.y) >= 0 && cvRound(kp.y) < size.height;
  if (inside) return;
  std::ostringstream msg;
  msg << "descriptor extraction: keypoint " << index << " at (" << kp.x << ", " << kp.y << ") is "
      << (finite ? "outside the " : "not finite in the ") << size.width << "x" << size.height << " image";
  throw Error(msg.str());
}

// The angle planes among `planes` (read by the gradient-region module).
PlaneSet angle_planes(const PlaneSet& planes) {
  PlaneSet out;
  for (int c = 0; c < 3; ++c) out.set(plane_bit(angle_plane(c)), planes.test(plane_bit(angle_plane(c))));
  return out;
}

// Indices of the patch centres sorted by row, then column (stable).
std::vector<int> row_major_order(const std::vector<cv::Point>& centres) {
  std::vector<int> order(centres.size());
  for (std::size_t k = 0; k < order.size(); ++k) order[k] = static_cast<int>(k);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
    const cv::Point& pa = centres[static_cast<std::size_t>(a)];
    const cv::Point& pb = centres[static_cast<std::size_t>(b)];
    return pa.y != pb.y ? pa.y < pb.y : pa.x < pb.x;
  });
  return order;
}

}  // namespace

ExtractionPlan plan_extraction(const ActivationMask& activation) {
  ExtractionPlan plan;
  for (int m = 0; m < kModuleCount; ++m) {
    const auto module = static_cast<Module>(m);
    plan.bits[static_cast<std::size_t>(m)] = module_bits(activation, module);
    if (plan.bits[static_cast<std::size_t>(m)]) plan.modules.push_back(module);
  }
  const auto bits = [&](Module m) { return plan.bits[static_cast<std::size_t>(m)]; };
  for (int c = 0; c < 3; ++c) {
    int order = -1;
    const auto need = [&](bool used, int o) {
      if (used) order = std::max(order, o);
    };
    need(channel_bits(bits(Module::moments2), 3, c) != 0, 2);
    need(channel_bits(bits(Module::moments3), 4, c) != 0, 3);
    need(channel_bits(bits(Module::moments4), 5, c) != 0, 4);
    need(channel_bits(bits(Module::moments5), 6, c) != 0, 5);
    need(channel_bits(bits(Module::hu), 7, c) != 0, 3);
    const std::uint64_t affine = channel_bits(bits(Module::affine_invariants), 10, c);
    for (int k = 0; k < 10; ++k) need(((affine >> k) & 1) != 0, affine_invariant_order(k + 1));
    plan.moment_order[static_cast<std::size_t>(c)] = order;
  }
  for (int i = 0; i < kValueCount; ++i)
    if (activation.test(static_cast<std::size_t>(i))) plan.columns.push_back(i);
  return plan;
}

cv::Mat extract(const PreparedImage& image, const std::vector<cv::Point2f>& keypoints, const DescriptorParams& params,
                ExtractionStats* stats) {
  check_compatible(image, params);
  for (std::size_t i = 0; i < keypoints.size(); ++i) check_keypoint(keypoints[i], i, image.image_size);

  const ExtractionPlan plan = plan_extraction(params.activation);
  const int rows = static_cast<int>(keypoints.size());
  const int cols = static_cast<int>(plan.columns.size());
  cv::Mat out(rows, cols, CV_32F);
  if (rows == 0 || cols == 0) return out;

  ExtractionStats local;
  ExtractionStats& counts = stats ? *stats : local;
  const int r = params.patch_radius;
  std::vector<cv::Point> centres(static_cast<std::size_t>(rows));
  for (int k = 0; k < rows; ++k) {
    const cv::Point2f& kp = keypoints[static_cast<std::size_t>(k)];
    centres[static_cast<std::size_t>(k)] = {cvRound(kp.x), cvRound(kp.y)};
  }
  // Keypoints go through row by row: the mean/sigma, gradient-region and
  // moment modules add up column sums shared by the row's keypoints
  // (strip_sums.hpp); rows of the result keep the input order.
  const std::vector<int> order = row_major_order(centres);
  StripSums strip;
  const PlaneSet statistics = required_planes(restricted_to(params.activation, kStatisticsModules));
  const PlaneSet regions = angle_planes(required_planes(params.activation));
  strip.configure(image, r, statistics, regions, plan.moment_order);
  const bool use_strip = strip.any();

  // Singular values go in batches of vector lanes over the keypoints in
  // processing order (a lane's values do not depend on its batch).
  std::vector<float> singular;
  if (const std::uint64_t bits = plan.bits[static_cast<std::size_t>(Module::singular_values)]) {
    std::vector<cv::Point> ordered(order.size());
    for (std::size_t k = 0; k < order.size(); ++k) ordered[k] = centres[static_cast<std::size_t>(order[k])];
    singular.resize(order.size() * kSingularValueCount);
    singular_values_of_patches(image, ordered, r, bits, singular.data());
  }

  std::array<PatchMoments, 3> moments;
  float values[kValueCount];
  std::vector<int> row_centres;
  for (std::size_t at = 0; at < order.size();) {
    const int y = centres[static_cast<std::size_t>(order[at])].y;
    std::size_t end = at;
    row_centres.clear();
    for (; end < order.size() && centres[static_cast<std::size_t>(order[end])].y == y; ++end)
      row_centres.push_back(centres[static_cast<std::size_t>(order[end])].x);
    if (use_strip) strip.compute(y, row_centres);
    for (std::size_t k = at; k < end; ++k) {
      const int index = order[k];
      const cv::Point centre = centres[static_cast<std::size_t>(index)];
      const ModuleContext context{image,
                                  keypoints[static_cast<std::size_t>(index)],
                                  centre.x,
                                  centre.y,
                                  r,
                                  moments,
                                  use_strip ? &strip : nullptr,
                                  singular.empty() ? nullptr : singular.data() + k * kSingularValueCount};
      for (int c = 0; c < 3; ++c) {
        const int moment_order = plan.moment_order[static_cast<std::size_t>(c)];
        if (moment_order < 0) continue;
        strip.moments(c, centre.x, moments[static_cast<std::size_t>(c)]);
        ++counts.moment_calls[static_cast<std::size_t>(c)];
      }
      for (const Module m : plan.modules) {
        module_function(m)(context, plan.bits[static_cast<std::size_t>(m)], values + module_offset(m));
        ++counts.module_calls[static_cast<std::size_t>(m)];
      }
      float* dst = out.ptr<float>(index);
      for (int col = 0; col < cols; ++col) dst[col] = values[plan.columns[static_cast<std::size_t>(col)]];
    }
    at = end;
  }
  counts.keypoints += static_cast<std::uint64_t>(rows);
  return out;
}

std::vector<std::string> active_value_names(const DescriptorParams& params) {
  std::vector<std::string> names;
  for (int i = 0; i < kValueCount; ++i)
    if (params.activation.test(static_cast<std::size_t>(i))) names.push_back(value_name(i));
  return names;
}

}  // namespace facadeslam::semantics
