#pragma once
// Module 13: the three largest singular values of each colour channel's
// (2r+1) x (2r+1) patch, read as a matrix (thesis IV.4.3 (13), "eigen
// values"): [sigma1 sigma2 sigma3] x 3 channels, computing per channel only
// up to the highest active one.
//
// A full SVD per patch and channel would cost more than the rest of the
// descriptor, so the values come from a Golub-Kahan-Lanczos
// bidiagonalisation of the patch with full reorthogonalisation, started from
// its column sums (close to the leading singular vector of a non-negative
// patch): 3 steps per wanted value (3 for sigma1 alone, 9 for sigma1..3),
// then the singular values of the small bidiagonal matrix. It works on the
// singular values, not their squares, so float vectors resolve small ones,
// and it is exact once the steps reach 2r+1. On the 3 x ~3,500 grid patches
// of a 640 x 480 facade photo (r = 3, 6, 10) the largest deviations from a
// full SVD were 6e-7 sigma1 for sigma1, 4e-5 sigma1 for sigma2 and 3e-7 sigma1
// for sigma3 (tests/semantics checks 1e-4 sigma1 on synthetic textures). The
// step count depends on the highest active value of the channel, so sigma1
// may differ in its last float digits between genomes.
#include <cstdint>

#include "semantics/descriptor/modules/module_context.hpp"

namespace facadeslam::semantics {

// Writes the `count` (1..3) largest singular values of `patch`, descending,
// to `out`; returns the number of Lanczos steps taken.
int top_singular_values(const PatchView& patch, int count, double* out);

void singular_values_module(const ModuleContext& context, std::uint64_t bits, float* values);

}  // namespace facadeslam::semantics
