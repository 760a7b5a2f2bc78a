#pragma once
// Mean and standard deviation of a patch (thesis eq. III.30, population
// sigma): the patch kernel, which strip_sums.hpp shares between keypoints
// on one row.
#include "semantics/descriptor/modules/patch_view.hpp"

namespace facadeslam::semantics {

struct MeanStd {
  double mean = 0.0;
  double std = 0.0;
};

MeanStd patch_mean_std(const PatchView& patch);

}  // namespace facadeslam::semantics
