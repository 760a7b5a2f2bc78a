#pragma once
// Module 13: the three largest singular values of each colour channel's
// (2r+1) x (2r+1) patch, read as a matrix (thesis IV.4.3 (13), "eigen
// values"): [sigma1 sigma2 sigma3] x 3 channels, computing per channel only
// up to the highest active one.
//
// A full SVD per patch and channel would cost more than the rest of the
// descriptor, so the values come from a symmetric Lanczos iteration with
// full reorthogonalisation on the patch's Gram matrix G = A^T A, started
// from the column sums (close to the leading singular vector of a
// non-negative patch): 3 steps per wanted value (3 for sigma1 alone, 9 for
// sigma1..3), then the eigenvalues of the small tridiagonal matrix, whose
// square roots are the singular values. k steps on G give the same Ritz
// values as k Golub-Kahan bidiagonalisation steps on A; it is exact once the
// steps reach 2r+1. The tests check 1e-4 sigma1 against a full SVD on
// synthetic textures. The step count depends on the highest active value of
// the channel, so sigma1 may differ in its last float digits between genomes.
//
// Patches are processed kSingularValueLanes at a time, one per vector lane
// (any keypoints, any channels of one size): the iteration has no
// horizontal sums, and a patch's values do not depend on the other patches
// of its batch.
#include <cstdint>
#include <vector>

#include "semantics/descriptor/modules/module_context.hpp"

namespace facadeslam::semantics {

inline constexpr int kSingularValueLanes = 8;
inline constexpr int kSingularValueCount = 9;  // the module's values

// Writes the `count` (1..3) largest singular values of `patch`, descending,
// to `out`; returns the number of Lanczos steps taken.
int top_singular_values(const PatchView& patch, int count, double* out);

// The same for 1..kSingularValueLanes patches of one size at once: out[l]
// gets the `count` values of patches[l], steps[l] the steps taken (0 for a
// zero patch), when steps is not null.
void top_singular_values(const PatchView* patches, int lanes, int count, double (*out)[3], int* steps = nullptr);

// The module's active values (bits) for the patches of `radius` centred on
// `centres`, in batches: keypoint k's nine module values start at
// values[kSingularValueCount * k] (inactive ones are left as they were).
void singular_values_of_patches(const PreparedImage& image, const std::vector<cv::Point>& centres, int radius,
                                std::uint64_t bits, float* values);

// One keypoint: copies context.singular_values when the extractor computed
// them in batches, else computes them alone.
void singular_values_module(const ModuleContext& context, std::uint64_t bits, float* values);

}  // namespace facadeslam::semantics
