#pragma once
#include "semantics/descriptor/modules/module_context.hpp"

namespace facadeslam::semantics {

// Module 12: mean and sigma of the distance to the nearest Canny edge over
// the patch (thesis III.4.4): flat areas give large, even values.
void edge_distance_module(const ModuleContext& context, std::uint64_t bits, float* values);

}  // namespace facadeslam::semantics
