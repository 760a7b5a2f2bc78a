#pragma once
#include "semantics/descriptor/modules/module_context.hpp"

namespace facadeslam::semantics {

// Modules 3-6: the normalised central moments eta_pq of one order per colour
// channel, grouped by channel, p descending: order 2 gives
// [eta20 eta11 eta02] x 3 channels, order 5 [eta50 eta41 .. eta05] x 3.
void central_moments_module(int order, const ModuleContext& context, std::uint64_t bits, float* values);

void moments2_module(const ModuleContext& context, std::uint64_t bits, float* values);
void moments3_module(const ModuleContext& context, std::uint64_t bits, float* values);
void moments4_module(const ModuleContext& context, std::uint64_t bits, float* values);
void moments5_module(const ModuleContext& context, std::uint64_t bits, float* values);

}  // namespace facadeslam::semantics
