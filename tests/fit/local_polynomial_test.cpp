#include "opf/fit/local_polynomial.h"

#include "opf/core/random.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

namespace opf {
namespace {

struct Signal {
  std::vector<double> t;
  Eigen::Matrix3Xd values;
};

// `count` samples at `rate` Hz ending at t = 7 s (far from 0, so the expansion point matters).
template <class F>
Signal sample(int count, double rate, F f) {
  Signal s;
  s.values.resize(3, count);
  for (int k = 0; k < count; ++k) {
    const double t = 7.0 - (count - 1 - k) / rate;
    s.t.push_back(t);
    s.values.col(k) = f(t);
  }
  return s;
}

TEST(LocalPolynomial, RecoversAQuadraticExactly) {
  const Eigen::Vector3d c0(1, -2, 0.5), c1(0.3, 0.1, -0.2), c2(-0.4, 0.05, 1.0);
  const Signal s = sample(20, 30.0, [&](double t) {
    const double tau = t - 7.0;
    return Eigen::Vector3d(c0 + c1 * tau + c2 * tau * tau);
  });
  LocalPolynomial fit;
  ASSERT_TRUE(fit_local_polynomial(s.t, s.values, 0.0, 7.0, 2, Eigen::Vector3d::Zero(), 3, fit));
  EXPECT_LT((fit.coefficients.col(0) - c0).norm(), 1e-9);
  EXPECT_LT((fit.coefficients.col(1) - c1).norm(), 1e-8);
  EXPECT_LT((fit.coefficients.col(2) - c2).norm(), 1e-7);
  EXPECT_LT((fit.value(7.5) - (c0 + 0.5 * c1 + 0.25 * c2)).norm(), 1e-7);
  EXPECT_LT((fit.rate(7.5) - (c1 + 1.0 * c2)).norm(), 1e-7);
  EXPECT_EQ(fit.samples, 20);
}

TEST(LocalPolynomial, KnownAccelerationLeavesOnlyTheLineToFit) {
  const Eigen::Vector3d g(0, 0, -9.81), v(2, 0.5, 3), p(0, 0, 1);
  const Signal s = sample(30, 100.0, [&](double t) {
    const double tau = t - 7.0;
    return Eigen::Vector3d(p + v * tau + 0.5 * g * tau * tau);
  });
  LocalPolynomial fit;
  ASSERT_TRUE(fit_local_polynomial(s.t, s.values, 0.0, 7.0, 1, g, 0, fit));
  EXPECT_LT((fit.rate(7.0) - v).norm(), 1e-9);
  // Extrapolated half a second: the parabola, not the tangent.
  EXPECT_LT((fit.value(7.5) - (p + 0.5 * v + 0.125 * g)).norm(), 1e-9);
}

TEST(LocalPolynomial, OnlyTheSamplesInTheRangeAreFitted) {
  // A line up to t = 6.5 s, then a step of 1 m: fitting [6.6, 7] sees only the step's level.
  const Signal s =
      sample(31, 60.0, [](double t) { return Eigen::Vector3d(t < 6.55 ? t : 10.0, 0.0, 0.0); });
  LocalPolynomial fit;
  ASSERT_TRUE(fit_local_polynomial(s.t, s.values, 6.6, 7.0, 0, Eigen::Vector3d::Zero(), 0, fit));
  EXPECT_NEAR(fit.value(7.0).x(), 10.0, 1e-12);
  EXPECT_EQ(fit.samples, 25);  // t = 6.6 .. 7.0 at 60 Hz
}

TEST(LocalPolynomial, HuberWeightsKeepAnOutlierFromBendingTheLine) {
  Random random(3);
  const Eigen::Vector3d v(0.2, -0.1, 0.0);
  Signal s = sample(30, 30.0, [&](double t) {
    return Eigen::Vector3d(v * (t - 7.0) +
                           0.002 * Eigen::Vector3d(random.normal(), random.normal(), 0.0));
  });
  s.values.col(25) += Eigen::Vector3d(0.5, 0.5, 0.0);  // a wrong detection near the end
  LocalPolynomial robust, plain;
  ASSERT_TRUE(fit_local_polynomial(s.t, s.values, 0.0, 7.0, 1, Eigen::Vector3d::Zero(), 3, robust));
  ASSERT_TRUE(fit_local_polynomial(s.t, s.values, 0.0, 7.0, 1, Eigen::Vector3d::Zero(), 0, plain));
  // Least squares moves the velocity by ~0.1 m/s; the robust fit keeps it within the noise's
  // ~4 sigma (sigma_v = 0.002 sqrt(12 / 30) / 0.97 s = 1.3 mm/s), plus the outlier's bounded pull.
  EXPECT_GT((plain.rate(7.0) - v).norm(), 0.05);
  EXPECT_LT((robust.rate(7.0) - v).norm(), 0.012);
}

TEST(LocalPolynomial, RefusesTooFewSamplesAndBadOrders) {
  const Signal s = sample(3, 30.0, [](double t) { return Eigen::Vector3d(t, 0, 0); });
  LocalPolynomial fit;
  EXPECT_TRUE(fit_local_polynomial(s.t, s.values, 0.0, 7.0, 1, Eigen::Vector3d::Zero(), 0, fit));
  EXPECT_FALSE(fit_local_polynomial(s.t, s.values, 0.0, 7.0, 2, Eigen::Vector3d::Zero(), 0, fit));
  EXPECT_THROW(fit_local_polynomial(s.t, s.values, 0.0, 7.0, 3, Eigen::Vector3d::Zero(), 0, fit),
               std::invalid_argument);
}

}  // namespace
}  // namespace opf
