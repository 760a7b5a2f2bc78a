#pragma once
// Module 14: mean gradient angle of each colour channel over the whole patch
// (region 00) and its four r x r quadrants (11 top-left, 12 top-right,
// 21 bottom-left, 22 bottom-right; the centre row and column belong only to
// the whole patch), thesis IV.4.3 (14) and Figure 4.5; then the ten
// differences between those five means (00-11, 00-12, 00-21, 00-22, 11-12,
// 11-21, 11-22, 12-21, 12-22, 21-22). Angles are the per-pixel
// atan2(gy, gx) in [0, 2pi) of preprocessing step 5, averaged arithmetically
// as the thesis does (no circular mean); differences are plain differences.
// Layout: [5 means] x 3 channels, then [10 differences] x 3 channels.
#include <array>

#include "semantics/descriptor/modules/module_context.hpp"

namespace facadeslam::semantics {

// Means of the whole patch and the quadrants 11, 12, 21, 22, in that order.
std::array<double, 5> gradient_region_means(const PatchView& angles);

// The same from the patch's 2r+1 column sums of the r rows above (`top`) and
// the r rows below (`bottom`) the centre row, and the centre row itself
// (`middle`); shared by the patch kernel and the strip sums (strip_sums.hpp)
// so that both add up in the same order.
std::array<double, 5> region_means_from_columns(const float* top, const float* bottom, const float* middle, int r);

void gradient_angles_module(const ModuleContext& context, std::uint64_t bits, float* values);

}  // namespace facadeslam::semantics
