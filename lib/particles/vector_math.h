#pragma once
// Branch-free elementary functions for the particle kernels. Each is a scalar inline function
// written with selects instead of branches, so that a loop calling it vectorises (libm's exp,
// atan2 and sincos do not). Polynomials and reductions are Cephes' (S. L. Moshier), and fdlibm's
// for the double log, which keep about one ulp over the stated domains;
// tests/particles/vector_math_test.cpp checks them against libm.

#include <bit>
#include <cstdint>

namespace opf::vmath {

#define OPF_ALWAYS_INLINE [[gnu::always_inline]] inline
// On a lambda handed to an inline kernel helper: without it GCC may compile the lambda's body
// once, outside the target_clones versions of the kernel (baseline instructions, no vectors).
#define OPF_INLINE_LAMBDA __attribute__((always_inline))

inline constexpr double kHalfPi = 1.57079632679489661923;
inline constexpr double kQuarterPi = 0.78539816339744830962;

/// Rounds to the nearest integer by the 1.5 * 2^52 trick (no SSE4.1 round instruction needed);
/// valid for |x| < 2^51. `integer` receives the rounded value's low bits as an integer.
OPF_ALWAYS_INLINE double round_nearest(double x, std::int64_t& integer) {
  constexpr double kMagic = 6755399441055744.0;  // 1.5 * 2^52
  const double shifted = x + kMagic;
  integer = std::bit_cast<std::int64_t>(shifted) - std::bit_cast<std::int64_t>(kMagic);
  return shifted - kMagic;
}

/// e^x for x <= 0 (log-weights shifted by their maximum); exactly 0 below -708, where e^x would
/// be subnormal. NaN stays NaN. Reduction by ln 2 in two parts (Cephes), then the Taylor
/// polynomial to r^13 on |r| <= ln(2)/2 (truncation below 2e-17): no division.
OPF_ALWAYS_INLINE double exp_nonpositive(double x) {
  constexpr double kLog2e = 1.4426950408889634073599;
  constexpr double kC1 = 6.93145751953125E-1;
  constexpr double kC2 = 1.42860682030941723212E-6;
  const bool underflow = x < -708.0;
  const double clamped = underflow ? -708.0 : x;
  std::int64_t n;
  const double k = round_nearest(kLog2e * clamped, n);
  const double r = (clamped - k * kC1) - k * kC2;
  double p = 1.0 / 6227020800.0;  // 1/13!
  p = p * r + 1.0 / 479001600.0;
  p = p * r + 1.0 / 39916800.0;
  p = p * r + 1.0 / 3628800.0;
  p = p * r + 1.0 / 362880.0;
  p = p * r + 1.0 / 40320.0;
  p = p * r + 1.0 / 5040.0;
  p = p * r + 1.0 / 720.0;
  p = p * r + 1.0 / 120.0;
  p = p * r + 1.0 / 24.0;
  p = p * r + 1.0 / 6.0;
  p = p * r + 0.5;
  p = p * r + 1.0;
  p = p * r + 1.0;
  // 2^n by building the exponent field: n >= -1022 here, so the result is a normal number.
  const double scale = std::bit_cast<double>(static_cast<std::uint64_t>(n + 1023) << 52);
  const double result = p * scale;
  return underflow ? 0.0 : (x != x ? x : result);
}

/// Natural log of a positive normal double; +inf and NaN give themselves. fdlibm's e_log.c
/// (Sun Microsystems, under 1 ulp): x = (1 + f) 2^k with 1 + f in [sqrt(1/2), sqrt(2)), and
/// ln(1 + f) = f - f^2 / 2 + s (f^2 / 2 + R(s^2)), s = f / (2 + f), R its minimax polynomial.
OPF_ALWAYS_INLINE double log_positive(double x) {
  constexpr std::uint64_t kMantissa = 0x000FFFFFFFFFFFFFull;
  constexpr std::uint64_t kSqrt2Mantissa = 0x6A09E667F3BCDull;  // sqrt(2) = 1.6A09E667F3BCC9...
  const std::uint64_t bits = std::bit_cast<std::uint64_t>(x);
  const std::uint64_t mantissa = bits & kMantissa;
  const bool high = mantissa >= kSqrt2Mantissa;  // 1 + f = 1.mantissa / 2, one binade up
  const double m = std::bit_cast<double>(mantissa | (high ? 0x3FE0000000000000ull     // [0.5, 1)
                                                          : 0x3FF0000000000000ull));  // [1, 2)
  const double k =
      static_cast<double>(static_cast<std::int64_t>(bits >> 52) - 1023 + (high ? 1 : 0));
  const double f = m - 1.0;
  const double half_square = 0.5 * f * f;
  const double s = f / (2.0 + f);
  const double z = s * s;
  const double w = z * z;
  const double odd = w * (3.999999999940941908e-01 +
                          w * (2.222219843214978396e-01 + w * 1.531383769920937332e-01));
  const double even = z * (6.666666666666735130e-01 +
                           w * (2.857142874366239149e-01 +
                                w * (1.818357216161805012e-01 + w * 1.479819860511658591e-01)));
  const double r = odd + even;
  const double result =
      k * 6.93147180369123816490e-01 -
      ((half_square - (s * (half_square + r) + k * 1.90821492927058770002e-10)) - f);
  return x > 1.7976931348623157e308 || x != x ? x : result;
}

/// Natural log of a positive normal float (Cephes logf).
OPF_ALWAYS_INLINE float log_positive(float x) {
  const std::uint32_t bits = std::bit_cast<std::uint32_t>(x);
  int e = static_cast<int>(bits >> 23) - 126;  // x = m 2^e with m in [0.5, 1)
  float m = std::bit_cast<float>((bits & 0x007fffffu) | 0x3f000000u);
  const bool low = m < 0.707106781186547524f;
  e = low ? e - 1 : e;
  m = low ? m + m - 1.0f : m - 1.0f;
  const float z = m * m;
  float y = ((((((((7.0376836292E-2f * m - 1.1514610310E-1f) * m + 1.1676998740E-1f) * m -
                  1.2420140846E-1f) *
                     m +
                 1.4249322787E-1f) *
                    m -
                1.6668057665E-1f) *
                   m +
               2.0000714765E-1f) *
                  m -
              2.4999993993E-1f) *
                 m +
             3.3333331174E-1f) *
            m * z;
  const float fe = static_cast<float>(e);
  y += fe * -2.12194440e-4f;
  y += -0.5f * z;
  return (m + y) + fe * 0.693359375f;
}

/// sin and cos of x in [-pi/4, pi/4] in float: Cephes' sinf/cosf polynomials (about 1e-7).
OPF_ALWAYS_INLINE void sincos_reduced(float x, float& s, float& c) {
  const float z = x * x;
  s = ((-1.9515295891E-4f * z + 8.3321608736E-3f) * z - 1.6666654611E-1f) * z * x + x;
  c = ((2.443315711809948E-5f * z - 1.388731625493765E-3f) * z + 4.166664568298827E-2f) * z * z -
      0.5f * z + 1.0f;
}

/// sin(x) / x and cos(x) from z = x^2, for |x| <= pi/4 (z <= 0.6168): sincos_reduced's
/// polynomials without x itself, so a caller holding |v|^2 needs no square root or division.
OPF_ALWAYS_INLINE void sin_over_x_and_cos_of_square(float z, float& sin_over_x, float& c) {
  sin_over_x = ((-1.9515295891E-4f * z + 8.3321608736E-3f) * z - 1.6666654611E-1f) * z + 1.0f;
  c = ((2.443315711809948E-5f * z - 1.388731625493765E-3f) * z + 4.166664568298827E-2f) * z * z -
      0.5f * z + 1.0f;
}

/// asin(s) / s from z = s^2, for |s| <= 1/2 (z <= 1/4): Cephes asinf's polynomial (about 2.5e-7
/// relative), with no square root or division. For a unit quaternion (v, w) with |v| <= 1/2
/// (turns up to 60 degrees), the angle is 2 |v| asin_over_x_of_square(|v|^2).
OPF_ALWAYS_INLINE float asin_over_x_of_square(float z) {
  return ((((4.2163199048E-2f * z + 2.4181311049E-2f) * z + 4.5470025998E-2f) * z +
           7.4953002686E-2f) *
              z +
          1.6666752422E-1f) *
             z +
         1.0f;
}

// ---- Single precision, for the parts of a step whose results need 1e-7 relative accuracy only
// (angles of rotation particles: the observation noise is 0.05 rad), at twice the lanes.

/// sin x and cos x in float for |x| < 8192: reduction by pi/2 in three parts, then Cephes'
/// sinf/cosf polynomials on [-pi/4, pi/4].
OPF_ALWAYS_INLINE void sincos(float x, float& s, float& c) {
  constexpr float kTwoOverPi = 0.636619772367581343f;
  constexpr float kMagic = 12582912.0f;  // 1.5 * 2^23: adding it rounds to an integer
  const float shifted = x * kTwoOverPi + kMagic;
  const std::int32_t quadrant =
      (std::bit_cast<std::int32_t>(shifted) - std::bit_cast<std::int32_t>(kMagic)) & 3;
  const float k = shifted - kMagic;
  const float r =
      ((x - k * 1.5703125f) - k * 4.837512969970703125e-4f) - k * 7.54978995489188216e-8f;
  float sin_r, cos_r;
  sincos_reduced(r, sin_r, cos_r);
  const bool swap = (quadrant & 1) != 0;
  const float s0 = swap ? cos_r : sin_r;
  const float c0 = swap ? sin_r : cos_r;
  s = (quadrant & 2) != 0 ? -s0 : s0;
  c = (quadrant == 1 || quadrant == 2) ? -c0 : c0;
}

/// e^x in float for x <= 0 (Cephes expf); exactly 0 below -87, where e^x would be subnormal.
/// NaN gives NaN.
OPF_ALWAYS_INLINE float exp_nonpositive(float x) {
  constexpr float kMagic = 12582912.0f;  // 1.5 * 2^23: adding it rounds to an integer
  const bool underflow = x < -87.0f;
  const float clamped = underflow ? -87.0f : x;
  const float shifted = clamped * 1.44269504088896341f + kMagic;
  const std::int32_t n = std::bit_cast<std::int32_t>(shifted) - std::bit_cast<std::int32_t>(kMagic);
  const float k = shifted - kMagic;
  const float r = (clamped - k * 0.693359375f) + k * 2.12194440e-4f;
  const float z = r * r;
  const float p = (((((1.9875691500E-4f * r + 1.3981999507E-3f) * r + 8.3334519073E-3f) * r +
                     4.1665795894E-2f) *
                        r +
                    1.6666665459E-1f) *
                       r +
                   5.0000001201E-1f) *
                      z +
                  r + 1.0f;
  const float scale = std::bit_cast<float>(static_cast<std::uint32_t>(n + 127) << 23);
  return underflow ? 0.0f : (x != x ? x : p * scale);
}

/// atan2(y, x) / y in float for y >= 0 and x > 0, with its limit 1 / x at y = 0 (Cephes atanf
/// after reducing the ratio to [-tan(pi/8), tan(pi/8)]).
OPF_ALWAYS_INLINE float atan2_nonnegative_over_y(float y, float x) {
  constexpr float kTan3PiOver8 = 2.414213562373095f;
  constexpr float kTanPiOver8 = 0.4142135623730950f;
  const bool steep = y > kTan3PiOver8 * x;
  const bool middle = !steep && y > kTanPiOver8 * x;
  // Not !steep && !middle: GCC 12 does not vectorise that combination of AVX-512 masks.
  const bool small = y <= kTanPiOver8 * x;
  const float num = steep ? -x : (middle ? y - x : y);
  float den = steep ? y : (middle ? y + x : x);
  den = den > 0.0f ? den : 1.0f;
  const float base =
      steep ? static_cast<float>(kHalfPi) : (middle ? static_cast<float>(kQuarterPi) : 0.0f);
  const float u = num / den;
  const float z = u * u;
  // atan(u) = u series
  const float series = (((8.05374449538e-2f * z - 1.38776856032E-1f) * z + 1.99777106478E-1f) * z -
                        3.33329491539E-1f) *
                           z +
                       1.0f;
  // Small ratio: u = y / x, so u series / y = series / x, finite as y -> 0.
  const float numerator = small ? series : base + u * series;
  float denominator = small ? x : y;
  denominator = denominator > 0.0f ? denominator : 1.0f;
  return numerator / denominator;
}

/// atan2(y, x) / y in float for a unit vector (y, x) with x >= 0 and y >= 0, from y^2 alone: the
/// half angle of a unit quaternion (|v|, w) over |v|, which its logarithm needs. The half-angle
/// identity atan2(y, x) = 2 atan(y / (1 + x)) keeps u = y / (1 + x) in [0, 1], where atan(u) / u
/// is a degree-7 polynomial in u^2 (a minimax fit, 1e-7 relative): one division, no square root
/// and no reduction.
OPF_ALWAYS_INLINE float atan2_unit_over_y_of_square(float y_squared, float x) {
  const float inverse = 1.0f / (1.0f + x);
  const float z = y_squared * inverse * inverse;  // u^2
  const float atan_over_u =
      ((((((-4.6932610172E-3f * z + 2.4252350755E-2f) * z - 5.9486321432E-2f) * z +
          9.9142879625E-2f) *
             z -
         1.4019479217E-1f) *
            z +
        1.9969723617E-1f) *
           z -
       3.3331990729E-1f) *
          z +
      9.9999990099E-1f;
  return 2.0f * atan_over_u * inverse;
}

}  // namespace opf::vmath
