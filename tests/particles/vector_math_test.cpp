#include "opf/particles/vector_math.h"

#include "opf/core/random.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace opf {
namespace {

constexpr int kDraws = 200000;
constexpr double kUlp = std::numeric_limits<double>::epsilon();  // 2.2e-16
constexpr double kUlpF = std::numeric_limits<float>::epsilon();  // 1.2e-7

// Bounds are two units in the last place of the result type (Cephes' own figure is about one),
// except where a reduction step adds its own rounding (stated per test).

TEST(VectorMath, ExpNonPositiveMatchesLibmToTwoUlp) {
  Random random(1);
  double worst = 0.0;
  for (int i = 0; i < kDraws; ++i) {
    const double x = i % 2 ? -708.0 * random.uniform() : -random.uniform();
    worst = std::max(worst, std::abs(vmath::exp_nonpositive(x) / std::exp(x) - 1.0));
  }
  EXPECT_LT(worst, 2 * kUlp);
  EXPECT_EQ(vmath::exp_nonpositive(0.0), 1.0);
  EXPECT_EQ(vmath::exp_nonpositive(-708.5), 0.0);  // would be subnormal
  EXPECT_EQ(vmath::exp_nonpositive(-std::numeric_limits<double>::infinity()), 0.0);
  EXPECT_TRUE(std::isnan(vmath::exp_nonpositive(std::nan(""))));
}

// Over the whole range of normal doubles, and near 1, where ln x is small and only a relative
// bound says it is accurate.
TEST(VectorMath, LogPositiveMatchesLibmToTwoUlp) {
  Random random(2);
  double worst = 0.0;
  for (int i = 0; i < kDraws; ++i) {
    const double x =
        i % 2 ? std::exp(1400.0 * random.uniform() - 700.0) : 1.0 + 0.6 * (random.uniform() - 0.5);
    if (x == 1.0) continue;
    worst = std::max(worst, std::abs(vmath::log_positive(x) / std::log(x) - 1.0));
  }
  EXPECT_LT(worst, 2 * kUlp);
  EXPECT_EQ(vmath::log_positive(1.0), 0.0);
  EXPECT_EQ(vmath::log_positive(std::numeric_limits<double>::min()),
            std::log(std::numeric_limits<double>::min()));
  EXPECT_EQ(vmath::log_positive(std::numeric_limits<double>::infinity()),
            std::numeric_limits<double>::infinity());
  EXPECT_TRUE(std::isnan(vmath::log_positive(std::nan(""))));
}

TEST(VectorMath, SinCosMatchLibm) {
  Random random(3);
  float worst_float = 0.0f;
  for (int i = 0; i < kDraws; ++i) {
    const double x = 200.0 * (random.uniform() - 0.5);
    const auto xf = static_cast<float>(x);
    float sf, cf;
    vmath::sincos(xf, sf, cf);
    worst_float = std::max({worst_float, static_cast<float>(std::abs(sf - std::sin(double(xf)))),
                            static_cast<float>(std::abs(cf - std::cos(double(xf))))});
  }
  EXPECT_LT(worst_float, 2 * kUlpF);
}

TEST(VectorMath, SinglePrecisionLogExpAndArctangent) {
  Random random(4);
  double worst_log = 0.0, worst_exp = 0.0, worst_atan = 0.0;
  for (int i = 0; i < kDraws; ++i) {
    const auto u = static_cast<float>((random.next() >> 40) + 1) * 0x1.0p-24f;  // (0, 1]
    if (u != 1.0f)
      worst_log = std::max(worst_log, std::abs(vmath::log_positive(u) / std::log(double(u)) - 1.0));
    const auto x = static_cast<float>(-87.0 * random.uniform());
    worst_exp =
        std::max(worst_exp, std::abs(vmath::exp_nonpositive(x) / std::exp(double(x)) - 1.0));
    const auto y = static_cast<float>(std::pow(10.0, 10.0 * random.uniform() - 5.0));
    const auto w = static_cast<float>(random.uniform() + 1e-3);
    const double reference = std::atan2(double(y), double(w));
    worst_atan =
        std::max(worst_atan, std::abs(vmath::atan2_nonnegative_over_y(y, w) * y / reference - 1.0));
  }
  EXPECT_LT(worst_log, 2 * kUlpF);
  EXPECT_LT(worst_exp, 2 * kUlpF);
  EXPECT_LT(worst_atan, 4 * kUlpF);  // reduction, polynomial and the final division
  EXPECT_EQ(vmath::exp_nonpositive(-88.0f), 0.0f);
  EXPECT_EQ(vmath::log_positive(1.0f), 0.0f);
}

TEST(VectorMath, ReducedSinCosIsAccurateOnItsInterval) {
  float worst = 0.0f;
  for (int i = -1000; i <= 1000; ++i) {
    const float x = static_cast<float>(M_PI / 4) * static_cast<float>(i) / 1000.0f;
    float s, c;
    vmath::sincos_reduced(x, s, c);
    worst = std::max({worst, static_cast<float>(std::abs(s - std::sin(double(x)))),
                      static_cast<float>(std::abs(c - std::cos(double(x))))});
  }
  EXPECT_LT(worst, 2 * kUlpF);
}

// The square-argument forms the rotation kernels use where they hold |v|^2 and not |v|: relative
// error of sin(x)/x and absolute of cos(x) on |x| <= pi/4, relative error of asin(s)/s on
// |s| <= 1/2 (Cephes gives 2.5e-7 for asinf: two ulp).
TEST(VectorMath, SquareArgumentFormsAreAccurateOnTheirIntervals) {
  float worst_sinc = 0.0f, worst_cos = 0.0f, worst_asin = 0.0f;
  for (int i = 0; i <= 2000; ++i) {
    const double x = M_PI / 4 * i / 2000.0;
    float sinc, c;
    vmath::sin_over_x_and_cos_of_square(static_cast<float>(x * x), sinc, c);
    const double exact_sinc = i == 0 ? 1.0 : std::sin(x) / x;
    worst_sinc = std::max(worst_sinc, static_cast<float>(std::abs(sinc / exact_sinc - 1.0)));
    worst_cos = std::max(worst_cos, static_cast<float>(std::abs(c - std::cos(x))));
    const double s = 0.5 * i / 2000.0;
    const double exact_asinc = i == 0 ? 1.0 : std::asin(s) / s;
    const float asinc = vmath::asin_over_x_of_square(static_cast<float>(s * s));
    worst_asin = std::max(worst_asin, static_cast<float>(std::abs(asinc / exact_asinc - 1.0)));
  }
  EXPECT_LT(worst_sinc, 2 * kUlpF);
  EXPECT_LT(worst_cos, 2 * kUlpF);
  EXPECT_LT(worst_asin, 2 * kUlpF);
}

// The unit-vector form the tangent moments take for clouds spread past 60 degrees: every half
// angle from 0 to a half turn, the float vector (sin, cos) rounded as a normalised quaternion's
// parts are. Bound: the fit's 1.5 ulp plus the rounding of the vector's norm and the division.
TEST(VectorMath, UnitArctangentOverItsSineIsAccurateOnAQuarterTurn) {
  double worst = 0.0;
  for (int i = 0; i <= 200000; ++i) {
    const double half_angle = M_PI / 2 * i / 200000.0;
    const auto y = static_cast<float>(std::sin(half_angle));
    const auto x = static_cast<float>(std::cos(half_angle));
    const double exact = i == 0 ? 1.0 : std::atan2(double(y), double(x)) / double(y);
    worst = std::max(worst, std::abs(vmath::atan2_unit_over_y_of_square(y * y, x) / exact - 1.0));
  }
  EXPECT_LT(worst, 3 * kUlpF);
  EXPECT_NEAR(vmath::atan2_unit_over_y_of_square(0.0f, 1.0f), 1.0f, kUlpF);  // the limit at 0
}

}  // namespace
}  // namespace opf
