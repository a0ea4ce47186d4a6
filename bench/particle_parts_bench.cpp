// Each part of a particle filter step on its own, at N particles per portion (the paper: 5000),
// so a change to one kernel shows where the step's time goes: Gaussian sampling, the random-walk
// prediction of each portion, the likelihood of each portion, normalisation with the ESS, each
// resampler, the moments (mean and covariance; Markley's mean for rotation) and the occluder
// module's Bhattacharyya search over K candidates. Particles per second count one portion.

#include "opf/core/random.h"
#include "opf/core/so3.h"
#include "opf/particles/gaussian_likelihood.h"
#include "opf/particles/gaussian_sampler.h"
#include "opf/particles/particle_statistics.h"
#include "opf/particles/random_walk_model.h"
#include "opf/particles/resampling.h"
#include "opf/permanence/occluder_selection.h"

#include <benchmark/benchmark.h>

#include <string>
#include <vector>

namespace opf {
namespace {

constexpr double kStepSigmaTranslation = 0.05 * 0.18257418583505536;  // 0.05 m/sqrt(s), 30 Hz
constexpr double kStepSigmaRotation = 0.1 * 0.18257418583505536;

std::size_t count_of(const benchmark::State& state) {
  return static_cast<std::size_t>(state.range(0));
}

void per_particle(benchmark::State& state) {
  state.SetItemsProcessed(state.iterations() * state.range(0));
}

TranslationParticles translation_cloud(std::size_t n, GaussianSampler& noise) {
  TranslationParticles particles;
  particles.resize(n);
  scatter_around(particles, Eigen::Vector3d(0.4, 0.1, 0.05), 0.01, noise);
  return particles;
}

RotationParticles rotation_cloud(std::size_t n, GaussianSampler& noise) {
  RotationParticles particles;
  particles.resize(n);
  scatter_around(particles, so3::exp(Eigen::Vector3d(0.1, -0.3, 0.7)), 0.05, noise);
  return particles;
}

// Weights of a typical update: the likelihood of a measurement 1 sigma from the cloud's centre.
template <int Dim>
Eigen::VectorXd typical_weights(ParticlePortion<Dim> particles) {
  if constexpr (Dim == 3)
    reweight_gaussian(particles, Eigen::Vector3d(0.41, 0.1, 0.05), 1e-4);
  else
    reweight_gaussian(particles, so3::exp(Eigen::Vector3d(0.15, -0.3, 0.7)), 0.0025);
  particles.weights.normalise();
  return particles.weights.linear();
}

void BM_GaussianSampling(benchmark::State& state) {
  GaussianSampler sampler(1);
  std::vector<float> out(3 * count_of(state));  // three per particle
  for (auto _ : state) {
    sampler.fill(out);
    benchmark::DoNotOptimize(out.data());
  }
  per_particle(state);
}

void BM_PredictTranslation(benchmark::State& state) {
  GaussianSampler noise(1);
  TranslationParticles particles = translation_cloud(count_of(state), noise);
  for (auto _ : state) predict_random_walk(particles, kStepSigmaTranslation, noise);
  per_particle(state);
}

void BM_PredictRotation(benchmark::State& state) {
  GaussianSampler noise(1);
  RotationParticles particles = rotation_cloud(count_of(state), noise);
  for (auto _ : state) predict_random_walk(particles, kStepSigmaRotation, noise);
  per_particle(state);
}

void BM_LikelihoodTranslation(benchmark::State& state) {
  GaussianSampler noise(1);
  const TranslationParticles particles = translation_cloud(count_of(state), noise);
  Eigen::VectorXd exponents;
  for (auto _ : state)
    benchmark::DoNotOptimize(
        gaussian_exponents(particles, Eigen::Vector3d(0.41, 0.1, 0.05), 1e-4, exponents));
  per_particle(state);
}

void BM_LikelihoodRotation(benchmark::State& state) {
  GaussianSampler noise(1);
  const RotationParticles particles = rotation_cloud(count_of(state), noise);
  const Eigen::Quaterniond z = so3::exp(Eigen::Vector3d(0.15, -0.3, 0.7));
  Eigen::VectorXd exponents;
  for (auto _ : state)
    benchmark::DoNotOptimize(gaussian_exponents(particles, z, 0.0025, exponents));
  per_particle(state);
}

void BM_NormaliseWithEss(benchmark::State& state) {
  GaussianSampler noise(1);
  TranslationParticles particles = translation_cloud(count_of(state), noise);
  Eigen::VectorXd exponents, linear;
  gaussian_exponents(particles, Eigen::Vector3d(0.41, 0.1, 0.05), 1e-4, exponents);
  for (auto _ : state) {
    particles.weights.log() = exponents;  // unnormalised again each time
    benchmark::DoNotOptimize(particles.weights.normalise(linear));
  }
  per_particle(state);
}

void BM_Resample(benchmark::State& state) {
  const auto scheme = static_cast<ResamplingScheme>(state.range(1));
  GaussianSampler noise(1);
  const Eigen::VectorXd w = typical_weights(translation_cloud(count_of(state), noise));
  Random random(2);
  for (auto _ : state)
    benchmark::DoNotOptimize(resample_indices(w, count_of(state), scheme, random));
  per_particle(state);
  static const char* const kNames[] = {"multinomial", "residual", "stratified", "systematic"};
  state.SetLabel(kNames[state.range(1)]);
}

// Index selection and the copy of the rotation portion's states (4 rows): a whole resampling.
void BM_ResampleRotationPortion(benchmark::State& state) {
  GaussianSampler noise(1);
  RotationParticles particles = rotation_cloud(count_of(state), noise);
  const Eigen::VectorXd w = typical_weights(particles);
  Random random(2);
  for (auto _ : state)
    particles.resample(
        resample_indices(w, particles.size(), mrpt::bayes::CParticleFilter::prSystematic, random));
  per_particle(state);
}

// What a filter step runs when it resamples every frame by the systematic scheme (the paper's
// default): single-precision relative weights in, one pass of end marks and the copy of the
// portion's rows (the AVX-512 permute gather where the CPU has it). Portion 3: translation
// (3 rows of double), 4: rotation (4 rows of float).
template <int Dim>
void BM_SystematicResamplePortion(benchmark::State& state) {
  GaussianSampler noise(1);
  ParticlePortion<Dim> particles;
  if constexpr (Dim == 3)
    particles = translation_cloud(count_of(state), noise);
  else
    particles = rotation_cloud(count_of(state), noise);
  const Eigen::VectorXd w = typical_weights(particles);
  const std::vector<float> relative(w.data(), w.data() + w.size());
  Random random(2);
  for (auto _ : state) particles.resample_systematic(relative, random.uniform());
  per_particle(state);
}

void BM_TranslationMoments(benchmark::State& state) {
  GaussianSampler noise(1);
  TranslationParticles particles = translation_cloud(count_of(state), noise);
  if (state.range(1)) particles.weights.log() = typical_weights(particles).array().log();
  for (auto _ : state) benchmark::DoNotOptimize(translation_moments(particles));
  per_particle(state);
}

// Markley's mean (M = sum w q q^T and its 4x4 eigen-solve) and the tangent covariance.
void BM_RotationMoments(benchmark::State& state) {
  GaussianSampler noise(1);
  RotationParticles particles = rotation_cloud(count_of(state), noise);
  if (state.range(1)) particles.weights.log() = typical_weights(particles).array().log();
  for (auto _ : state) benchmark::DoNotOptimize(rotation_moments(particles));
  per_particle(state);
}

// Algorithm 1's search: D_B from the hidden object's cloud to each of K other objects' clouds
// in the line-of-sight plane.
void BM_OccluderSearch(benchmark::State& state) {
  const auto k = static_cast<std::size_t>(state.range(0));
  Random random(3);
  std::vector<OccluderCandidate> candidates;
  for (std::size_t i = 0; i < k; ++i) {
    const Eigen::Vector3d mean(random.uniform(), random.uniform(), 0.05 * random.uniform());
    const Eigen::Matrix3d covariance =
        (1e-4 * (1.0 + random.uniform())) * Eigen::Matrix3d::Identity();
    candidates.push_back({"object" + std::to_string(i), mean, covariance});
  }
  OccluderOptions options;
  options.camera_position = Eigen::Vector4d(0.5, -0.5, 1.0, 1.0);
  const Eigen::Vector3d hidden(0.5, 0.5, 0.02);
  const Eigen::Matrix3d hidden_covariance = 1e-4 * Eigen::Matrix3d::Identity();
  for (auto _ : state)
    benchmark::DoNotOptimize(choose_occluders(hidden, hidden_covariance, candidates, options));
  state.SetItemsProcessed(state.iterations() * state.range(0));
}

void particle_counts(benchmark::internal::Benchmark* b) {
  b->RangeMultiplier(10)->Range(100, 100000)->Arg(5000)->Unit(benchmark::kMicrosecond);
}

BENCHMARK(BM_GaussianSampling)->Apply(particle_counts);
BENCHMARK(BM_PredictTranslation)->Apply(particle_counts);
BENCHMARK(BM_PredictRotation)->Apply(particle_counts);
BENCHMARK(BM_LikelihoodTranslation)->Apply(particle_counts);
BENCHMARK(BM_LikelihoodRotation)->Apply(particle_counts);
BENCHMARK(BM_NormaliseWithEss)->Apply(particle_counts);
BENCHMARK(BM_Resample)
    ->ArgNames({"n", "scheme"})
    ->ArgsProduct(
        {{5000},
         {mrpt::bayes::CParticleFilter::prMultinomial, mrpt::bayes::CParticleFilter::prResidual,
          mrpt::bayes::CParticleFilter::prStratified, mrpt::bayes::CParticleFilter::prSystematic}})
    ->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_ResampleRotationPortion)->Apply(particle_counts);
BENCHMARK(BM_SystematicResamplePortion<3>)
    ->Name("BM_SystematicResampleTranslation")
    ->Apply(particle_counts);
BENCHMARK(BM_SystematicResamplePortion<4>)
    ->Name("BM_SystematicResampleRotation")
    ->Apply(particle_counts);
BENCHMARK(BM_TranslationMoments)
    ->ArgNames({"n", "weighted"})
    ->ArgsProduct({{5000}, {0, 1}})
    ->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_RotationMoments)
    ->ArgNames({"n", "weighted"})
    ->ArgsProduct({{5000}, {0, 1}})
    ->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_OccluderSearch)->RangeMultiplier(2)->Range(1, 128)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace opf
