#include "opf/particles/likelihood_kernels.h"
#include "opf/particles/motion_kernels.h"
#include "opf/particles/resampling_kernels.h"
#include "opf/particles/statistics_kernels.h"
#include "opf/particles/weight_kernels.h"

#include "opf/core/random.h"
#include "opf/core/so3.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <array>
#include <cmath>
#include <limits>
#include <numeric>
#include <vector>

namespace opf {
namespace {

// Random unit quaternions near `centre` with `spread` rad of tangent noise, as four rows.
std::vector<float> quaternion_rows(std::size_t n, const Eigen::Quaterniond& centre, double spread,
                                   Random& random) {
  std::vector<float> q(4 * n);
  for (std::size_t i = 0; i < n; ++i) {
    const Eigen::Vector3d e(random.normal(), random.normal(), random.normal());
    const Eigen::Quaterniond v = centre * so3::exp(spread * e);
    for (int r = 0; r < 4; ++r) q[r * n + i] = static_cast<float>(v.coeffs()[r]);
  }
  return q;
}

Eigen::Quaterniond column(const std::vector<float>& q, std::size_t n, std::size_t i) {
  return Eigen::Quaterniond(q[3 * n + i], q[i], q[n + i], q[2 * n + i]);
}

// The textbook walk over the cumulative weights (the definition of systematic resampling).
std::vector<std::size_t> reference_systematic(const std::vector<double>& w, double offset) {
  const double total = std::accumulate(w.begin(), w.end(), 0.0);
  std::vector<std::size_t> indices;
  double cumulative = w[0] / total;
  std::size_t j = 0;
  for (std::size_t k = 0; k < w.size(); ++k) {
    const double u = (static_cast<double>(k) + offset) / static_cast<double>(w.size());
    while (u >= cumulative && j + 1 < w.size()) cumulative += w[++j] / total;
    indices.push_back(j);
  }
  return indices;
}

TEST(ParticleKernels, SystematicIndicesFollowTheCumulativeWeights) {
  Random random(1);
  for (std::size_t n : {2, 7, 100, 1001, 5000}) {
    std::vector<double> w(n);
    for (double& v : w) v = std::exp(-8.0 * random.uniform());  // spans three decades
    const double offset = random.uniform();
    std::vector<std::size_t> indices(n);
    kernels::systematic_indices(w.data(), n, offset, n, indices.data());
    const std::vector<std::size_t> expected = reference_systematic(w, offset);
    // Both walks add the same weights in a different order; a slot may change particle only
    // where a position falls within rounding of a boundary, which these draws never do.
    EXPECT_EQ(indices, expected) << n;
    std::vector<float> wf(w.begin(), w.end());
    kernels::systematic_indices(wf.data(), n, offset, n, indices.data());
    std::size_t differing = 0;
    const std::vector<std::size_t> expected_f =
        reference_systematic(std::vector<double>(wf.begin(), wf.end()), offset);
    for (std::size_t k = 0; k < n; ++k) differing += indices[k] != expected_f[k];
    EXPECT_EQ(differing, 0u) << n;
  }
}

// Stratified resampling by end marks equals the walk over positions (k + u_k) / count.
TEST(ParticleKernels, StratifiedIndicesFollowTheCumulativeWeights) {
  Random random(7);
  for (std::size_t n : {2, 7, 100, 5000}) {
    std::vector<double> w(n), u(n);
    for (double& v : w) v = std::exp(-8.0 * random.uniform());
    for (double& v : u) v = random.uniform();
    const double total = std::accumulate(w.begin(), w.end(), 0.0);
    std::vector<std::size_t> expected;
    double cumulative = w[0] / total;
    std::size_t j = 0;
    for (std::size_t k = 0; k < n; ++k) {
      const double position = (static_cast<double>(k) + u[k]) / static_cast<double>(n);
      while (position >= cumulative && j + 1 < n) cumulative += w[++j] / total;
      expected.push_back(j);
    }
    std::vector<std::size_t> indices(n);
    kernels::stratified_indices(w.data(), n, u.data(), n, indices.data());
    EXPECT_EQ(indices, expected) << n;
  }
}

// The one-pass resampling copies exactly what the index walk selects.
TEST(ParticleKernels, SystematicResampleCopiesTheSelectedParticles) {
  Random random(6);
  for (std::size_t n : {2, 9, 1000, 4099}) {
    std::vector<float> w(n);
    for (float& v : w) v = static_cast<float>(std::exp(-6.0 * random.uniform()));
    const double offset = random.uniform();
    std::vector<std::size_t> indices(n);
    kernels::systematic_indices(w.data(), n, offset, n, indices.data());
    std::vector<double> translation(3 * n), moved(3 * n), expected(3 * n);
    for (double& v : translation) v = random.normal();
    kernels::systematic_resample(w.data(), n, offset, translation.data(), 3, moved.data());
    kernels::gather_rows(translation.data(), n, 3, indices.data(), n, expected.data());
    EXPECT_EQ(moved, expected) << n;
    std::vector<float> rotation(4 * n), turned(4 * n), expected_rotation(4 * n);
    for (float& v : rotation) v = static_cast<float>(random.normal());
    kernels::systematic_resample(w.data(), n, offset, rotation.data(), 4, turned.data());
    kernels::gather_rows(rotation.data(), n, 4, indices.data(), n, expected_rotation.data());
    EXPECT_EQ(turned, expected_rotation) << n;
  }
}

TEST(ParticleKernels, SystematicResamplingOfEqualWeightsKeepsEveryParticle) {
  std::vector<double> w(1000, 3.0);
  std::vector<std::size_t> indices(1000);
  kernels::systematic_indices(w.data(), w.size(), 0.37, w.size(), indices.data());
  for (std::size_t k = 0; k < indices.size(); ++k) EXPECT_EQ(indices[k], k);
  // One particle with all the weight takes every slot.
  std::vector<double> one(50, 0.0);
  one[17] = 1.0;
  kernels::systematic_indices(one.data(), one.size(), 0.5, 20, indices.data());
  for (std::size_t k = 0; k < 20; ++k) EXPECT_EQ(indices[k], 17u);
}

// Steps of every length: up to ~6 rad in every block (sin and cos by reduction), up to ~0.6 rad
// (the polynomials in |e|^2), the same with one shared sigma, and short steps with one long one
// in the second block.
TEST(ParticleKernels, PerturbQuaternionsIsTheTangentRandomWalk) {
  Random random(2);
  const std::size_t n = 1003;  // not a multiple of any vector width
  const Eigen::Quaterniond centre = so3::exp(Eigen::Vector3d(0.3, -1.2, 2.0));
  enum class Steps { kLong, kShort, kShared, kOneLong };
  for (const Steps steps : {Steps::kLong, Steps::kShort, Steps::kShared, Steps::kOneLong}) {
    std::vector<float> q = quaternion_rows(n, centre, 0.3, random);
    const std::vector<float> before = q;
    std::vector<float> noise(3 * n);
    for (float& v : noise) v = static_cast<float>(3.0 * random.normal());  // up to ~12 sigma
    std::vector<double> sigma(n);
    const double largest = steps == Steps::kLong ? 0.5 : 0.05;
    for (double& s : sigma) s = steps == Steps::kShared ? largest : largest * random.uniform();
    if (steps == Steps::kOneLong) sigma[300] = 1.0;
    kernels::perturb_quaternions(q.data(), n, n, noise.data(), largest,
                                 steps == Steps::kShared ? nullptr : sigma.data());
    double worst_angle = 0.0, worst_norm = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      const Eigen::Vector3d step =
          sigma[i] * Eigen::Vector3d(noise[i], noise[n + i], noise[2 * n + i]);
      const Eigen::Quaterniond expected = column(before, n, i) * so3::exp(step);
      worst_angle = std::max(worst_angle, so3::angle_between(column(q, n, i), expected));
      worst_norm = std::max(worst_norm, std::abs(column(q, n, i).norm() - 1.0));
    }
    // Single precision: a few float epsilons (1.2e-7) of angle and of norm.
    EXPECT_LT(worst_angle, 1e-6) << static_cast<int>(steps);
    EXPECT_LT(worst_norm, 5e-7) << static_cast<int>(steps);
  }
}

TEST(ParticleKernels, RotateQuaternionsTurnsEveryParticle) {
  Random random(3);
  const std::size_t n = 77;
  std::vector<float> q = quaternion_rows(n, Eigen::Quaterniond::Identity(), 1.0, random);
  const std::vector<float> before = q;
  const Eigen::Quaterniond turn = so3::exp(Eigen::Vector3d(0.1, 0.7, -0.4));
  kernels::rotate_quaternions(q.data(), n, {turn.x(), turn.y(), turn.z(), turn.w()});
  for (std::size_t i = 0; i < n; ++i)
    EXPECT_LT(so3::angle_between(column(q, n, i), turn * column(before, n, i)), 1e-6);
}

// The velocity drift's fused step does in one pass exactly what a turn and then the random walk
// do in two, bit for bit: the OPF's results do not depend on which path ran.
TEST(ParticleKernels, TurnAndPerturbIsTheTurnThenTheRandomWalk) {
  Random random(4);
  const std::size_t n = 1003;
  for (const double sigma : {0.02, 2.0}) {  // the polynomial path and the reduction's
    std::vector<float> fused =
        quaternion_rows(n, so3::exp(Eigen::Vector3d(0.2, 0.1, -0.3)), 0.2, random);
    std::vector<float> two_passes = fused;
    std::vector<float> noise(3 * n);
    for (float& v : noise) v = static_cast<float>(random.normal());
    const Eigen::Quaterniond turn = so3::exp(Eigen::Vector3d(0.05, -0.02, 0.3));
    const std::array<double, 4> r{turn.x(), turn.y(), turn.z(), turn.w()};
    kernels::turn_and_perturb_quaternions(fused.data(), n, n, noise.data(), sigma, r);
    kernels::rotate_quaternions(two_passes.data(), n, r);
    kernels::perturb_quaternions(two_passes.data(), n, n, noise.data(), sigma, nullptr);
    EXPECT_EQ(fused, two_passes) << sigma;
  }
  std::vector<double> x(1003), shifted(1003);
  std::vector<float> noise(x.size());
  for (std::size_t i = 0; i < x.size(); ++i) {
    x[i] = shifted[i] = random.normal();
    noise[i] = static_cast<float>(random.normal());
  }
  kernels::add_offset_and_scaled_noise(x.data(), noise.data(), 0.25, 0.01, x.size());
  for (double& v : shifted) v += 0.25;
  kernels::add_scaled_noise(shifted.data(), noise.data(), 0.01, shifted.size());
  EXPECT_EQ(x, shifted);
}

// Clouds of every spread: 0.05 rad keeps every block of particles within 60 degrees of z (the
// kernel's asin polynomial), 1.5 rad puts far particles in every block (the arctangent over its
// whole range), 0.3 rad mixes the two; one far particle among near ones sends only its block
// down the arctangent path.
std::vector<float> cloud_of_spread(std::size_t n, const Eigen::Quaterniond& centre, double spread,
                                   Random& random) {
  std::vector<float> q = quaternion_rows(n, centre, spread > 0.0 ? spread : 0.05, random);
  if (spread < 0.0) {  // one stray particle, 2.5 rad away, in the second block
    const Eigen::Quaterniond far = centre * so3::exp(Eigen::Vector3d(0.0, 2.5, 0.0));
    for (int r = 0; r < 4; ++r) q[r * n + 300] = static_cast<float>(far.coeffs()[r]);
  }
  return q;
}

// Float quaternions resolve angles to a few 1e-8 rad; the product z^-1 q adds about four
// roundings of 6e-8 per component, so the kernel's angle is good to 5e-7 rad (the worst seen over
// these clouds is 4e-7 near pi and 1.2e-7 below 60 degrees). The exponent s theta^2 then moves
// by at most |s| (2 theta + delta) delta.
double exponent_tolerance(double scale, double angle) {
  constexpr double kAngleResolution = 5e-7;
  return std::abs(scale) * (2.0 * angle + kAngleResolution) * kAngleResolution;
}

TEST(ParticleKernels, RotationExponentsAreMinusHalfSquaredAnglesOverVariance) {
  Random random(4);
  const std::size_t n = 1001;  // three whole blocks and a partial one
  const Eigen::Quaterniond z = so3::exp(Eigen::Vector3d(1.0, 0.5, -2.0));
  for (const double spread : {0.05, 0.3, 1.5, -1.0}) {
    const std::vector<float> q = cloud_of_spread(n, z, spread, random);
    const double variance = 0.0025, scale = -0.5 / variance;
    std::vector<double> out(n, 1.0);
    const double best = kernels::rotation_exponents(q.data(), n, {z.x(), z.y(), z.z(), z.w()},
                                                    scale, out.data(), true);
    double expected_best = -std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < n; ++i) {
      const double angle = so3::angle_between(column(q, n, i), z);
      const double expected = scale * angle * angle;
      expected_best = std::max(expected_best, expected);
      EXPECT_NEAR(out[i], 1.0 + expected, exponent_tolerance(scale, angle))
          << "spread " << spread << ", particle " << i;
    }
    EXPECT_NEAR(best, expected_best, exponent_tolerance(scale, std::sqrt(expected_best / scale)));
  }
}

// The tangent second moment about the mean against so3::log in double, for every kind of block.
TEST(ParticleKernels, TangentSecondMomentIsTheSumOfLogOuterProducts) {
  Random random(8);
  const std::size_t n = 1001;
  const Eigen::Quaterniond mean = so3::exp(Eigen::Vector3d(-0.4, 1.1, 0.3));
  for (const double spread : {0.05, 0.3, 1.0, -1.0}) {
    const std::vector<float> q = cloud_of_spread(n, mean, spread, random);
    std::vector<double> w(n);
    for (double& v : w) v = random.uniform();
    for (const bool weighted : {false, true}) {
      const std::array<double, 6> t = kernels::tangent_second_moment(
          q.data(), n, weighted ? w.data() : nullptr, {-mean.x(), -mean.y(), -mean.z(), mean.w()});
      std::array<double, 6> expected{};
      for (std::size_t i = 0; i < n; ++i) {
        const Eigen::Vector3d d = so3::log(mean.conjugate() * column(q, n, i));
        const double wi = weighted ? w[i] : 1.0;
        const std::array<double, 6> terms{d.x() * d.x(), d.x() * d.y(), d.x() * d.z(),
                                          d.y() * d.y(), d.y() * d.z(), d.z() * d.z()};
        for (std::size_t k = 0; k < 6; ++k) expected[k] += wi * terms[k];
      }
      // Single precision tangent vectors: 1e-6 relative to the largest diagonal term.
      const double tolerance = 1e-6 * std::max({expected[0], expected[3], expected[5]});
      for (std::size_t k = 0; k < 6; ++k)
        EXPECT_NEAR(t[k], expected[k], tolerance)
            << "spread " << spread << ", weighted " << weighted << ", term " << k;
    }
  }
}

TEST(ParticleKernels, TranslationExponentsOverwriteOrAccumulate) {
  const std::size_t n = 9;
  std::vector<double> x(3 * n);
  for (std::size_t i = 0; i < 3 * n; ++i) x[i] = 0.1 * static_cast<double>(i);
  std::vector<double> out(n, 5.0);
  const std::array<double, 3> z{0.2, 1.1, 2.0};
  const double best = kernels::translation_exponents(x.data(), n, z, -2.0, out.data(), false);
  double expected_best = -1e300;
  for (std::size_t i = 0; i < n; ++i) {
    const double d2 =
        std::pow(x[i] - z[0], 2) + std::pow(x[n + i] - z[1], 2) + std::pow(x[2 * n + i] - z[2], 2);
    EXPECT_NEAR(out[i], -2.0 * d2, 1e-14);
    expected_best = std::max(expected_best, -2.0 * d2);
  }
  EXPECT_DOUBLE_EQ(best, expected_best);
  const std::vector<double> first = out;
  kernels::translation_exponents(x.data(), n, z, -2.0, out.data(), true);
  for (std::size_t i = 0; i < n; ++i) EXPECT_NEAR(out[i], 2.0 * first[i], 1e-14);
}

TEST(ParticleKernels, NormalisationAndResamplingWeights) {
  const std::size_t n = 1000;
  std::vector<double> log_w(n), linear(n);
  for (std::size_t i = 0; i < n; ++i) log_w[i] = -1000.0 - 0.01 * static_cast<double>(i);
  std::vector<double> original = log_w;
  std::vector<float> relative(n);
  const kernels::NormalisedWeights fast =
      kernels::resampling_weights(log_w.data(), relative.data(), n);
  const kernels::NormalisedWeights exact =
      kernels::normalise_log_weights(log_w.data(), linear.data(), n);
  ASSERT_TRUE(exact.usable);
  ASSERT_TRUE(fast.usable);
  double sum = 0.0, sum_squares = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const double w = std::exp(original[i] - original[0]);
    sum += w;
    sum_squares += w * w;
    // The exponent is rounded to float first: relative error |x| 2^-24 plus the exp's own.
    const double x = original[i] - original[0];
    EXPECT_NEAR(relative[i], w, (std::abs(x) + 2.0) * 1.2e-7 * w);
  }
  const double ess = sum * sum / (static_cast<double>(n) * sum_squares);
  EXPECT_NEAR(exact.ess_fraction, ess, 1e-14);
  EXPECT_NEAR(fast.ess_fraction, ess, 1e-6);
  for (std::size_t i = 0; i < n; ++i) {
    EXPECT_NEAR(linear[i], std::exp(original[i] - original[0]) / sum, 1e-15);
    EXPECT_NEAR(std::exp(log_w[i]), linear[i], 1e-15);
  }
  log_w.assign(n, -std::numeric_limits<double>::infinity());
  EXPECT_FALSE(kernels::normalise_log_weights(log_w.data(), linear.data(), n).usable);
  EXPECT_FALSE(kernels::resampling_weights(log_w.data(), relative.data(), n).usable);
  log_w.assign(n, 0.0);
  log_w[500] = std::nan("");
  EXPECT_FALSE(kernels::normalise_log_weights(log_w.data(), linear.data(), n).usable);
}

TEST(ParticleKernels, GatherAndLargestIndex) {
  const std::vector<double> in{0, 1, 2, 3, 10, 11, 12, 13};  // two rows of four
  const std::vector<std::size_t> indices{3, 3, 0, 2, 1};
  std::vector<double> out(10);
  kernels::gather_rows(in.data(), 4, 2, indices.data(), indices.size(), out.data());
  EXPECT_EQ(out, (std::vector<double>{3, 3, 0, 2, 1, 13, 13, 10, 12, 11}));
  std::vector<std::size_t> many(1003, 4);
  many[777] = 901;
  EXPECT_EQ(kernels::largest_index(many.data(), many.size()), 901u);
}

TEST(ParticleKernels, MomentSumsMatchDirectSums) {
  Random random(5);
  const std::size_t n = 513;
  std::vector<double> x(3 * n), w(n);
  for (double& v : x) v = 1000.0 + random.normal();  // far from the origin
  for (double& v : w) v = random.uniform();
  const std::array<double, 3> ref{x[0], x[n], x[2 * n]};
  const kernels::TranslationSums s = kernels::translation_sums(x.data(), n, w.data(), ref);
  double sw = 0, sx = 0, sxy = 0;
  for (std::size_t i = 0; i < n; ++i) {
    sw += w[i];
    sx += w[i] * (x[i] - ref[0]);
    sxy += w[i] * (x[i] - ref[0]) * (x[n + i] - ref[1]);
  }
  EXPECT_NEAR(s.weight, sw, 1e-12);
  EXPECT_NEAR(s.first[0], sx, 1e-11);
  EXPECT_NEAR(s.second[1], sxy, 1e-11);

  const Eigen::Quaterniond mean = so3::exp(Eigen::Vector3d(0.2, 0.1, -0.5));
  const std::vector<float> q = quaternion_rows(n, mean, 0.2, random);
  const std::array<double, 10> m = kernels::quaternion_second_moment(q.data(), n, w.data());
  const std::array<double, 6> t = kernels::tangent_second_moment(
      q.data(), n, nullptr, {-mean.x(), -mean.y(), -mean.z(), mean.w()});
  double mxw = 0, tzz = 0, txy = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const Eigen::Quaterniond qi = column(q, n, i);
    mxw += w[i] * qi.x() * qi.w();
    const Eigen::Vector3d d = so3::log(mean.conjugate() * qi);
    tzz += d.z() * d.z();
    txy += d.x() * d.y();
  }
  EXPECT_NEAR(m[3], mxw, 1e-12);
  // Single precision tangent vectors: 1e-6 relative.
  EXPECT_NEAR(t[5], tzz, 1e-6 * tzz);
  EXPECT_NEAR(t[1], txy, 1e-6 * tzz);
}

}  // namespace
}  // namespace opf
