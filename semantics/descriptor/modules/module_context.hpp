#pragma once
// What a module sees of one keypoint: its patches in the prepared planes and
// the patch moments the extractor computed once for the channels that need
// them. Each module writes only its active values into its slice of the
// 185-value row (bit i of `bits` = the module's i-th value).
#include <array>
#include <cstdint>

#include <opencv2/core.hpp>

#include "semantics/descriptor/modules/patch_moments.hpp"
#include "semantics/descriptor/modules/mean_std.hpp"
#include "semantics/descriptor/modules/strip_sums.hpp"
#include "semantics/descriptor/prepared_image.hpp"

namespace facadeslam::semantics {

struct ModuleContext {
  const PreparedImage& image;
  cv::Point2f keypoint;  // as given
  int x = 0, y = 0;      // the patch centre: the pixel nearest to the keypoint
  int radius = 0;
  const std::array<PatchMoments, 3>& moments;  // per colour channel (order -1 = not computed)
  const StripSums* strip = nullptr;            // column sums of this keypoint's row, where extraction shares them
  // This keypoint's nine singular-value module values, where extraction
  // computed them in batches (singular_values_module.hpp); else null.
  const float* singular_values = nullptr;

  // Mean and sigma of plane p over the patch, from the strip when it has them.
  MeanStd mean_std(PlaneId p) const {
    return strip && strip->has_statistics(p) ? strip->mean_std(p, x) : patch_mean_std(patch(p));
  }

  PatchView patch(PlaneId p) const { return image.patch(p, x, y, radius); }
};

using ModuleFunction = void (*)(const ModuleContext& context, std::uint64_t bits, float* values);

inline bool bit_set(std::uint64_t bits, int i) { return ((bits >> i) & 1) != 0; }

}  // namespace facadeslam::semantics
