#pragma once
// Branch-free elementary functions for the particle kernels. Each is a scalar inline function
// written with selects instead of branches, so that a loop calling it vectorises (libm's exp,
// atan2 and sincos do not). Polynomials and reductions are Cephes' (S. L. Moshier), which keep
// about one ulp over the stated domains; tests/particles/vector_math_test.cpp checks them
// against libm.

#include <bit>
#include <cstdint>

namespace opf::vmath {

#define OPF_ALWAYS_INLINE [[gnu::always_inline]] inline

inline constexpr double kPi = 3.14159265358979323846;
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
/// be subnormal. NaN stays NaN.
OPF_ALWAYS_INLINE double exp_nonpositive(double x) {
  constexpr double kLog2e = 1.4426950408889634073599;
  constexpr double kC1 = 6.93145751953125E-1;
  constexpr double kC2 = 1.42860682030941723212E-6;
  const bool underflow = x < -708.0;
  const double clamped = underflow ? -708.0 : x;
  std::int64_t n;
  const double px = round_nearest(kLog2e * clamped, n);
  const double r = (clamped - px * kC1) - px * kC2;
  const double rr = r * r;
  const double p = r * ((1.26177193074810590878E-4 * rr + 3.02994407707441961300E-2) * rr +
                        9.99999999999999999910E-1);
  const double q = ((3.00198505138664455042E-6 * rr + 2.52448340349684104192E-3) * rr +
                    2.27265548208155028766E-1) *
                       rr +
                   2.00000000000000000009E0;
  const double mantissa = 1.0 + 2.0 * (p / (q - p));
  // 2^n by building the exponent field: n >= -1022 here, so the result is a normal number.
  const double scale = std::bit_cast<double>(static_cast<std::uint64_t>(n + 1023) << 52);
  return underflow ? 0.0 : mantissa * scale;
}

/// atan2(y, x) for y >= 0 and x >= 0, not both 0, in [0, pi/2]. One division picks the reduced
/// argument of Cephes' three ranges; the rational approximation needs a second.
OPF_ALWAYS_INLINE double atan2_nonnegative(double y, double x) {
  constexpr double kTan3PiOver8 = 2.41421356237309504880;
  constexpr double kMoreBits = 6.123233995736765886130E-17;
  const bool steep = y > kTan3PiOver8 * x;     // ratio above tan(3 pi / 8)
  const bool middle = !steep && y > 0.66 * x;  // ratio in (0.66, tan(3 pi / 8)]
  const double num = steep ? -x : (middle ? y - x : y);
  double den = steep ? y : (middle ? y + x : x);
  den = den > 0.0 ? den : 1.0;  // y = x = 0 gives 0, not NaN
  const double base =
      steep ? kHalfPi + kMoreBits : (middle ? kQuarterPi + 0.5 * kMoreBits : 0.0);
  const double u = num / den;
  const double z = u * u;
  const double p = (((-8.750608600031904122785E-1 * z - 1.615753718733365076637E1) * z -
                     7.500855792314704667340E1) *
                        z -
                    1.228866684490136173410E2) *
                       z -
                   6.485021904942025371773E1;
  const double q = ((((z + 2.485846490142306297962E1) * z + 1.650270098316988542046E2) * z +
                     4.328810604912902668951E2) *
                        z +
                    4.853903996359136964868E2) *
                       z +
                   1.945506571482613964425E2;
  return base + (u + u * (z * p / q));
}

/// sin x and cos x for |x| < 2^30 (rotation half-angles): reduction by pi/2 in three parts, then
/// Cephes' polynomials on [-pi/4, pi/4] and the quadrant's swap and signs.
OPF_ALWAYS_INLINE void sincos(double x, double& s, double& c) {
  constexpr double kTwoOverPi = 0.63661977236758134308;
  std::int64_t n;
  const double k = round_nearest(x * kTwoOverPi, n);
  const double r = ((x - k * 1.57079625129699707031) - k * 7.54978941586159635335E-8) -
                   k * 5.39030285815811905290E-15;
  const double z = r * r;
  const double sin_r =
      r + r * z *
              (((((1.58962301576546568060E-10 * z - 2.50507477628578072866E-8) * z +
                  2.75573136213857245213E-6) *
                     z -
                 1.98412698295895385996E-4) *
                    z +
                8.33333333332211858878E-3) *
                   z -
               1.66666666666666307295E-1);
  const double cos_r =
      1.0 - 0.5 * z +
      z * z *
          (((((-1.13585365213876817300E-11 * z + 2.08757008419747316778E-9) * z -
              2.75573141792967388112E-7) *
                 z +
             2.48015872888517045348E-5) *
                z -
            1.38888888888730564116E-3) *
               z +
           4.16666666666665929218E-2);
  const std::int64_t quadrant = n & 3;
  const bool swap = (quadrant & 1) != 0;
  const double s0 = swap ? cos_r : sin_r;
  const double c0 = swap ? sin_r : cos_r;
  s = (quadrant & 2) != 0 ? -s0 : s0;
  c = (quadrant == 1 || quadrant == 2) ? -c0 : c0;
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

/// sin and cos of x in [0, pi/2] in float: Taylor polynomials to x^11 and x^12 (error below
/// 1e-8 over the interval, under float's resolution).
OPF_ALWAYS_INLINE void sincos_quadrant(float x, float& s, float& c) {
  const float z = x * x;
  s = x * (1.0f +
           z * (-1.0f / 6 +
                z * (1.0f / 120 +
                     z * (-1.0f / 5040 + z * (1.0f / 362880 + z * (-1.0f / 39916800))))));
  c = 1.0f +
      z * (-0.5f +
           z * (1.0f / 24 +
                z * (-1.0f / 720 +
                     z * (1.0f / 40320 + z * (-1.0f / 3628800 + z * (1.0f / 479001600))))));
}

}  // namespace opf::vmath
