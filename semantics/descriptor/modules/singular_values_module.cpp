#include "semantics/descriptor/modules/singular_values_module.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

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
  // Off-diagonals below 1e-13 |T| are negligible: the eigenvalues are the
  // squared singular values, wanted to ~1e-13 sigma1^2, i.e. each singular
  // value to ~3e-7 sigma1 at worst. A tighter bound (1e-15) is at the level
  // of double rounding and made the iteration run to its cap.
  double norm = 0.0;
  for (int i = 0; i < m; ++i) norm = std::max(norm, std::abs(d[i]) + 2.0 * std::abs(e[i]));
  const double negligible = 1e-13 * norm;
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

// The `count` largest eigenvalues of the m x m symmetric positive
// semi-definite tridiagonal with diagonal d and off-diagonal e[0..m-2],
// descending, by Laguerre's iteration on the characteristic polynomial with
// the roots already found divided out (Maehly). From above every root,
// Laguerre's step on a real-rooted polynomial goes monotonically down to the
// largest one, in a few cubically convergent steps: the Gershgorin bound
// starts the first root, and trace - (roots found) bounds the next one, as
// no eigenvalue is negative. Returns false when that bound does not separate
// the next root from the last (near-multiple roots) or the iteration does
// not settle: the caller then solves the whole matrix.
bool top_tridiagonal_eigenvalues(const double* d, const double* e, int m, int count, double* out) {
  double upper = 0.0, trace = 0.0;
  for (int i = 0; i < m; ++i) {
    const double left = i > 0 ? std::abs(e[i - 1]) : 0.0, right = i + 1 < m ? std::abs(e[i]) : 0.0;
    upper = std::max(upper, d[i] + left + right);
    trace += d[i];
  }
  if (!(upper > 0.0)) return false;
  const double tolerance = 1e-14 * upper;
  double found_sum = 0.0;
  for (int k = 0; k < count; ++k) {
    double x = k == 0 ? upper : std::min(upper, trace - found_sum) + tolerance;
    if (k > 0 && !(x < out[k - 1] - 1e-6 * upper)) return false;
    const int degree = m - k;
    bool settled = false;
    for (int iteration = 0; iteration < 40 && !settled; ++iteration) {
      // p, p', p'' of det(T - x I) by the three-term recurrence, scaled by
      // the largest entry so that nothing overflows.
      double p0 = 1.0, p1 = d[0] - x, dp0 = 0.0, dp1 = -1.0, ddp0 = 0.0, ddp1 = 0.0;
      for (int i = 1; i < m; ++i) {
        const double a = d[i] - x, b = e[i - 1] * e[i - 1];
        const double p2 = a * p1 - b * p0;
        const double dp2 = -p1 + a * dp1 - b * dp0;
        const double ddp2 = -2.0 * dp1 + a * ddp1 - b * ddp0;
        p0 = p1, p1 = p2, dp0 = dp1, dp1 = dp2, ddp0 = ddp1, ddp1 = ddp2;
        const double scale = std::max({std::abs(p1), std::abs(dp1), std::abs(ddp1)});
        if (scale > 1e100) {
          const double inverse = 1.0 / scale;
          p0 *= inverse, p1 *= inverse, dp0 *= inverse, dp1 *= inverse, ddp0 *= inverse, ddp1 *= inverse;
        }
      }
      if (p1 == 0.0) {  // x is a root
        settled = true;
        break;
      }
      double g = dp1 / p1, h = g * g - ddp1 / p1;
      for (int j = 0; j < k; ++j) {  // divide out the roots found
        const double inverse = 1.0 / (x - out[j]);
        g -= inverse;
        h -= inverse * inverse;
      }
      const double n = degree;
      const double root = std::sqrt(std::max(0.0, (n - 1.0) * (n * h - g * g)));
      const double denominator = g > 0.0 ? g + root : g - root;
      if (!(std::abs(denominator) > 0.0)) return false;
      const double step = n / denominator;
      x -= step;
      settled = std::abs(step) <= tolerance;
    }
    if (!settled || !std::isfinite(x)) return false;
    out[k] = x;
    found_sum += x;
  }
  return true;
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

// Symmetric Lanczos on the Gram matrix G = A^T A of the patch A (n x n,
// rows of W floats with zero lanes past n), applied as A^T (A v) without
// forming G. k Lanczos steps on G from a start vector v span the same
// Krylov space as k Golub-Kahan steps on A from v, so the Ritz values are
// the same; a step costs one product with A (row dot products, reduced
// eight rows at a time) and one with A^T (broadcast-adds). The run is split
// into start / step / finish so that several channels can be stepped in
// lockstep: their steps are independent, and interleaving them keeps more
// work in flight than one channel's chain of dependent steps.
template <int W>
struct GramLanczos {
  static constexpr int kBlocks = W / kLanes;
  static constexpr int kDoubleBlocks = W / 4;
  struct alignas(32) Row {
    float x[W];
  };
  struct alignas(32) Vector {
    double x[W];
  };

  int n = 0;
  // Rows in groups of 8 for the dot products; rows past n stay zero.
  static constexpr int kRowGroups = kBlocks;  // n <= W
  Row a[kRowGroups * kLanes];  // the patch, row by row
  Vector v[kMaxSteps + 1];  // Lanczos vectors
  double scale = 0.0;       // squared Frobenius norm = trace(G)

  [[gnu::always_inline]] static double dot(const Vector& x, const Vector& y) {
    DoubleLanes sum{};
    for (int b = 0; b < kDoubleBlocks; ++b) {
      DoubleLanes xb, yb;
      std::memcpy(&xb, x.x + 4 * b, sizeof xb);
      std::memcpy(&yb, y.x + 4 * b, sizeof yb);
      sum += xb * yb;
    }
    return (sum[0] + sum[2]) + (sum[1] + sum[3]);
  }

  // y += s x
  [[gnu::always_inline]] static void add_scaled(Vector& y, double s, const Vector& x) {
    for (int j = 0; j < W; ++j) y.x[j] += s * x.x[j];
  }

  [[gnu::always_inline]] static void scale_by(Vector& x, double s) {
    for (int j = 0; j < W; ++j) x.x[j] *= s;
  }

  // Sums of 8 vectors' lanes, as the 8 lanes of one vector: a transpose
  // folded into the adds (3 levels of pairwise shuffles). Vectors are
  // passed by reference: by value their ABI would depend on the target.
  [[gnu::always_inline]] static void lane_sums(const FloatLanes* x, FloatLanes& out) {
    FloatLanes pairs[4];  // pairs[k] = lane-pair sums of x[2k] and x[2k+1], interleaved
    for (int k = 0; k < 4; ++k)
      pairs[k] = __builtin_shufflevector(x[2 * k], x[2 * k + 1], 0, 8, 2, 10, 4, 12, 6, 14) +
                 __builtin_shufflevector(x[2 * k], x[2 * k + 1], 1, 9, 3, 11, 5, 13, 7, 15);
    // quads[k] = [x(4k) x(4k+1) x(4k+2) x(4k+3)] sums of the low and high lane halves
    FloatLanes quads[2];
    for (int k = 0; k < 2; ++k)
      quads[k] = __builtin_shufflevector(pairs[2 * k], pairs[2 * k + 1], 0, 1, 8, 9, 4, 5, 12, 13) +
                 __builtin_shufflevector(pairs[2 * k], pairs[2 * k + 1], 2, 3, 10, 11, 6, 7, 14, 15);
    out = __builtin_shufflevector(quads[0], quads[1], 0, 1, 2, 3, 8, 9, 10, 11) +
          __builtin_shufflevector(quads[0], quads[1], 4, 5, 6, 7, 12, 13, 14, 15);
  }

  // y = G x = A^T (A x) without forming G: the row dot products a_i . x
  // (lane products reduced eight rows at a time), then the rows scaled by
  // them and summed. Float products, double result.
  [[gnu::always_inline]] void multiply(const Vector& x, Vector& y) const {
    FloatLanes xf[kBlocks];
    for (int b = 0; b < kBlocks; ++b)
      for (int k = 0; k < kLanes; ++k) xf[b][k] = static_cast<float>(x.x[b * kLanes + k]);
    alignas(32) float ax[kRowGroups * kLanes];
    for (int group = 0; group < kRowGroups; ++group) {
      FloatLanes products[kLanes];
      for (int t = 0; t < kLanes; ++t) {
        const Row& row = a[group * kLanes + t];  // rows past n are zero
        FloatLanes p = {};
        for (int b = 0; b < kBlocks; ++b) {
          FloatLanes lanes;
          load_lanes(lanes, row.x + b * kLanes);
          p += lanes * xf[b];
        }
        products[t] = p;
      }
      FloatLanes sums;
      lane_sums(products, sums);
      store_lanes(ax + group * kLanes, sums);
    }
    FloatLanes even[kBlocks] = {}, odd[kBlocks] = {};
    int i = 0;
    for (; i + 1 < n; i += 2)
      for (int b = 0; b < kBlocks; ++b) {
        FloatLanes row, next;
        load_lanes(row, a[i].x + b * kLanes);
        load_lanes(next, a[i + 1].x + b * kLanes);
        even[b] += ax[i] * row;
        odd[b] += ax[i + 1] * next;
      }
    if (i < n)
      for (int b = 0; b < kBlocks; ++b) {
        FloatLanes row;
        load_lanes(row, a[i].x + b * kLanes);
        even[b] += ax[i] * row;
      }
    for (int b = 0; b < kBlocks; ++b) {
      const FloatLanes sum = even[b] + odd[b];
      for (int k = 0; k < kLanes; ++k) y.x[b * kLanes + k] = sum[k];
    }
  }

  // Normalises x and returns its norm; when x has numerically vanished (the
  // Krylov space is invariant), replaces it with the unit vector least
  // represented in the basis, orthogonalised, and returns 0.
  [[gnu::always_inline]] double normalise(Vector& x, const Vector* basis, int count) const {
    const double norm = std::sqrt(dot(x, x));
    if (norm > 1e-9 * scale) {
      scale_by(x, 1.0 / norm);
      return norm;
    }
    int best = 0;
    double best_residual = -1.0;
    for (int j = 0; j < n; ++j) {
      double residual = 1.0;
      for (int k = 0; k < count; ++k) residual -= basis[k].x[j] * basis[k].x[j];
      if (residual > best_residual) {
        best_residual = residual;
        best = j;
      }
    }
    x = Vector{};
    x.x[best] = 1.0;
    orthogonalise(x, basis, count);
    scale_by(x, 1.0 / std::sqrt(dot(x, x)));
    return 0.0;
  }

  // Classical Gram-Schmidt against the first `count` basis vectors: once is
  // enough in double for these few steps (the Ritz values agree with a full
  // SVD to 1e-6 sigma1 either way).
  [[gnu::always_inline]] static void orthogonalise(Vector& x, const Vector* basis, int count) {
    double coefficients[kMaxSteps + 1];
    for (int k = 0; k < count; ++k) coefficients[k] = dot(basis[k], x);
    for (int k = 0; k < count; ++k) add_scaled(x, -coefficients[k], basis[k]);
  }

  int count = 0, steps = 0;
  double alpha[kMaxSteps] = {}, beta[kMaxSteps] = {};

  // Loads the patch and the start vector; returns false for a zero patch.
  [[gnu::always_inline]] bool start(const PatchView& patch, int wanted) {
    const int size = patch.size();  // a local: the stores into a[] could alias a member
    n = size;
    count = wanted;
    // One accumulator per lane block: a single one would chain all 3 x 21
    // multiply-adds one after the other.
    FloatLanes squares[kBlocks] = {};
    FloatLanes column_sums[kBlocks] = {};  // the start vector
    for (int i = 0; i < size; ++i) {
      const float* row = patch.row(i);
      for (int b = 0; b < kBlocks; ++b) {
        FloatLanes lanes;
        load_lanes(lanes, row + b * kLanes);
        if (b == kBlocks - 1) keep_below(lanes, b * kLanes, size);  // earlier blocks are inside the patch
        store_lanes(a[i].x + b * kLanes, lanes);
        squares[b] += lanes * lanes;
        column_sums[b] += lanes;
      }
    }
    for (int i = size; i < kRowGroups * kLanes; ++i) a[i] = Row{};
    for (int b = 1; b < kBlocks; ++b) squares[0] += squares[b];
    scale = lane_sum(squares[0]);
    steps = scale > 0.0 ? std::min(n, kStepsPerValue * count) : 0;
    if (steps == 0) return false;  // a zero patch
    v[0] = Vector{};
    for (int b = 0; b < kBlocks; ++b)
      for (int k = 0; k < kLanes; ++k) v[0].x[b * kLanes + k] = column_sums[b][k];
    normalise(v[0], v, 0);
    return true;
  }

  // Step m of T = V^T G V, tridiagonal with diagonal alpha and off-diagonal
  // beta; its eigenvalues approximate those of G, the squared singular values.
  [[gnu::always_inline]] void step(int m) {
    Vector& w = v[m + 1];
    multiply(v[m], w);
    alpha[m] = dot(v[m], w);
    if (m + 1 == steps) return;  // the last beta couples to a step not taken
    orthogonalise(w, v, m + 1);
    beta[m] = normalise(w, v, m + 1);
  }

  // The `count` largest singular values, descending, into out.
  [[gnu::always_inline]] void finish(double* out) {
    std::fill(out, out + count, 0.0);
    if (steps == 0) return;
    double off_diagonal[kMaxSteps];
    for (int i = 0; i < steps; ++i) off_diagonal[i] = i + 1 < steps ? beta[i] : 0.0;
    const int found = std::min(count, steps);
    double top[3];
    if (steps > 3 && top_tridiagonal_eigenvalues(alpha, off_diagonal, steps, found, top)) {
      for (int k = 0; k < found; ++k) out[k] = std::sqrt(std::max(top[k], 0.0));
      return;
    }
    if (steps == 3) symmetric_3x3_eigenvalues(alpha, off_diagonal);
    else tridiagonal_eigenvalues(alpha, off_diagonal, steps);
    for (int k = 0; k < found; ++k) {  // selection of the largest few (m <= 9)
      int largest = k;
      for (int i = k + 1; i < steps; ++i)
        if (alpha[i] > alpha[largest]) largest = i;
      std::swap(alpha[k], alpha[largest]);
      out[k] = std::sqrt(std::max(alpha[k], 0.0));
    }
  }
};

}  // namespace

// Up to three patches stepped in lockstep (see GramLanczos).
template <int W>
[[gnu::always_inline]] inline void run_lockstep(const PatchView* patches, const int* counts, int channels,
                                                double (*out)[3], int* steps) {
  GramLanczos<W> lanczos[3];  // default-initialised: start() writes what the rest reads
  int most = 0;
  for (int c = 0; c < channels; ++c) {
    lanczos[c].start(patches[c], counts[c]);
    most = std::max(most, lanczos[c].steps);
  }
  for (int m = 0; m < most; ++m)
    for (int c = 0; c < channels; ++c)
      if (m < lanczos[c].steps) lanczos[c].step(m);
  for (int c = 0; c < channels; ++c) {
    lanczos[c].finish(out[c]);
    if (steps) steps[c] = lanczos[c].steps;
  }
}

FACADESLAM_KERNEL
void top_singular_values(const PatchView* patches, const int* counts, int channels, double (*out)[3], int* steps) {
  CV_Assert(channels >= 1 && channels <= 3);
  for (int c = 0; c < channels; ++c)
    CV_Assert(counts[c] >= 1 && counts[c] <= 3 && patches[c].radius == patches[0].radius);
  switch (lane_width(patches[0].size())) {
    case 8: return run_lockstep<8>(patches, counts, channels, out, steps);
    case 16: return run_lockstep<16>(patches, counts, channels, out, steps);
    case 24: return run_lockstep<24>(patches, counts, channels, out, steps);
    default: break;
  }
  CV_Error(cv::Error::StsOutOfRange, "patch radius exceeds the kernels' 10 pixels");
}

int top_singular_values(const PatchView& patch, int count, double* out) {
  double values[1][3];
  int steps = 0;
  top_singular_values(&patch, &count, 1, values, &steps);
  std::copy(values[0], values[0] + count, out);
  return steps;
}

void singular_values_module(const ModuleContext& context, std::uint64_t bits, float* values) {
  PatchView patches[3];
  int counts[3], channel_of[3];
  int channels = 0;
  for (int c = 0; c < 3; ++c) {
    const std::uint64_t wanted = (bits >> (3 * c)) & 0x7;
    if (!wanted) continue;
    patches[channels] = context.patch(colour_plane(c));
    counts[channels] = wanted & 4 ? 3 : wanted & 2 ? 2 : 1;
    channel_of[channels++] = c;
  }
  if (channels == 0) return;
  double sigma[3][3];
  top_singular_values(patches, counts, channels, sigma, nullptr);
  for (int i = 0; i < channels; ++i) {
    const int c = channel_of[i];
    for (int k = 0; k < counts[i]; ++k)
      if (bit_set(bits >> (3 * c), k)) values[3 * c + k] = static_cast<float>(sigma[i][k]);
  }
}

}  // namespace facadeslam::semantics
