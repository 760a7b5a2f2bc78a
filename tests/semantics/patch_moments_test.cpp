#include <gtest/gtest.h>

#include <cmath>

#include <opencv2/imgproc.hpp>

#include "semantics/descriptor/modules/affine_invariants_module.hpp"
#include "semantics/descriptor/modules/hu_module.hpp"
#include "semantics/descriptor/modules/patch_moments.hpp"
#include "tests/semantics/semantics_test_util.hpp"

namespace facadeslam::semantics {
namespace {

using test_util::patch_from;
using test_util::supersampled_patch;

PatchMoments moments_of(const cv::Mat& patch, int order = 5) {
  PatchMoments m;
  compute_patch_moments(view_of(patch), order, m);
  return m;
}

void expect_relative(double actual, double expected, double tolerance, const std::string& what) {
  EXPECT_NEAR(actual, expected, tolerance * std::max(std::abs(expected), 1e-12)) << what;
}

// An asymmetric blob: three Gaussians, so that odd moments do not vanish.
double blob(double x, double y) {
  const double s2 = 2 * 1.6 * 1.6;
  return std::exp(-((x + 2) * (x + 2) + (y + 1) * (y + 1)) / s2) +
         0.7 * std::exp(-((x - 2) * (x - 2) + (y - 1.5) * (y - 1.5)) / s2) +
         0.5 * std::exp(-((x - 0.5) * (x - 0.5) + (y + 2.5) * (y + 2.5)) / s2);
}

TEST(PatchMoments, RectangleMatchesClosedForm) {
  // A 7 x 4 rectangle of intensity 0.8, off the patch centre.
  const int w = 7, h = 4;
  const double v = 0.8;
  const cv::Mat patch =
      patch_from(10, [&](double x, double y) { return x >= -5 && x < -5 + w && y >= 1 && y < 1 + h ? v : 0.0; });
  const PatchMoments m = moments_of(patch);
  // Discrete sums over a run of n pixels about its middle:
  // sum d^2 = n(n^2-1)/12, sum d^4 = n(n^2-1)(3n^2-7)/240, odd sums = 0.
  const auto s2 = [](double n) { return n * (n * n - 1) / 12; };
  const auto s4 = [](double n) { return n * (n * n - 1) * (3 * n * n - 7) / 240; };
  const double mass = v * w * h;
  expect_relative(m.mass(), mass, 1e-6, "mu00");
  expect_relative(m.mu[2][0], v * h * s2(w), 1e-5, "mu20");
  expect_relative(m.mu[0][2], v * w * s2(h), 1e-5, "mu02");
  expect_relative(m.mu[4][0], v * h * s4(w), 1e-5, "mu40");
  expect_relative(m.mu[2][2], v * s2(w) * s2(h), 1e-5, "mu22");
  expect_relative(m.mu[0][4], v * w * s4(h), 1e-5, "mu04");
  for (const auto& [p, q] : {std::pair{1, 1}, {3, 0}, {2, 1}, {1, 2}, {0, 3}, {3, 1}, {1, 3}, {5, 0}, {3, 2}, {1, 4}})
    EXPECT_NEAR(m.mu[p][q], 0.0, 1e-4 * m.mu[2][0] * 10) << "odd moment mu" << p << q;
  expect_relative(m.eta(2, 0), v * h * s2(w) / (mass * mass), 1e-5, "eta20");
  expect_relative(m.eta(4, 0), v * h * s4(w) / std::pow(mass, 3), 1e-5, "eta40");
  expect_relative(m.eta(2, 2), v * s2(w) * s2(h) / std::pow(mass, 3), 1e-5, "eta22");
}

TEST(PatchMoments, MatchOpenCvUpToThirdOrder) {
  const cv::Mat patch = supersampled_patch(8, [](double x, double y) { return 0.1 + blob(x, y); });
  const PatchMoments m = moments_of(patch, 3);
  const cv::Moments cv_m = cv::moments(patch, false);
  expect_relative(m.mass(), cv_m.m00, 1e-6, "m00");
  expect_relative(m.mu[2][0], cv_m.mu20, 1e-5, "mu20");
  expect_relative(m.mu[1][1], cv_m.mu11, 1e-4, "mu11");
  expect_relative(m.mu[0][2], cv_m.mu02, 1e-5, "mu02");
  expect_relative(m.mu[3][0], cv_m.mu30, 1e-4, "mu30");
  expect_relative(m.mu[2][1], cv_m.mu21, 1e-4, "mu21");
  expect_relative(m.mu[1][2], cv_m.mu12, 1e-4, "mu12");
  expect_relative(m.mu[0][3], cv_m.mu03, 1e-4, "mu03");
  expect_relative(m.eta(2, 0), cv_m.nu20, 1e-5, "nu20");
  expect_relative(m.eta(2, 1), cv_m.nu21, 1e-4, "nu21");
  expect_relative(m.eta(0, 3), cv_m.nu03, 1e-4, "nu03");
}

TEST(PatchMoments, MatchBruteForceUpToFifthOrder) {
  cv::Mat patch(21, 21, CV_32F);
  cv::RNG rng(4);
  rng.fill(patch, cv::RNG::UNIFORM, 0.0, 1.0);
  const PatchMoments m = moments_of(patch);
  double m00 = 0, m10 = 0, m01 = 0;
  for (int y = 0; y < 21; ++y)
    for (int x = 0; x < 21; ++x) {
      const double v = patch.at<float>(y, x);
      m00 += v;
      m10 += v * x;
      m01 += v * y;
    }
  const double cx = m10 / m00, cy = m01 / m00;
  for (int p = 0; p <= 5; ++p)
    for (int q = 0; p + q <= 5; ++q) {
      double mu = 0;
      for (int y = 0; y < 21; ++y)
        for (int x = 0; x < 21; ++x) mu += std::pow(x - cx, p) * std::pow(y - cy, q) * patch.at<float>(y, x);
      const double scale = std::pow(10.0, p + q) * m00;  // magnitude of the terms summed
      EXPECT_NEAR(m.mu[p][q], p + q == 1 ? 0.0 : mu, 1e-6 * scale) << "mu" << p << q;
      if (p + q >= 2) {
        const double norm = std::pow(m00, 1 + (p + q) / 2.0);
        EXPECT_NEAR(m.eta(p, q), mu / norm, 1e-6 * scale / norm);
      }
    }
}

TEST(PatchMoments, ZeroPatchHasNoMoments) {
  const PatchMoments m = moments_of(cv::Mat::zeros(9, 9, CV_32F));
  EXPECT_EQ(m.mass(), 0.0);
  EXPECT_EQ(m.eta(2, 0), 0.0);
  EXPECT_EQ(affine_invariant(m, 1), 0.0);
  EXPECT_EQ(hu_invariants(m)[0], 0.0);
}

TEST(HuMoments, MatchOpenCv) {
  const cv::Mat patch = supersampled_patch(9, [](double x, double y) { return blob(x, y); });
  const auto phi = hu_invariants(moments_of(patch, 3));
  double reference[7];
  cv::HuMoments(cv::moments(patch, false), reference);
  for (int i = 0; i < 7; ++i)
    EXPECT_NEAR(phi[static_cast<std::size_t>(i)], reference[i], 1e-4 * std::abs(reference[i]) + 1e-12)
        << "phi" << i + 1;
}

TEST(HuMoments, UnchangedByQuarterTurnsOfThePatch) {
  const cv::Mat patch = supersampled_patch(10, [](double x, double y) { return 0.05 + blob(x, y); });
  const auto phi = hu_invariants(moments_of(patch, 3));
  for (const int code : {cv::ROTATE_90_CLOCKWISE, cv::ROTATE_180, cv::ROTATE_90_COUNTERCLOCKWISE}) {
    cv::Mat rotated;
    cv::rotate(patch, rotated, code);
    const auto turned = hu_invariants(moments_of(rotated, 3));
    for (int i = 0; i < 7; ++i)
      EXPECT_NEAR(turned[static_cast<std::size_t>(i)], phi[static_cast<std::size_t>(i)],
                  1e-4 * std::abs(phi[static_cast<std::size_t>(i)]) + 1e-15)
          << "phi" << i + 1 << " rotation " << code;
  }
  // A mirror image flips the sign of phi7 only (it detects reflection).
  cv::Mat mirrored;
  cv::flip(patch, mirrored, 1);
  const auto flipped = hu_invariants(moments_of(mirrored, 3));
  EXPECT_NEAR(flipped[6], -phi[6], 1e-4 * std::abs(phi[6]));
  EXPECT_GT(std::abs(phi[6]), 1e-12) << "the blob must be asymmetric for this test to mean anything";
}

TEST(AffineInvariants, UnchangedByAnAffineMapOfABlob) {
  const cv::Mat original = supersampled_patch(10, blob);
  const PatchMoments m = moments_of(original);
  for (const cv::Matx22d a : {cv::Matx22d(1.2, 0.4, -0.1, 0.9), cv::Matx22d(0.8, -0.5, 0.3, 1.1)}) {
    const cv::Matx22d inv = a.inv();
    const cv::Mat mapped = supersampled_patch(
        10, [&](double x, double y) { return blob(inv(0, 0) * x + inv(0, 1) * y, inv(1, 0) * x + inv(1, 1) * y); });
    const PatchMoments mm = moments_of(mapped);
    for (int k = 1; k <= 10; ++k) {
      const double expected = affine_invariant(m, k);
      // Resampling the mapped blob on the pixel grid perturbs the
      // higher orders most: 2 % up to 4th order, 5 % for I10 (5th order).
      const double tolerance = affine_invariant_order(k) < 5 ? 0.02 : 0.05;
      EXPECT_NEAR(affine_invariant(mm, k), expected, tolerance * std::abs(expected)) << "I" << k;
      EXPECT_GT(std::abs(expected), 1e-9) << "I" << k << " must not vanish on the test blob";
    }
  }
}

TEST(AffineInvariants, TellDifferentShapesApart) {
  const PatchMoments a = moments_of(supersampled_patch(10, blob));
  const PatchMoments b =
      moments_of(supersampled_patch(10, [](double x, double y) { return blob(-x, 0.6 * y) + blob(y, x); }));
  int differing = 0;
  for (int k = 1; k <= 10; ++k)
    differing += std::abs(affine_invariant(a, k) - affine_invariant(b, k)) > 0.1 * std::abs(affine_invariant(a, k));
  EXPECT_GE(differing, 8);
}

TEST(AffineInvariants, NeededOrders) {
  EXPECT_EQ(affine_invariant_order(1), 2);
  EXPECT_EQ(affine_invariant_order(2), 3);
  EXPECT_EQ(affine_invariant_order(5), 4);
  EXPECT_EQ(affine_invariant_order(9), 4);
  EXPECT_EQ(affine_invariant_order(10), 5);
}

TEST(CentralMomentsFromRaw, MatchADirectSumAboutTheCentroid) {
  // Weighted points; raw moments about an arbitrary origin.
  const double points[][3] = {{-3, 1, 0.5}, {2, 2, 2.0}, {0.5, -4, 1.0}, {4, -1, 0.25}, {1, 3, 3.0}};
  double raw[kMaxMomentOrder + 1][kMaxMomentOrder + 1] = {};
  double m00 = 0, mx = 0, my = 0;
  for (const auto& [x, y, w] : points) {
    for (int p = 0; p <= kMaxMomentOrder; ++p)
      for (int q = 0; p + q <= kMaxMomentOrder; ++q) raw[p][q] += std::pow(x, p) * std::pow(y, q) * w;
    m00 += w, mx += x * w, my += y * w;
  }
  double mu[kMaxMomentOrder + 1][kMaxMomentOrder + 1];
  central_moments_from_raw(raw, kMaxMomentOrder, mu);
  for (int p = 0; p <= kMaxMomentOrder; ++p)
    for (int q = 0; p + q <= kMaxMomentOrder; ++q) {
      double direct = 0;
      for (const auto& [x, y, w] : points) direct += std::pow(x - mx / m00, p) * std::pow(y - my / m00, q) * w;
      EXPECT_NEAR(mu[p][q], direct, 1e-9 * std::max(1.0, std::abs(direct))) << "mu" << p << q;
    }
}

}  // namespace
}  // namespace facadeslam::semantics
