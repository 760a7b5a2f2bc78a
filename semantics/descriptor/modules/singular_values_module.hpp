#pragma once
// Module 13: the three largest singular values of each colour channel's
// (2r+1) x (2r+1) patch, read as a matrix (thesis IV.4.3 (13), "eigen
// values"): [sigma1 sigma2 sigma3] x 3 channels, computing per channel only
// up to the highest active one.
//
// A full SVD per patch and channel would cost more than the rest of the
// descriptor, so the values come from a symmetric Lanczos iteration with
// full reorthogonalisation on the patch's Gram matrix G = A^T A (float
// products, double iteration), started from the column sums (close to the
// leading singular vector of a non-negative patch): 3 steps per wanted value
// (3 for sigma1 alone, 9 for sigma1..3), then the eigenvalues of the small
// tridiagonal matrix, whose square roots are the singular values. k steps
// on G give the same Ritz values as k Golub-Kahan bidiagonalisation steps on
// A; forming G once (n^2 (2r+1) / 2 multiply-adds) makes every step a
// single n x n product instead of one with A and one with A^T. It is exact
// once the steps reach 2r+1. The tests check 1e-4 sigma1 against a full SVD
// on synthetic textures. The step count depends on the highest active value
// of the channel, so sigma1 may differ in its last float digits between
// genomes.
#include <cstdint>

#include "semantics/descriptor/modules/module_context.hpp"

namespace facadeslam::semantics {

// Writes the `count` (1..3) largest singular values of `patch`, descending,
// to `out`; returns the number of Lanczos steps taken.
int top_singular_values(const PatchView& patch, int count, double* out);

// The same for up to three patches of one size at once (the colour channels
// of a keypoint), stepped in lockstep: out[i] gets the counts[i] values of
// patches[i]; steps[i] the steps taken, when steps is not null.
void top_singular_values(const PatchView* patches, const int* counts, int channels, double (*out)[3], int* steps);

void singular_values_module(const ModuleContext& context, std::uint64_t bits, float* values);

}  // namespace facadeslam::semantics
