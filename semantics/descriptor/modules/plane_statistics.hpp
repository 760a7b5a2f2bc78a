#pragma once
// Mean and standard deviation of a patch (thesis eq. III.30, population
// sigma), shared by every "mean and sigma of ..." module.
#include <cstdint>

#include "semantics/descriptor/modules/mean_std.hpp"
#include "semantics/descriptor/modules/module_context.hpp"

namespace facadeslam::semantics {

// For a module laid out as [mean of planes[0..k), std of planes[0..k)]:
// computes the statistics of each plane with an active mean or std and
// writes the active ones.
void mean_std_values(const ModuleContext& context, const PlaneId* planes, int k, std::uint64_t bits, float* values);

}  // namespace facadeslam::semantics
