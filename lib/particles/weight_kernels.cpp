#include "opf/particles/weight_kernels.h"

#include "opf/particles/kernel_support.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <memory>
#include <stdexcept>
#include <vector>

namespace opf::kernels {

using namespace detail;

namespace {

// The largest value, and whether any is NaN.
OPF_ALWAYS_INLINE double max_value(const double* __restrict a, std::size_t n, bool& has_nan) {
  constexpr double kNone = -std::numeric_limits<double>::infinity();
  double top[kLanes] = {kNone, kNone, kNone, kNone, kNone, kNone, kNone, kNone};
  int nan[kLanes] = {};
  std::size_t i = 0;
  for (; i + kLanes <= n; i += kLanes) {
#pragma omp simd
    for (std::size_t l = 0; l < kLanes; ++l) {
      const double v = a[i + l];
      top[l] = v > top[l] ? v : top[l];
      nan[l] |= v != v ? 1 : 0;
    }
  }
  for (; i < n; ++i) {
    top[0] = a[i] > top[0] ? a[i] : top[0];
    nan[0] |= a[i] != a[i] ? 1 : 0;
  }
  int any = 0;
  for (std::size_t l = 0; l < kLanes; ++l) any |= nan[l];
  has_nan = any != 0;
  return lanes_max(top);
}

// exp(log_w - max log_w) in single precision, written to `linear` when kWrite, and the ESS
// fraction of those weights: one body for resampling and for the share test, so both read the
// same fraction.
template <bool kWrite>
OPF_ALWAYS_INLINE NormalisedWeights single_precision_weights(const double* __restrict log_w,
                                                             float* __restrict linear,
                                                             std::size_t n) {
  if (n == 0) return {};
  bool nan = false;
  const double top = max_value(log_w, n, nan);
  if (nan || !std::isfinite(top)) return {false, 0.0};
  const std::array<double, 2> sums = sum_in_lanes<float, 2>(
      n, [=](std::size_t i, std::size_t l, float(&a)[2][16]) OPF_INLINE_LAMBDA {
        const float w = vmath::exp_nonpositive(static_cast<float>(log_w[i] - top));
        if constexpr (kWrite) linear[i] = w;
        a[0][l] += w;
        a[1][l] += w * w;
      });
  return {true, sums[0] * sums[0] / (static_cast<double>(n) * sums[1])};
}

}  // namespace

OPF_KERNEL NormalisedWeights normalise_log_weights(double* __restrict log_w,
                                                   double* __restrict linear, std::size_t n) {
  if (n == 0) return {};
  bool nan = false;
  const double top = max_value(log_w, n, nan);
  if (nan || !std::isfinite(top)) return {false, 0.0};
  const std::array<double, 2> sums = sum_in_lanes<double, 2>(
      n, [=](std::size_t i, std::size_t l, double(&a)[2][8]) OPF_INLINE_LAMBDA {
        const double w = vmath::exp_nonpositive(log_w[i] - top);
        linear[i] = w;
        a[0][l] += w;
        a[1][l] += w * w;
      });
  const double sum = sums[0], sum_squares = sums[1];
  // Shift by the max first, then by the log-sum of the (small) shifted values: full precision.
  const double shift = top + std::log(sum);
  const double inverse_sum = 1.0 / sum;
#pragma omp simd
  for (std::size_t i = 0; i < n; ++i) {
    log_w[i] -= shift;
    linear[i] *= inverse_sum;
  }
  return {true, sum * sum / (static_cast<double>(n) * sum_squares)};
}

OPF_KERNEL NormalisedWeights resampling_weights(const double* __restrict log_w,
                                                float* __restrict linear, std::size_t n) {
  return single_precision_weights<true>(log_w, linear, n);
}

OPF_KERNEL double effective_fraction(const double* __restrict log_w, std::size_t n) {
  const NormalisedWeights w = single_precision_weights<false>(log_w, nullptr, n);
  return n > 0 && w.usable ? w.ess_fraction : std::numeric_limits<double>::quiet_NaN();
}

OPF_KERNEL double relative_weights(const double* __restrict log_w, double* __restrict linear,
                                   std::size_t n) {
  bool nan = false;
  const double top = max_value(log_w, n, nan);
  return sum_in_lanes<double, 1>(
      n, [=](std::size_t i, std::size_t l, double(&a)[1][8]) OPF_INLINE_LAMBDA {
        linear[i] = vmath::exp_nonpositive(log_w[i] - top);
        a[0][l] += linear[i];
      })[0];
}

}  // namespace opf::kernels
