#include "semantics/descriptor/extraction.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/util/error.hpp"
#include "semantics/descriptor/module_registry.hpp"
#include "semantics/descriptor/modules/affine_invariants_module.hpp"

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
    throw Error("descriptor extraction: the image was prepared with other preprocessing parameters "
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
  const bool inside = finite && cvRound(kp.x) >= 0 && cvRound(kp.x) < size.width && cvRound(kp.y) >= 0 &&
                      cvRound(kp.y) < size.height;
  if (inside) return;
  std::ostringstream msg;
  msg << "descriptor extraction: keypoint " << index << " at (" << kp.x << ", " << kp.y << ") is "
      << (finite ? "outside the " : "not finite in the ") << size.width << "x" << size.height << " image";
  throw Error(msg.str());
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

cv::Mat extract(const PreparedImage& image, const std::vector<cv::Point2f>& keypoints,
                const DescriptorParams& params, ExtractionStats* stats) {
  check_compatible(image, params);
  for (std::size_t i = 0; i < keypoints.size(); ++i) check_keypoint(keypoints[i], i, image.image_size);

  const ExtractionPlan plan = plan_extraction(params.activation);
  const int rows = static_cast<int>(keypoints.size());
  const int cols = static_cast<int>(plan.columns.size());
  cv::Mat out(rows, cols, CV_32F);
  if (rows == 0 || cols == 0) return out;

  ExtractionStats local;
  ExtractionStats& counts = stats ? *stats : local;
  std::array<PatchMoments, 3> moments;
  float values[kValueCount];
  // The planes a module reads, for prefetching the next keypoint's patch.
  std::vector<const cv::Mat*> read_planes;
  for (int p = 0; p < kPlaneCount; ++p)
    if (image.computed.test(static_cast<std::size_t>(p)) &&
        required_planes(params.activation).test(static_cast<std::size_t>(p)))
      read_planes.push_back(&image.planes[static_cast<std::size_t>(p)]);
  for (int row = 0; row < rows; ++row) {
    if (row + 1 < rows) {
      // Neighbouring keypoints (a grid, or corners along an edge) share most
      // of their patch rows, so the next patch's right edge is what is not
      // in cache yet: one prefetch per row and plane, while this keypoint
      // computes.
      const cv::Point2f next = keypoints[static_cast<std::size_t>(row) + 1];
      const int right = cvRound(next.x) + image.border + params.patch_radius;
      const int top = cvRound(next.y) + image.border - params.patch_radius;
      for (const cv::Mat* plane : read_planes)
        for (int i = 0; i <= 2 * params.patch_radius; ++i) __builtin_prefetch(plane->ptr<float>(top + i) + right);
    }
    const cv::Point2f kp = keypoints[static_cast<std::size_t>(row)];
    const ModuleContext context{image, kp, cvRound(kp.x), cvRound(kp.y), params.patch_radius, moments};
    for (int c = 0; c < 3; ++c) {
      const int order = plan.moment_order[static_cast<std::size_t>(c)];
      if (order < 0) continue;
      compute_patch_moments(context.patch(colour_plane(c)), order, moments[static_cast<std::size_t>(c)]);
      ++counts.moment_calls[static_cast<std::size_t>(c)];
    }
    for (const Module m : plan.modules) {
      module_function(m)(context, plan.bits[static_cast<std::size_t>(m)], values + module_offset(m));
      ++counts.module_calls[static_cast<std::size_t>(m)];
    }
    float* dst = out.ptr<float>(row);
    for (int col = 0; col < cols; ++col) dst[col] = values[plan.columns[static_cast<std::size_t>(col)]];
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
