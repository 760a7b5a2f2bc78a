#pragma once
// Levenberg-Marquardt with a Huber loss (iteratively reweighted) over a
// state that lives on a manifold, with a central-difference Jacobian. The
// two-view refinements (essential pose, homography) run it once per
// start-up on a few hundred residuals, so clarity wins over analytic
// derivatives; they differ only in their state, retraction and residuals.
#include <cmath>
#include <optional>

#include <Eigen/Cholesky>
#include <Eigen/Core>

namespace facadeslam::robust_lm {

inline double huber_cost(double r, double k) {
  const double a = std::abs(r);
  return a <= k ? r * r : 2.0 * k * a - k * k;
}

inline double huber_cost(const Eigen::VectorXd& r, double k) {
  double c = 0.0;
  for (Eigen::Index n = 0; n < r.size(); ++n) c += huber_cost(r(n), k);
  return c;
}

// residuals(state) -> std::optional<Eigen::VectorXd> (nullopt: the state is
// invalid, e.g. a singular homography); retract(state, delta) -> state moved
// by the N-vector delta in its tangent space. Returns the best state reached
// (the input when its residuals are invalid).
template <int N, class State, class Residuals, class Retract>
State minimise(State x, double huber_k, int max_iterations, const Residuals& residuals, const Retract& retract) {
  using VectorN = Eigen::Matrix<double, N, 1>;
  std::optional<Eigen::VectorXd> r = residuals(x);
  if (!r) return x;
  double current = huber_cost(*r, huber_k);
  double lambda = 1e-4;
  constexpr double h = 1e-7;
  for (int iteration = 0; iteration < max_iterations; ++iteration) {
    Eigen::MatrixXd J(r->size(), N);
    for (int p = 0; p < N; ++p) {
      const VectorN step = VectorN::Unit(p) * h;
      const std::optional<Eigen::VectorXd> plus = residuals(retract(x, step));
      const std::optional<Eigen::VectorXd> minus = residuals(retract(x, VectorN(-step)));
      if (!plus || !minus) return x;
      J.col(p) = (*plus - *minus) / (2.0 * h);
    }
    // Huber weights of the current residuals (IRLS).
    Eigen::VectorXd w(r->size());
    for (Eigen::Index n = 0; n < r->size(); ++n)
      w(n) = std::abs((*r)(n)) <= huber_k ? 1.0 : huber_k / std::abs((*r)(n));
    const Eigen::Matrix<double, N, N> A = J.transpose() * w.asDiagonal() * J;
    const VectorN g = J.transpose() * w.asDiagonal() * *r;

    bool improved = false;
    while (lambda < 1e8) {
      Eigen::Matrix<double, N, N> damped = A;
      damped.diagonal() += lambda * A.diagonal().cwiseMax(1e-12);
      const VectorN delta = damped.ldlt().solve(-g);
      if (!delta.allFinite()) break;
      State candidate = retract(x, delta);
      if (std::optional<Eigen::VectorXd> r_candidate = residuals(candidate)) {
        const double c = huber_cost(*r_candidate, huber_k);
        if (c < current) {
          const bool converged = delta.norm() < 1e-12 || (current - c) < 1e-12 * current;
          x = std::move(candidate);
          r = std::move(r_candidate);
          current = c;
          lambda = std::max(lambda * 0.1, 1e-10);
          improved = !converged;
          break;
        }
      }
      lambda *= 10.0;
    }
    if (!improved) break;
  }
  return x;
}

}  // namespace facadeslam::robust_lm
