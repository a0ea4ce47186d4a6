#include "particles/particle_kernels.h"

#include "particles/kernel_dispatch.h"
#include "particles/vector_math.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace opf::kernels {
namespace {

// Hamilton product a * b of quaternions stored (x, y, z, w).
struct Quat {
  double x, y, z, w;
};

OPF_ALWAYS_INLINE Quat multiply(const Quat& a, const Quat& b) {
  return {a.w * b.x + a.x * b.w + a.y * b.z - a.z * b.y,
          a.w * b.y - a.x * b.z + a.y * b.w + a.z * b.x,
          a.w * b.z + a.x * b.y - a.y * b.x + a.z * b.w,
          a.w * b.w - a.x * b.x - a.y * b.y - a.z * b.z};
}

OPF_ALWAYS_INLINE Quat normalised(const Quat& q) {
  const double inverse = 1.0 / std::sqrt(q.x * q.x + q.y * q.y + q.z * q.z + q.w * q.w);
  return {q.x * inverse, q.y * inverse, q.z * inverse, q.w * inverse};
}

OPF_ALWAYS_INLINE Quat load(const double* q, std::size_t n, std::size_t i) {
  return {q[i], q[n + i], q[2 * n + i], q[3 * n + i]};
}

OPF_ALWAYS_INLINE void store(double* q, std::size_t n, std::size_t i, const Quat& v) {
  q[i] = v.x;
  q[n + i] = v.y;
  q[2 * n + i] = v.z;
  q[3 * n + i] = v.w;
}

// exp of the tangent vector v: (sin(|v|/2) v/|v|, cos(|v|/2)), with the limit 1/2 of
// sin(|v|/2)/|v| at 0.
OPF_ALWAYS_INLINE Quat exp_tangent(double vx, double vy, double vz) {
  const double angle = std::sqrt(vx * vx + vy * vy + vz * vz);
  double s, c;
  vmath::sincos(0.5 * angle, s, c);
  const double factor = angle > 1e-300 ? s / angle : 0.5;
  return {factor * vx, factor * vy, factor * vz, c};
}

// The geodesic angle of the rotation r (any sign): 2 atan2(|v|, |w|), in [0, pi].
OPF_ALWAYS_INLINE double rotation_angle(const Quat& r) {
  return 2.0 * vmath::atan2_nonnegative(std::sqrt(r.x * r.x + r.y * r.y + r.z * r.z),
                                        std::fabs(r.w));
}

template <bool kPerParticle>
OPF_ALWAYS_INLINE void perturb(double* __restrict q, std::size_t n, const float* __restrict noise,
                               double sigma, const double* __restrict sigmas) {
#pragma omp simd
  for (std::size_t i = 0; i < n; ++i) {
    const double s = kPerParticle ? sigmas[i] : sigma;
    const Quat step = exp_tangent(s * noise[i], s * noise[n + i], s * noise[2 * n + i]);
    store(q, n, i, normalised(multiply(load(q, n, i), step)));
  }
}

template <bool kWeighted>
OPF_ALWAYS_INLINE TranslationSums sums(const double* __restrict x, std::size_t n,
                                       const double* __restrict w,
                                       const std::array<double, 3>& ref) {
  double sw = 0, sx = 0, sy = 0, sz = 0, xx = 0, xy = 0, xz = 0, yy = 0, yz = 0, zz = 0;
#pragma omp simd reduction(+ : sw, sx, sy, sz, xx, xy, xz, yy, yz, zz)
  for (std::size_t i = 0; i < n; ++i) {
    const double wi = kWeighted ? w[i] : 1.0;
    const double dx = x[i] - ref[0], dy = x[n + i] - ref[1], dz = x[2 * n + i] - ref[2];
    sw += wi;
    sx += wi * dx;
    sy += wi * dy;
    sz += wi * dz;
    xx += wi * dx * dx;
    xy += wi * dx * dy;
    xz += wi * dx * dz;
    yy += wi * dy * dy;
    yz += wi * dy * dz;
    zz += wi * dz * dz;
  }
  return {sw, {sx, sy, sz}, {xx, xy, xz, yy, yz, zz}};
}

template <bool kWeighted>
OPF_ALWAYS_INLINE std::array<double, 10> markley(const double* __restrict q, std::size_t n,
                                                 const double* __restrict w) {
  double xx = 0, xy = 0, xz = 0, xw = 0, yy = 0, yz = 0, yw = 0, zz = 0, zw = 0, ww = 0;
#pragma omp simd reduction(+ : xx, xy, xz, xw, yy, yz, yw, zz, zw, ww)
  for (std::size_t i = 0; i < n; ++i) {
    const double wi = kWeighted ? w[i] : 1.0;
    const Quat v = load(q, n, i);
    const double wx = wi * v.x, wy = wi * v.y, wz = wi * v.z;
    xx += wx * v.x;
    xy += wx * v.y;
    xz += wx * v.z;
    xw += wx * v.w;
    yy += wy * v.y;
    yz += wy * v.z;
    yw += wy * v.w;
    zz += wz * v.z;
    zw += wz * v.w;
    ww += wi * v.w * v.w;
  }
  return {xx, xy, xz, xw, yy, yz, yw, zz, zw, ww};
}

template <bool kWeighted>
OPF_ALWAYS_INLINE std::array<double, 6> tangent(const double* __restrict q, std::size_t n,
                                                const double* __restrict w, const Quat& inverse) {
  double xx = 0, xy = 0, xz = 0, yy = 0, yz = 0, zz = 0;
#pragma omp simd reduction(+ : xx, xy, xz, yy, yz, zz)
  for (std::size_t i = 0; i < n; ++i) {
    const double wi = kWeighted ? w[i] : 1.0;
    Quat r = multiply(inverse, load(q, n, i));
    // log on the hemisphere w >= 0: d = 2 atan2(|v|, w) v / |v|, -> 2 v / w as |v| -> 0.
    const double sign = r.w < 0.0 ? -1.0 : 1.0;
    const double vx = sign * r.x, vy = sign * r.y, vz = sign * r.z, rw = sign * r.w;
    const double norm = std::sqrt(vx * vx + vy * vy + vz * vz);
    const double angle = 2.0 * vmath::atan2_nonnegative(norm, rw);
    const double factor = norm > 1e-300 ? angle / norm : 2.0;
    const double dx = factor * vx, dy = factor * vy, dz = factor * vz;
    xx += wi * dx * dx;
    xy += wi * dx * dy;
    xz += wi * dx * dz;
    yy += wi * dy * dy;
    yz += wi * dy * dz;
    zz += wi * dz * dz;
  }
  return {xx, xy, xz, yy, yz, zz};
}

}  // namespace

OPF_KERNEL void add_scaled_noise(double* __restrict x, const float* __restrict noise, double sigma,
                                 std::size_t count) {
#pragma omp simd
  for (std::size_t i = 0; i < count; ++i) x[i] += sigma * static_cast<double>(noise[i]);
}

OPF_KERNEL void add_scaled_noise_per_particle(double* __restrict x, const float* __restrict noise,
                                              const double* __restrict sigma, std::size_t rows,
                                              std::size_t n) {
  for (std::size_t r = 0; r < rows; ++r) {
#pragma omp simd
    for (std::size_t i = 0; i < n; ++i)
      x[r * n + i] += sigma[i] * static_cast<double>(noise[r * n + i]);
  }
}

OPF_KERNEL void perturb_quaternions(double* q, std::size_t n, const float* noise, double sigma,
                                    const double* sigma_per_particle) {
  if (sigma_per_particle)
    perturb<true>(q, n, noise, sigma, sigma_per_particle);
  else
    perturb<false>(q, n, noise, sigma, nullptr);
}

OPF_KERNEL void rotate_quaternions(double* __restrict q, std::size_t n,
                                   const std::array<double, 4>& r) {
  const Quat turn{r[0], r[1], r[2], r[3]};
#pragma omp simd
  for (std::size_t i = 0; i < n; ++i) store(q, n, i, normalised(multiply(turn, load(q, n, i))));
}

OPF_KERNEL double translation_exponents(const double* __restrict x, std::size_t n,
                                        const std::array<double, 3>& z, double scale,
                                        double* __restrict out, bool accumulate) {
  double best = -std::numeric_limits<double>::infinity();
  const double zx = z[0], zy = z[1], zz = z[2];
  const double keep = accumulate ? 1.0 : 0.0;
#pragma omp simd reduction(max : best)
  for (std::size_t i = 0; i < n; ++i) {
    const double dx = x[i] - zx, dy = x[n + i] - zy, dz = x[2 * n + i] - zz;
    const double e = scale * (dx * dx + dy * dy + dz * dz);
    out[i] = keep * out[i] + e;
    best = std::max(best, e);
  }
  return best;
}

OPF_KERNEL double rotation_exponents(const double* __restrict q, std::size_t n,
                                     const std::array<double, 4>& z, double scale,
                                     double* __restrict out, bool accumulate) {
  double best = -std::numeric_limits<double>::infinity();
  const Quat inverse{-z[0], -z[1], -z[2], z[3]};  // z is a unit quaternion
  const double keep = accumulate ? 1.0 : 0.0;
#pragma omp simd reduction(max : best)
  for (std::size_t i = 0; i < n; ++i) {
    const double angle = rotation_angle(multiply(inverse, load(q, n, i)));
    const double e = scale * angle * angle;
    out[i] = keep * out[i] + e;
    best = std::max(best, e);
  }
  return best;
}

OPF_KERNEL NormalisedWeights normalise_log_weights(double* __restrict log_w,
                                                   double* __restrict linear, std::size_t n) {
  if (n == 0) return {};
  double top = -std::numeric_limits<double>::infinity();
  int nan = 0;
#pragma omp simd reduction(max : top) reduction(| : nan)
  for (std::size_t i = 0; i < n; ++i) {
    top = std::max(top, log_w[i]);
    nan |= std::isnan(log_w[i]) ? 1 : 0;
  }
  if (nan || !std::isfinite(top)) return {false, 0.0};
  double sum = 0.0, sum_squares = 0.0;
#pragma omp simd reduction(+ : sum, sum_squares)
  for (std::size_t i = 0; i < n; ++i) {
    const double w = vmath::exp_nonpositive(log_w[i] - top);
    linear[i] = w;
    sum += w;
    sum_squares += w * w;
  }
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

OPF_KERNEL double relative_weights(const double* __restrict log_w, double* __restrict linear,
                                   std::size_t n) {
  double top = -std::numeric_limits<double>::infinity();
#pragma omp simd reduction(max : top)
  for (std::size_t i = 0; i < n; ++i) top = std::max(top, log_w[i]);
  double sum = 0.0;
#pragma omp simd reduction(+ : sum)
  for (std::size_t i = 0; i < n; ++i) {
    linear[i] = vmath::exp_nonpositive(log_w[i] - top);
    sum += linear[i];
  }
  return sum;
}

void systematic_indices(const double* w, std::size_t n, double offset, std::size_t count,
                        std::size_t* indices) {
  // ends[k]: how many particles' intervals end at or before slot k; the particle of slot k is
  // that count. Particle i's slots end where (k + offset) / count reaches its cumulative weight
  // C_i: at ceil(count C_i - offset), clamped to [0, count]. The last particle takes any
  // remainder left by rounding.
  std::fill(indices, indices + count, std::size_t{0});
  const double slots = static_cast<double>(count);
  double cumulative = 0.0;
  for (std::size_t i = 0; i + 1 < n; ++i) {
    cumulative += w[i];
    const double end = std::ceil(slots * cumulative - offset);
    const std::size_t e = end <= 0.0 ? 0 : std::min(count, static_cast<std::size_t>(end));
    if (e < count) ++indices[e];
  }
  std::size_t particle = 0;
  for (std::size_t k = 0; k < count; ++k) {
    particle += indices[k];
    indices[k] = particle;
  }
}

OPF_KERNEL void gather_rows(const double* __restrict in, std::size_t n_in, std::size_t rows,
                            const std::size_t* __restrict indices, std::size_t count,
                            double* __restrict out) {
  for (std::size_t r = 0; r < rows; ++r) {
    const double* row = in + r * n_in;
    double* target = out + r * count;
    for (std::size_t k = 0; k < count; ++k) target[k] = row[indices[k]];
  }
}

OPF_KERNEL TranslationSums translation_sums(const double* x, std::size_t n, const double* w,
                                            const std::array<double, 3>& reference) {
  return w ? sums<true>(x, n, w, reference) : sums<false>(x, n, nullptr, reference);
}

OPF_KERNEL std::array<double, 10> quaternion_second_moment(const double* q, std::size_t n,
                                                           const double* w) {
  return w ? markley<true>(q, n, w) : markley<false>(q, n, nullptr);
}

OPF_KERNEL std::array<double, 6> tangent_second_moment(const double* q, std::size_t n,
                                                       const double* w,
                                                       const std::array<double, 4>& mean_inverse) {
  const Quat inverse{mean_inverse[0], mean_inverse[1], mean_inverse[2], mean_inverse[3]};
  return w ? tangent<true>(q, n, w, inverse) : tangent<false>(q, n, nullptr, inverse);
}

}  // namespace opf::kernels
