#pragma once
// Module 7: Hu's seven moment invariants per colour channel (thesis eq.
// III.35, Hu 1962), from the normalised central moments. The thesis prints
// phi2 = (eta20 - eta02)^2 + eta11^2 and phi3 = (eta30 - eta12)^2 +
// (eta21 - eta03)^2; those drop the factors 4 and 3 of Hu's definitions and
// would not be rotation invariant, so Hu's (and OpenCV's) forms are used:
// phi2 = (eta20 - eta02)^2 + 4 eta11^2, phi3 = (eta30 - 3 eta12)^2 + (3 eta21 - eta03)^2.
#include <array>

#include "semantics/descriptor/modules/module_context.hpp"

namespace facadeslam::semantics {

// phi1..phi7 of moments computed to order >= 3.
std::array<double, 7> hu_invariants(const PatchMoments& moments);

// Values [phi1..phi7] x 3 channels.
void hu_module(const ModuleContext& context, std::uint64_t bits, float* values);

}  // namespace facadeslam::semantics
