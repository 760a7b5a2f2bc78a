#pragma once
// Intensity-weighted moments of a patch (thesis III.4.2, eqs. III.31-34):
// raw M_pq = sum x^p y^q I(x, y) with x to the right and y down, measured
// from the patch centre; central mu_pq about the intensity centroid; and the
// normalised eta_pq = mu_pq / mu00^(1 + (p+q)/2). Shared by the central
// moment, Hu and affine-invariant modules, computed once per channel.
#include <cstddef>

#include "semantics/descriptor/modules/patch_view.hpp"

namespace facadeslam::semantics {

inline constexpr int kMaxMomentOrder = 5;

struct PatchMoments {
  int order = -1;                                            // highest p+q computed
  double mu[kMaxMomentOrder + 1][kMaxMomentOrder + 1] = {};  // central mu[p][q]; mu[0][0] = mass
  double eta_scale[kMaxMomentOrder + 1] = {};                // 1 / mu00^(1 + k/2), 0 without mass
  double mass_powers[15] = {};                               // mu00^k, k = 0..14 (affine invariants)

  double mass() const { return mu[0][0]; }
  // Normalised central moment; 0 for a patch without mass.
  double eta(int p, int q) const { return mu[p][q] * eta_scale[p + q]; }
};

// Moments up to `order` (0..5): mu[p][q] for p + q <= order, every
// eta_scale and mass_powers entry; entries above `order` keep what `out`
// held. A patch whose total intensity is not positive (e.g. all black) has
// all moments 0. Reads rows with the slack of PatchView::kReadSlack.
void compute_patch_moments(const PatchView& patch, int order, PatchMoments& out);

// The same in two halves, for patches that share a centre row (StripSums):
//  - moment_column_sums: the sums over rows dy = -r..r of dy^q I(x, row + dy),
//    q = 0..order, for the `count` columns x from `centre` (a pointer into
//    the centre row, rows `stride` floats apart), interleaved: column x's
//    sums at columns[kMomentColumnStride * x + q] (zero past the order). It
//    works in whole blocks of 8 columns: it reads and writes up to 7 columns
//    past `count` (PatchView::kReadSlack; `columns` must be as wide);
//  - patch_moments_from_columns: the moments of the patch whose first
//    column's sums `columns` points at.
// Bit-identical to compute_patch_moments of the same patch.
inline constexpr int kMomentColumnStride = 8;
void moment_column_sums(const float* centre, std::ptrdiff_t stride, int r, int order, int count, float* columns);
void patch_moments_from_columns(const float* columns, int r, int order, PatchMoments& out);

// Central moments mu[p][q] (p + q <= order, 0..5) from raw moments
// raw[p][q] = sum of x^p y^q w about any origin, for weights w of the
// caller's own (EDD's normalised intensity); raw[0][0] must be positive.
void central_moments_from_raw(const double (*raw)[kMaxMomentOrder + 1], int order, double (*mu)[kMaxMomentOrder + 1]);

}  // namespace facadeslam::semantics
