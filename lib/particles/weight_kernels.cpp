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

// w_i = exp(log_w[i] - max log_w) in T's precision, written to `linear`, with their sum and sum
// of squares: one body for normalisation (double) and for resampling and the share test (float).
// Not usable when a weight is NaN or every one -inf.
struct ShiftedExponentials {
  bool usable = false;
  double top = 0.0, sum = 0.0, sum_squares = 0.0;

  /// The ESS fraction (sum w)^2 / (n sum w^2).
  double ess_fraction(std::size_t n) const {
    return sum * sum / (static_cast<double>(n) * sum_squares);
  }
};

template <class T>
OPF_ALWAYS_INLINE ShiftedExponentials shifted_exponentials(const double* __restrict log_w,
                                                           T* __restrict linear, std::size_t n) {
  bool nan = false;
  const double top = max_value(log_w, n, nan);
  if (nan || !std::isfinite(top)) return {};
  const std::array<double, 2> sums =
      sum_in_lanes<T, 2>(n, [=](std::size_t i, std::size_t l, auto& a) OPF_INLINE_LAMBDA {
        const T w = vmath::exp_nonpositive(static_cast<T>(log_w[i] - top));
        linear[i] = w;
        a[0][l] += w;
        a[1][l] += w * w;
      });
  return {true, top, sums[0], sums[1]};
}

}  // namespace

OPF_KERNEL NormalisedWeights normalise_log_weights(double* __restrict log_w,
                                                   double* __restrict linear, std::size_t n) {
  if (n == 0) return {};
  const ShiftedExponentials e = shifted_exponentials<double>(log_w, linear, n);
  if (!e.usable) return {false, 0.0};
  // Shift by the max first, then by the log-sum of the (small) shifted values: full precision.
  const double shift = e.top + std::log(e.sum);
  const double inverse_sum = 1.0 / e.sum;
#pragma omp simd
  for (std::size_t i = 0; i < n; ++i) {
    log_w[i] -= shift;
    linear[i] *= inverse_sum;
  }
  return {true, e.ess_fraction(n)};
}

OPF_KERNEL NormalisedWeights resampling_weights(const double* __restrict log_w,
                                                float* __restrict linear, std::size_t n) {
  if (n == 0) return {};
  const ShiftedExponentials e = shifted_exponentials<float>(log_w, linear, n);
  return e.usable ? NormalisedWeights{true, e.ess_fraction(n)} : NormalisedWeights{false, 0.0};
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
