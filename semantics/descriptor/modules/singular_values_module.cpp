#include "semantics/descriptor/modules/singular_values_module.hpp"

#include <algorithm>
#include <cmath>

#include "semantics/descriptor/descriptor_params.hpp"
#include "semantics/descriptor/kernel_support.hpp"

namespace facadeslam::semantics {
namespace {

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

// The three eigenvalues of the symmetric tridiagonal [[d0 e0 0] [e0 d1 e1]
// [0 e1 d2]], left in d, in closed form (the trigonometric solution of the
// characteristic cubic): the fallback for sigma1 alone (three steps).
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

// The `count` largest singular values, descending, from the tridiagonal of
// `steps` steps (diagonal d, off-diagonal e[0..steps-2]; both are
// overwritten) by solving it whole: square roots of its largest
// eigenvalues. For the lanes the Laguerre iteration leaves unsettled.
void largest_singular_values(double* d, double* e, int steps, int count, double* out) {
  const int found = std::min(count, steps);
  if (steps == 3)
    symmetric_3x3_eigenvalues(d, e);
  else
    tridiagonal_eigenvalues(d, e, steps);
  for (int k = 0; k < found; ++k) {  // selection of the largest few (m <= 9)
    int largest = k;
    for (int i = k + 1; i < steps; ++i)
      if (d[i] > d[largest]) largest = i;
    std::swap(d[k], d[largest]);
    out[k] = std::sqrt(std::max(d[k], 0.0));
  }
}

// Four doubles' comparison masks (all bits set where true).
using DoubleMask = long long __attribute__((vector_size(4 * sizeof(long long))));

[[gnu::always_inline]] inline void abs_lanes(const DoubleLanes& x, DoubleLanes& out) {
  const DoubleLanes zero = {};
  out = x < zero ? -x : x;
}

[[gnu::always_inline]] inline bool any_lane(const DoubleMask& m) { return (m[0] | m[1] | m[2] | m[3]) != 0; }

// The `count` largest eigenvalues, descending, of four m x m symmetric
// positive semi-definite tridiagonals at once, one per lane (diagonal d,
// off-diagonal e[0..m-2] with e[m-1] = 0), by Laguerre's iteration on the
// characteristic polynomial with the roots already found divided out
// (Maehly). From above every root, Laguerre's step on a real-rooted
// polynomial goes monotonically down to the largest one, in a few cubically
// convergent steps: the Gershgorin bound starts the first root, and
// trace - (roots found) bounds the next one, as no eigenvalue is negative.
// Each lane stops when its step is below tolerance. `settled` marks the
// lanes where every root settled; a lane is left unsettled when that bound
// does not separate its next root from the last (near-multiple roots) or
// its iteration does not settle, for largest_singular_values to solve whole.
[[gnu::always_inline]] inline void top_tridiagonal_eigenvalues_4(const DoubleLanes* d, const DoubleLanes* e, int m,
                                                                 int count, DoubleLanes* out, DoubleMask& settled) {
  const DoubleLanes zero = {}, one = zero + 1.0;
  DoubleLanes upper = zero, trace = zero;
  for (int i = 0; i < m; ++i) {
    DoubleLanes left = zero, right = zero;
    if (i > 0) abs_lanes(e[i - 1], left);
    if (i + 1 < m) abs_lanes(e[i], right);
    const DoubleLanes bound = d[i] + left + right;
    upper = bound > upper ? bound : upper;
    trace += d[i];
  }
  DoubleMask good = upper > zero;
  const DoubleLanes tolerance = 1e-14 * upper;
  DoubleLanes found_sum = zero;
  for (int k = 0; k < count; ++k) {
    DoubleLanes x = upper;
    if (k > 0) {
      const DoubleLanes rest = trace - found_sum;
      x = (rest < upper ? rest : upper) + tolerance;
      good &= x < out[k - 1] - 1e-6 * upper;
    }
    const double n = m - k;
    DoubleMask done = ~good;
    for (int iteration = 0; iteration < 40 && any_lane(~done); ++iteration) {
      // p, p', p'' of det(T - x I) by the three-term recurrence, scaled by
      // the largest entry so that nothing overflows.
      DoubleLanes p0 = one, p1 = d[0] - x, dp0 = zero, dp1 = -one, ddp0 = zero, ddp1 = zero;
      for (int i = 1; i < m; ++i) {
        const DoubleLanes a = d[i] - x, b = e[i - 1] * e[i - 1];
        const DoubleLanes p2 = a * p1 - b * p0;
        const DoubleLanes dp2 = -p1 + a * dp1 - b * dp0;
        const DoubleLanes ddp2 = -2.0 * dp1 + a * ddp1 - b * ddp0;
        p0 = p1, p1 = p2, dp0 = dp1, dp1 = dp2, ddp0 = ddp1, ddp1 = ddp2;
        DoubleLanes a1, a2, a3;
        abs_lanes(p1, a1);
        abs_lanes(dp1, a2);
        abs_lanes(ddp1, a3);
        DoubleLanes largest = a1 > a2 ? a1 : a2;
        largest = a3 > largest ? a3 : largest;
        const DoubleMask big = largest > 1e100;
        if (any_lane(big)) {
          const DoubleLanes inverse = big ? one / largest : one;
          p0 *= inverse, p1 *= inverse, dp0 *= inverse, dp1 *= inverse, ddp0 *= inverse, ddp1 *= inverse;
        }
      }
      const DoubleMask root = p1 == zero;  // x is a root
      done |= root;
      const DoubleLanes safe_p = root ? one : p1;
      DoubleLanes g = dp1 / safe_p, h = g * g - ddp1 / safe_p;
      for (int j = 0; j < k; ++j) {  // divide out the roots found
        const DoubleLanes inverse = one / (x - out[j]);
        g -= inverse;
        h -= inverse * inverse;
      }
      DoubleLanes radicand = (n - 1.0) * (n * h - g * g);
      radicand = radicand > zero ? radicand : zero;
      DoubleLanes root_term = zero;
      for (int t = 0; t < 4; ++t) root_term[t] = std::sqrt(radicand[t]);
      const DoubleLanes denominator = g > zero ? g + root_term : g - root_term;
      DoubleLanes size;
      abs_lanes(denominator, size);
      const DoubleMask moving = ~done;
      good &= ~(moving & ~(size > zero));
      const DoubleMask update = moving & good;
      const DoubleLanes step = n / (update ? denominator : one);
      x = update ? x - step : x;
      DoubleLanes step_size;
      abs_lanes(step, step_size);
      done |= ~good | (update & (step_size <= tolerance));
    }
    const DoubleMask finite = (x == x) & (x < 1e300) & (x > -1e300);
    good &= done & finite;
    out[k] = x;
    found_sum += x;
  }
  settled = good;
}

// Square roots of the lanes (a handful per step: not worth a vector
// intrinsic, and std::sqrt keeps the baseline build portable). Vectors are
// passed by reference: by value their ABI would depend on the target.
[[gnu::always_inline]] inline void sqrt_lanes(const FloatLanes& x, FloatLanes& out) {
  for (int l = 0; l < kLanes; ++l) out[l] = std::sqrt(x[l]);
}

// Golub-Kahan-Lanczos bidiagonalisation A V = U B of up to kLanes patches at
// once, one patch per vector lane: every operation is lane by lane, so no
// lane's result depends on the others (no horizontal reductions, and a
// lane's arithmetic is the same whatever the other lanes hold). k steps
// from the start vector v_0 give the upper bidiagonal B (diagonal alpha,
// superdiagonal beta) with B^T B = the tridiagonal of k Lanczos steps on
// G = A^T A from v_0, so the Ritz values are those of a Lanczos iteration on
// G, at the same cost (one product with A and one with A^T a step). Working
// on A rather than on G keeps float rounding at ~1e-7 sigma1 on every
// singular value, where products with G would leave ~1e-7 sigma1^2 on the
// squares, i.e. ~3e-4 sigma1 on a small one. Each new vector is the
// three-term recurrence (which removes the large components) followed by
// one Gram-Schmidt pass against all earlier vectors of its side (which
// removes what rounding left); a vanished vector is replaced by a fresh unit
// vector and its coefficient set to 0 (the bidiagonal splits).
template <int N>
struct LaneBidiagonalisation {
  static constexpr int kBlocks = lane_width(N) / kLanes;

  FloatLanes a[N][N];          // a[i][j] = row i, column j of each lane's patch
  FloatLanes v[kMaxSteps][N];  // right vectors (columns of V)
  FloatLanes u[kMaxSteps][N];  // left vectors (columns of U)
  FloatLanes norm;             // Frobenius norm of the patch, per lane
  // Below this a vector has vanished: coefficients are at most
  // sigma1 <= |A|_F, and what rounding leaves of a vanished vector is ~1e-7
  // of that.
  FloatLanes floor;
  FloatLanes alpha[kMaxSteps], beta[kMaxSteps];
  IntLanes live;  // lanes holding a patch with a non-zero entry (all bits set)
  int steps = 0;

  // out = sum_j x[j] y[j], lane by lane
  [[gnu::always_inline]] static void dot(const FloatLanes* x, const FloatLanes* y, FloatLanes& out) {
    FloatLanes even = x[0] * y[0], odd = {};  // two chains: N is odd
    for (int j = 1; j < N; j += 2) {
      even += x[j] * y[j];
      odd += x[j + 1] * y[j + 1];
    }
    out = even + odd;
  }

  // The patches, transposed to one lane each; lanes past `lanes` are zero.
  [[gnu::always_inline]] void load(const PatchView* patches, int lanes) {
    for (int i = 0; i < N; ++i)
      for (int b = 0; b < kBlocks; ++b) {
        FloatLanes rows[kLanes];
        for (int l = 0; l < kLanes; ++l) {
          if (l < lanes)
            load_lanes(rows[l], patches[l].row(i) + b * kLanes);  // PatchView::kReadSlack
          else
            rows[l] = FloatLanes{};
        }
        transpose_lanes(rows);
        for (int k = 0; k < kLanes && b * kLanes + k < N; ++k) a[i][b * kLanes + k] = rows[k];
      }
  }

  // x -= (basis_k . x) basis_k for k < count, one modified Gram-Schmidt pass.
  [[gnu::always_inline]] static void orthogonalise(FloatLanes* x, const FloatLanes (*basis)[N], int count) {
    for (int k = 0; k < count; ++k) {
      FloatLanes c;
      dot(basis[k], x, c);
      for (int j = 0; j < N; ++j) x[j] -= c * basis[k][j];
    }
  }

  // Lane l of basis[m]: the unit vector least represented in basis[0..m),
  // orthogonalised (twice) and normalised. Only where a lane's Krylov space
  // became invariant (the identity, a rank-deficient patch), which is rare
  // on real patches, so it is plain scalar code.
  static void restart_lane(FloatLanes (*basis)[N], int l, int m) {
    int best = 0;
    float best_residual = -1.0f;
    for (int j = 0; j < N; ++j) {
      float residual = 1.0f;
      for (int k = 0; k < m; ++k) residual -= basis[k][j][l] * basis[k][j][l];
      if (residual > best_residual) best_residual = residual, best = j;
    }
    float x[N] = {};
    x[best] = 1.0f;
    for (int pass = 0; pass < 2; ++pass)
      for (int k = 0; k < m; ++k) {
        float c = 0.0f;
        for (int j = 0; j < N; ++j) c += basis[k][j][l] * x[j];
        for (int j = 0; j < N; ++j) x[j] -= c * basis[k][j][l];
      }
    float length = 0.0f;
    for (int j = 0; j < N; ++j) length += x[j] * x[j];
    length = std::sqrt(length);
    for (int j = 0; j < N; ++j) basis[m][j][l] = x[j] / length;
  }

  // Normalises basis[m]; `coefficient` gets its norm. A live lane whose norm
  // is at most `floor` has vanished: coefficient 0 and a fresh unit vector.
  [[gnu::always_inline]] void normalise(FloatLanes (*basis)[N], int m, const FloatLanes& floor,
                                        FloatLanes& coefficient) const {
    FloatLanes* x = basis[m];
    FloatLanes squares;
    dot(x, x, squares);
    sqrt_lanes(squares, coefficient);
    const IntLanes kept = coefficient > floor;
    const FloatLanes zero = {};
    const FloatLanes inverse = kept ? 1.0f / coefficient : zero;
    for (int j = 0; j < N; ++j) x[j] *= inverse;
    coefficient = kept ? coefficient : zero;
    const IntLanes vanished = live & ~kept;
    for (int l = 0; l < kLanes; ++l)
      if (vanished[l]) restart_lane(basis, l, m);
  }

  // The products with A and A^T take eight rows (columns) at a time: one
  // load of x serves eight multiply-adds into eight independent
  // accumulators (enough to keep both FMA units busy), in named variables
  // because GCC keeps an accumulator array in memory. The rows left over
  // go one at a time.

  // y[i] = sum_j a[i][j] x[j]
  [[gnu::always_inline]] void times(const FloatLanes* x, FloatLanes* y) const {
    int i = 0;
    for (; i + 8 <= N; i += 8) {
      const FloatLanes(*r)[N] = a + i;
      FloatLanes s0 = {}, s1 = {}, s2 = {}, s3 = {}, s4 = {}, s5 = {}, s6 = {}, s7 = {};
      for (int j = 0; j < N; ++j) {
        const FloatLanes xj = x[j];
        s0 += r[0][j] * xj, s1 += r[1][j] * xj, s2 += r[2][j] * xj, s3 += r[3][j] * xj;
        s4 += r[4][j] * xj, s5 += r[5][j] * xj, s6 += r[6][j] * xj, s7 += r[7][j] * xj;
      }
      y[i] = s0, y[i + 1] = s1, y[i + 2] = s2, y[i + 3] = s3;
      y[i + 4] = s4, y[i + 5] = s5, y[i + 6] = s6, y[i + 7] = s7;
    }
    for (; i < N; ++i) dot(a[i], x, y[i]);
  }

  // y[j] = sum_i a[i][j] x[i]
  [[gnu::always_inline]] void transposed_times(const FloatLanes* x, FloatLanes* y) const {
    int j = 0;
    for (; j + 8 <= N; j += 8) {
      FloatLanes s0 = {}, s1 = {}, s2 = {}, s3 = {}, s4 = {}, s5 = {}, s6 = {}, s7 = {};
      for (int i = 0; i < N; ++i) {
        const FloatLanes xi = x[i];
        const FloatLanes* c = a[i] + j;
        s0 += c[0] * xi, s1 += c[1] * xi, s2 += c[2] * xi, s3 += c[3] * xi;
        s4 += c[4] * xi, s5 += c[5] * xi, s6 += c[6] * xi, s7 += c[7] * xi;
      }
      y[j] = s0, y[j + 1] = s1, y[j + 2] = s2, y[j + 3] = s3;
      y[j + 4] = s4, y[j + 5] = s5, y[j + 6] = s6, y[j + 7] = s7;
    }
    for (; j < N; ++j) {
      FloatLanes even = a[0][j] * x[0], odd = {};
      for (int i = 1; i < N; i += 2) {
        even += a[i][j] * x[i];
        odd += a[i + 1][j] * x[i + 1];
      }
      y[j] = even + odd;
    }
  }

  // u[m] = A v[m] - beta[m-1] u[m-1], orthogonalised against u[0..m).
  [[gnu::always_inline]] void left(int m) {
    FloatLanes* p = u[m];
    times(v[m], p);
    if (m > 0) {
      for (int i = 0; i < N; ++i) p[i] -= beta[m - 1] * u[m - 1][i];
      orthogonalise(p, u, m);
    }
    normalise(u, m, floor, alpha[m]);
  }

  // v[m+1] = A^T u[m] - alpha[m] v[m], orthogonalised against v[0..m].
  [[gnu::always_inline]] void right(int m) {
    FloatLanes* r = v[m + 1];
    transposed_times(u[m], r);
    for (int j = 0; j < N; ++j) r[j] -= alpha[m] * v[m][j];
    orthogonalise(r, v, m + 1);
    normalise(v, m + 1, floor, beta[m]);
  }

  // Start vector: the column sums, close to the leading right singular
  // vector of a non-negative patch (whose column sums have a norm of at
  // least |A|_F; they can only vanish on signed patches).
  [[gnu::always_inline]] void run(int count) {
    FloatLanes ones[N];
    for (int i = 0; i < N; ++i) ones[i] = FloatLanes{} + 1.0f;
    transposed_times(ones, v[0]);
    // |A|_F^2 in eight accumulators (one would chain all N^2 multiply-adds).
    const FloatLanes* entry = a[0];
    FloatLanes s0 = {}, s1 = {}, s2 = {}, s3 = {}, s4 = {}, s5 = {}, s6 = {}, s7 = {};
    int k = 0;
    for (; k + 8 <= N * N; k += 8) {
      s0 += entry[k] * entry[k], s1 += entry[k + 1] * entry[k + 1], s2 += entry[k + 2] * entry[k + 2];
      s3 += entry[k + 3] * entry[k + 3], s4 += entry[k + 4] * entry[k + 4], s5 += entry[k + 5] * entry[k + 5];
      s6 += entry[k + 6] * entry[k + 6], s7 += entry[k + 7] * entry[k + 7];
    }
    for (; k < N * N; ++k) s0 += entry[k] * entry[k];
    const FloatLanes squares = ((s0 + s1) + (s2 + s3)) + ((s4 + s5) + (s6 + s7));
    sqrt_lanes(squares, norm);
    floor = 1e-6f * norm;
    const FloatLanes zero = {};
    live = norm > zero;
    steps = std::min(N, kStepsPerValue * count);
    FloatLanes start_norm;
    normalise(v, 0, floor, start_norm);
    left(0);
    for (int m = 0; m + 1 < steps; ++m) {
      right(m);
      left(m + 1);
    }
  }

  // The `count` largest singular values of lanes 0..lanes-1, descending:
  // square roots of the largest eigenvalues of B^T B (tridiagonal: diagonal
  // alpha_i^2 + beta_(i-1)^2, off-diagonal alpha_i beta_i), formed in double
  // and solved four lanes at a time; a lane the lane solver leaves unsettled
  // goes through the scalar one.
  [[gnu::always_inline]] void finish(int lanes, int count, double (*out)[3]) const {
    const int found = std::min(count, steps);
    for (int group = 0; 4 * group < lanes; ++group) {
      DoubleLanes d[kMaxSteps], e[kMaxSteps];
      for (int i = 0; i < steps; ++i)
        for (int t = 0; t < 4; ++t) {
          const int l = 4 * group + t;
          const double diagonal = alpha[i][l], above = i > 0 ? static_cast<double>(beta[i - 1][l]) : 0.0;
          d[i][t] = diagonal * diagonal + above * above;
          e[i][t] = i + 1 < steps ? diagonal * static_cast<double>(beta[i][l]) : 0.0;
        }
      DoubleLanes top[3];
      DoubleMask settled;
      top_tridiagonal_eigenvalues_4(d, e, steps, found, top, settled);
      for (int t = 0; t < 4 && 4 * group + t < lanes; ++t) {
        const int l = 4 * group + t;
        std::fill(out[l], out[l] + count, 0.0);
        if (!live[l]) continue;
        if (settled[t]) {
          for (int k = 0; k < found; ++k) out[l][k] = std::sqrt(std::max(top[k][t], 0.0));
          continue;
        }
        double dl[kMaxSteps], el[kMaxSteps];
        for (int i = 0; i < steps; ++i) dl[i] = d[i][t], el[i] = e[i][t];
        largest_singular_values(dl, el, steps, count, out[l]);
      }
    }
  }
};

template <int N>
[[gnu::always_inline]] inline void run_lanes(const PatchView* patches, int lanes, int count, double (*out)[3],
                                             int* steps) {
  LaneBidiagonalisation<N> bidiagonal;  // default-initialised: load() and run() write what finish() reads
  bidiagonal.load(patches, lanes);
  bidiagonal.run(count);
  bidiagonal.finish(lanes, count, out);
  if (steps)
    for (int l = 0; l < lanes; ++l) steps[l] = bidiagonal.live[l] ? bidiagonal.steps : 0;
}

}  // namespace

FACADESLAM_KERNEL
void top_singular_values(const PatchView* patches, int lanes, int count, double (*out)[3], int* steps) {
  CV_Assert(lanes >= 1 && lanes <= kSingularValueLanes && count >= 1 && count <= 3);
  for (int l = 1; l < lanes; ++l) CV_Assert(patches[l].radius == patches[0].radius);
  switch (patches[0].size()) {
    case 3: return run_lanes<3>(patches, lanes, count, out, steps);
    case 5: return run_lanes<5>(patches, lanes, count, out, steps);
    case 7: return run_lanes<7>(patches, lanes, count, out, steps);
    case 9: return run_lanes<9>(patches, lanes, count, out, steps);
    case 11: return run_lanes<11>(patches, lanes, count, out, steps);
    case 13: return run_lanes<13>(patches, lanes, count, out, steps);
    case 15: return run_lanes<15>(patches, lanes, count, out, steps);
    case 17: return run_lanes<17>(patches, lanes, count, out, steps);
    case 19: return run_lanes<19>(patches, lanes, count, out, steps);
    case 21: return run_lanes<21>(patches, lanes, count, out, steps);
    default: break;
  }
  CV_Error(cv::Error::StsOutOfRange, "patch radius must be 1..10 for the singular values");
}

int top_singular_values(const PatchView& patch, int count, double* out) {
  double values[1][3];
  int steps = 0;
  top_singular_values(&patch, 1, count, values, &steps);
  std::copy(values[0], values[0] + count, out);
  return steps;
}

namespace {

// How many singular values of channel c the module bits want (the highest
// active one decides: the iteration finds them from the top).
int wanted_count(std::uint64_t bits, int c) {
  const std::uint64_t wanted = (bits >> (3 * c)) & 0x7;
  return wanted & 4 ? 3 : wanted & 2 ? 2 : wanted ? 1 : 0;
}

}  // namespace

void singular_values_of_patches(const PreparedImage& image, const std::vector<cv::Point>& centres, int radius,
                                std::uint64_t bits, float* values) {
  for (int c = 0; c < 3; ++c) {
    const int count = wanted_count(bits, c);
    if (count == 0) continue;
    for (std::size_t first = 0; first < centres.size(); first += kSingularValueLanes) {
      const int lanes = static_cast<int>(std::min<std::size_t>(kSingularValueLanes, centres.size() - first));
      PatchView patches[kSingularValueLanes];
      for (int l = 0; l < lanes; ++l) {
        const cv::Point& p = centres[first + static_cast<std::size_t>(l)];
        patches[l] = image.patch(colour_plane(c), p.x, p.y, radius);
      }
      double sigma[kSingularValueLanes][3];
      top_singular_values(patches, lanes, count, sigma);
      for (int l = 0; l < lanes; ++l) {
        float* row = values + (first + static_cast<std::size_t>(l)) * kSingularValueCount;
        for (int k = 0; k < count; ++k)
          if (bit_set(bits >> (3 * c), k)) row[3 * c + k] = static_cast<float>(sigma[l][k]);
      }
    }
  }
}

void singular_values_module(const ModuleContext& context, std::uint64_t bits, float* values) {
  if (context.singular_values) {  // computed in batches by the extractor
    for (int i = 0; i < kSingularValueCount; ++i)
      if (bit_set(bits, i)) values[i] = context.singular_values[i];
    return;
  }
  for (int c = 0; c < 3; ++c) {
    const int count = wanted_count(bits, c);
    if (count == 0) continue;
    double sigma[3];
    top_singular_values(context.patch(colour_plane(c)), count, sigma);
    for (int k = 0; k < count; ++k)
      if (bit_set(bits >> (3 * c), k)) values[3 * c + k] = static_cast<float>(sigma[k]);
  }
}

}  // namespace facadeslam::semantics
