#include "semantics/descriptor/modules/gradient_angles_module.hpp"

#include "semantics/descriptor/kernel_support.hpp"

namespace facadeslam::semantics {
namespace {

constexpr int kPairs[10][2] = {{0, 1}, {0, 2}, {0, 3}, {0, 4}, {1, 2}, {1, 3}, {1, 4}, {2, 3}, {2, 4}, {3, 4}};

template <int W>
[[gnu::always_inline]] inline std::array<double, 5> region_means_lanes(const PatchView& angles) {
  const int r = angles.radius;
  // Column sums of the upper and lower halves (vector adds over x), reduced
  // per quadrant at the end.
  alignas(32) float top[W] = {};
  alignas(32) float bottom[W] = {};
  for (int i = 0; i < r; ++i) {
    const float* up = angles.row(i);
    const float* down = angles.row(r + 1 + i);
    for (int x = 0; x < W; ++x) {
      top[x] += up[x];
      bottom[x] += down[x];
    }
  }
  return region_means_from_columns(top, bottom, angles.row(r), r);
}

}  // namespace

std::array<double, 5> region_means_from_columns(const float* top, const float* bottom, const float* middle, int r) {
  const int n = 2 * r + 1;
  double q11 = 0, q12 = 0, q21 = 0, q22 = 0, cross = static_cast<double>(top[r]) + bottom[r];
  for (int x = 0; x < r; ++x) {
    q11 += top[x];
    q21 += bottom[x];
    q12 += top[r + 1 + x];
    q22 += bottom[r + 1 + x];
  }
  for (int x = 0; x < n; ++x) cross += middle[x];
  const double quadrant = static_cast<double>(r) * r;
  return {(q11 + q12 + q21 + q22 + cross) / (static_cast<double>(n) * n), q11 / quadrant, q12 / quadrant,
          q21 / quadrant, q22 / quadrant};
}

FACADESLAM_KERNEL
std::array<double, 5> gradient_region_means(const PatchView& angles) {
  CV_Assert(angles.radius >= 1);
  switch (lane_width(angles.size())) {
    case 8: return region_means_lanes<8>(angles);
    case 16: return region_means_lanes<16>(angles);
    case 24: return region_means_lanes<24>(angles);
    default: break;
  }
  CV_Error(cv::Error::StsOutOfRange, "patch radius exceeds the kernels' 10 pixels");
}

void gradient_angles_module(const ModuleContext& context, std::uint64_t bits, float* values) {
  for (int c = 0; c < 3; ++c) {
    const std::uint64_t means = (bits >> (5 * c)) & 0x1F;
    const std::uint64_t differences = (bits >> (15 + 10 * c)) & 0x3FF;
    if (!means && !differences) continue;
    const PlaneId plane = angle_plane(c);
    const std::array<double, 5> m = context.strip && context.strip->has_regions(plane)
                                        ? context.strip->region_means(plane, context.x)
                                        : gradient_region_means(context.patch(plane));
    for (int k = 0; k < 5; ++k)
      if (bit_set(means, k)) values[5 * c + k] = static_cast<float>(m[static_cast<std::size_t>(k)]);
    for (int k = 0; k < 10; ++k)
      if (bit_set(differences, k)) values[15 + 10 * c + k] = static_cast<float>(m[kPairs[k][0]] - m[kPairs[k][1]]);
  }
}

}  // namespace facadeslam::semantics
