#pragma once
// Module 11: Flusser-Suk affine moment invariants I1..I10 per colour channel
// (thesis eq. III.36, Suk & Flusser 2004), from the central moments mu_pq
// normalised by powers of mu00. The formulas are the thesis' except I9,
// where the thesis prints 4 mu21^4 mu04: with that factor I9 changes under
// an affine map; Suk & Flusser's coefficient 1 makes it invariant (checked
// numerically on affinely mapped point sets, and by the unit tests).
// Invariance holds for a pattern wholly inside the patch; a patch window
// cut out of a larger image is not itself affine covariant.
#include <array>

#include "semantics/descriptor/modules/module_context.hpp"

namespace facadeslam::semantics {

// Highest moment order I_k needs (k = 1..10).
int affine_invariant_order(int k);

// I_k (k = 1..10); `moments` must be computed to affine_invariant_order(k).
double affine_invariant(const PatchMoments& moments, int k);

// Values [I1..I10] x 3 channels.
void affine_invariants_module(const ModuleContext& context, std::uint64_t bits, float* values);

}  // namespace facadeslam::semantics
