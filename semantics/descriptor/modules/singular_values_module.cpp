#include "semantics/descriptor/modules/singular_values_module.hpp"

#include <algorithm>
#include <cmath>

#include "semantics/descriptor/descriptor_params.hpp"
#include "semantics/descriptor/kernel_support.hpp"

namespace facadeslam::semantics {
namespace {

constexpr int kMaxSize = 2 * kMaxPatchRadius + 1;
// Bidiagonalisation steps per wanted singular value (see the header).
constexpr int kStepsPerValue = 3;
constexpr int kMaxSteps = 3 * kStepsPerValue;

// Eigenvalues of the m x m symmetric tridiagonal matrix with diagonal d and
// off-diagonal e[0..m-2] (e[m-1] is scratch), left in d (unordered): the
// implicit QL iteration with Wilkinson shifts. A general dense solver costs
// more than the whole bidiagonalisation at these sizes (m <= 9).
void tridiagonal_eigenvalues(double* d, double* e, int m) {
  e[m - 1] = 0.0;
  double norm = 0.0;  // a bound on |T|: off-diagonals below 1e-15 |T| are negligible
  for (int i = 0; i < m; ++i) norm = std::max(norm, std::abs(d[i]) + 2.0 * std::abs(e[i]));
  const double negligible = 1e-15 * norm;
  for (int l = 0; l < m; ++l) {
    for (int iteration = 0; iteration < 60; ++iteration) {
      int k = l;  // the first negligible off-diagonal at or after l splits the matrix
      while (k + 1 < m && std::abs(e[k]) > negligible) ++k;
      if (k == l) break;  // d[l] is an eigenvalue
      // Shift: the eigenvalue of the leading 2x2 block closer to d[l].
      double g = (d[l + 1] - d[l]) / (2.0 * e[l]);
      double r = std::sqrt(g * g + 1.0);
      g = d[k] - d[l] + e[l] / (g + std::copysign(r, g));
      double s = 1.0, c = 1.0, p = 0.0;
      bool deflated = false;
      for (int i = k - 1; i >= l; --i) {  // chase the bulge up with Givens rotations
        const double f = s * e[i];
        const double b = c * e[i];
        r = std::sqrt(f * f + g * g);
        e[i + 1] = r;
        if (r == 0.0) {  // an exact split: restart from the top
          d[i + 1] -= p;
          e[k] = 0.0;
          deflated = true;
          break;
        }
        s = f / r;
        c = g / r;
        g = d[i + 1] - p;
        r = (d[i] - g) * s + 2.0 * c * b;
        p = s * r;
        d[i + 1] = g + p;
        g = c * r - b;
      }
      if (deflated) continue;
      d[l] -= p;
      e[l] = g;
      e[k] = 0.0;
    }
  }
}

// The three eigenvalues of the symmetric tridiagonal [[d0 e0 0] [e0 d1 e1]
// [0 e1 d2]], left in d, in closed form (the trigonometric solution of the
// characteristic cubic): sigma1 alone takes three steps, and this is
// several times cheaper than the iteration.
void symmetric_3x3_eigenvalues(double* d, const double* e) {
  const double off = e[0] * e[0] + e[1] * e[1];
  const double mean = (d[0] + d[1] + d[2]) / 3.0;
  const double a = d[0] - mean, b = d[1] - mean, c = d[2] - mean;
  const double p = std::sqrt((a * a + b * b + c * c + 2.0 * off) / 6.0);
  if (!(p > 1e-300)) return;  // a multiple of the identity: d holds the eigenvalues
  // det((T - mean I) / p) / 2 = cos(3 phi)
  const double det = (a * (b * c - e[1] * e[1]) - e[0] * (e[0] * c)) / (p * p * p);
  const double phi = std::acos(std::clamp(det / 2.0, -1.0, 1.0)) / 3.0;
  constexpr double kThird = 2.0943951023931957;  // 2 pi / 3
  d[0] = mean + 2.0 * p * std::cos(phi);
  d[2] = mean + 2.0 * p * std::cos(phi + kThird);
  d[1] = 3.0 * mean - d[0] - d[2];
}

// Vectors of W floats (lanes past the patch size stay 0 throughout),
// processed kLanes at a time.
template <int W>
struct Lanczos {
  static constexpr int kBlocks = W / kLanes;
  struct alignas(32) Vector {
    float x[W];
  };

  int n = 0;
  Vector a[kMaxSize];       // the patch, row by row
  Vector u[kMaxSteps];      // left Lanczos vectors
  Vector v[kMaxSteps + 1];  // right Lanczos vectors
  double scale = 0.0;       // Frobenius norm of the patch

  [[gnu::always_inline]] static float dot(const Vector& x, const Vector& y) {
    FloatLanes sum{}, xb, yb;
    for (int b = 0; b < kBlocks; ++b) {
      load_lanes(xb, x.x + b * kLanes);
      load_lanes(yb, y.x + b * kLanes);
      sum += xb * yb;
    }
    return lane_sum(sum);
  }

  // y += s x
  [[gnu::always_inline]] static void add_scaled(Vector& y, float s, const Vector& x) {
    for (int j = 0; j < W; ++j) y.x[j] += s * x.x[j];
  }

  [[gnu::always_inline]] static void set_zero(Vector& x) {
    for (int j = 0; j < W; ++j) x.x[j] = 0.0f;
  }

  // y = A x: one dot product per patch row.
  [[gnu::always_inline]] void multiply(const Vector& x, Vector& y) const {
    set_zero(y);
    for (int i = 0; i < n; ++i) y.x[i] = dot(a[i], x);
  }

  // y = A^T x: the patch rows scaled by x and summed (vector multiply-adds).
  [[gnu::always_inline]] void multiply_transposed(const Vector& x, Vector& y) const {
    set_zero(y);
    for (int i = 0; i < n; ++i) add_scaled(y, x.x[i], a[i]);
  }

  // Classical Gram-Schmidt against the first `count` basis vectors, twice
  // ("twice is enough" for float vectors).
  [[gnu::always_inline]] static void orthogonalise(Vector& x, const Vector* basis, int count) {
    for (int pass = 0; pass < 2; ++pass)
      for (int k = 0; k < count; ++k) add_scaled(x, -dot(basis[k], x), basis[k]);
  }

  // Normalises x and returns its norm; when x has numerically vanished (the
  // Krylov space is invariant), replaces it with the unit vector least
  // represented in the basis, orthogonalised, and returns 0.
  [[gnu::always_inline]] double normalise(Vector& x, const Vector* basis, int count) const {
    const double norm = std::sqrt(static_cast<double>(dot(x, x)));
    if (norm > 1e-6 * scale) {
      const float inverse = static_cast<float>(1.0 / norm);
      for (int j = 0; j < W; ++j) x.x[j] *= inverse;
      return norm;
    }
    int best = 0;
    float best_residual = -1.0f;
    for (int j = 0; j < n; ++j) {
      float residual = 1.0f;
      for (int k = 0; k < count; ++k) residual -= basis[k].x[j] * basis[k].x[j];
      if (residual > best_residual) {
        best_residual = residual;
        best = j;
      }
    }
    set_zero(x);
    x.x[best] = 1.0f;
    orthogonalise(x, basis, count);
    const float inverse = static_cast<float>(1.0 / std::sqrt(static_cast<double>(dot(x, x))));
    for (int j = 0; j < W; ++j) x.x[j] *= inverse;
    return 0.0;
  }

  [[gnu::always_inline]] int run(const PatchView& patch, int count, double* out) {
    n = patch.size();
    std::fill(out, out + count, 0.0);
    FloatLanes squares{};
    Vector& column_sums = v[0];  // the start vector
    set_zero(column_sums);
    for (int i = 0; i < n; ++i) {
      const float* row = patch.row(i);
      for (int b = 0; b < kBlocks; ++b) {
        FloatLanes lanes;
        load_lanes(lanes, row + b * kLanes);
        keep_below(lanes, b * kLanes, n);
        store_lanes(a[i].x + b * kLanes, lanes);
        squares += lanes * lanes;
      }
      add_scaled(column_sums, 1.0f, a[i]);
    }
    const double frobenius = lane_sum(squares);
    if (!(frobenius > 0.0)) return 0;  // a zero patch
    scale = std::sqrt(frobenius);

    // Golub-Kahan bidiagonalisation A V = U B, B upper bidiagonal with
    // diagonal alpha and super-diagonal beta, started from the column sums.
    double alpha[kMaxSteps] = {}, beta[kMaxSteps] = {};
    normalise(v[0], v, 0);
    const int steps = std::min(n, kStepsPerValue * count);
    for (int m = 0; m < steps; ++m) {
      multiply(v[m], u[m]);  // u = A v
      orthogonalise(u[m], u, m);
      alpha[m] = normalise(u[m], u, m);
      if (m + 1 == steps) break;  // the last beta couples to a step not taken
      multiply_transposed(u[m], v[m + 1]);  // v' = A^T u
      orthogonalise(v[m + 1], v, m + 1);
      beta[m] = normalise(v[m + 1], v, m + 1);
    }

    // Singular values of B: square roots of the eigenvalues of the
    // tridiagonal B^T B (diagonal alpha_i^2 + beta_(i-1)^2, off-diagonal
    // alpha_i beta_i), in double.
    double diagonal[kMaxSteps], off_diagonal[kMaxSteps];
    for (int i = 0; i < steps; ++i) {
      diagonal[i] = alpha[i] * alpha[i] + (i > 0 ? beta[i - 1] * beta[i - 1] : 0.0);
      off_diagonal[i] = i + 1 < steps ? alpha[i] * beta[i] : 0.0;
    }
    if (steps == 3) symmetric_3x3_eigenvalues(diagonal, off_diagonal);
    else tridiagonal_eigenvalues(diagonal, off_diagonal, steps);
    const int found = std::min(count, steps);
    for (int k = 0; k < found; ++k) {  // selection of the largest few (m <= 9)
      int largest = k;
      for (int i = k + 1; i < steps; ++i)
        if (diagonal[i] > diagonal[largest]) largest = i;
      std::swap(diagonal[k], diagonal[largest]);
      out[k] = std::sqrt(std::max(diagonal[k], 0.0));
    }
    return steps;
  }
};

}  // namespace

FACADESLAM_KERNEL
int top_singular_values(const PatchView& patch, int count, double* out) {
  CV_Assert(count >= 1 && count <= 3);
  switch (lane_width(patch.size())) {
    case 8: {
      Lanczos<8> lanczos;  // default-initialised: run() writes what it reads
      return lanczos.run(patch, count, out);
    }
    case 16: {
      Lanczos<16> lanczos;  // default-initialised: run() writes what it reads
      return lanczos.run(patch, count, out);
    }
    case 24: {
      Lanczos<24> lanczos;  // default-initialised: run() writes what it reads
      return lanczos.run(patch, count, out);
    }
    default: break;
  }
  CV_Error(cv::Error::StsOutOfRange, "patch radius exceeds the kernels' 10 pixels");
}

void singular_values_module(const ModuleContext& context, std::uint64_t bits, float* values) {
  for (int c = 0; c < 3; ++c) {
    const std::uint64_t channel = (bits >> (3 * c)) & 0x7;
    if (!channel) continue;
    const int count = channel & 4 ? 3 : channel & 2 ? 2 : 1;
    double sigma[3];
    top_singular_values(context.patch(colour_plane(c)), count, sigma);
    for (int k = 0; k < count; ++k)
      if (bit_set(channel, k)) values[3 * c + k] = static_cast<float>(sigma[k]);
  }
}

}  // namespace facadeslam::semantics
