#include "opf/mrpt_bridge/mrpt_portion_adapter.h"

#include "opf/core/pose_conversion.h"
#include "opf/core/so3.h"
#include "opf/particles/pose_particle_filter.h"

#include <mrpt/bayes/CParticleFilter.h>
#include <mrpt/obs/CObservationRobotPose.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/random/RandomGenerators.h>

#include <gtest/gtest.h>

namespace opf {
namespace {

using mrpt::bayes::CParticleFilter;
using mrpt::bayes::CParticleFilterCapable;

struct Measurement {
  Eigen::Vector3d position;
  Eigen::Quaterniond orientation;
  bool observed;
};

// A moving object observed with noise, unobserved for frames 20..29.
std::vector<Measurement> measurement_stream() {
  Random noise(77);
  std::vector<Measurement> stream;
  for (int k = 0; k < 60; ++k) {
    const double t = k / 30.0;
    const Eigen::Vector3d p(0.4 + 0.1 * t + 0.005 * noise.normal(), 0.2 * t, 0.03);
    const Eigen::Quaterniond q = so3::exp(Eigen::Vector3d(0, 0, 0.5 * t + 0.02 * noise.normal()));
    stream.push_back({p, q, k < 20 || k >= 30});
  }
  return stream;
}

PoseParticleFilterOptions options() {
  PoseParticleFilterOptions o;
  o.translation_particles = 300;
  o.rotation_particles = 200;
  o.resampling.every_frame = false;  // MRPT resamples when ESS < BETA: exercise both branches
  o.resampling.ess_threshold = 0.5;
  return o;
}

// MRPT's CParticleFilter::executeOn drives our filter, one portion per call, to exactly the same
// particles and estimates as our own step loop using MRPT's resampler with the same seed. Without
// the weight reset in performSubstitution (MRPT 2.5 never resets the weights when executeOn
// resamples) the stale log-weights would survive resampling and the two runs would diverge.
TEST(MrptPortionAdapter, ExecuteOnMatchesOurOwnLoop) {
  const auto stream = measurement_stream();
  constexpr std::uint64_t kSeed = 5;
  constexpr double kDt = 1.0 / 30.0;
  constexpr unsigned kMrptSeed = 1234;

  // Run A: our own loop, resampling indices from MRPT's resampler.
  PoseParticleFilter ours(options(), kSeed);
  ours.initialise(stream[0].position, stream[0].orientation);
  mrpt::random::getRandomGenerator().randomize(kMrptSeed);
  int resamplings = 0;
  auto own_portion_step = [&](auto& portion, auto&& predict, auto&& reweight, bool observed) {
    predict();
    if (observed) reweight();
    portion.weights.normalise();
    if (portion.weights.effective_sample_fraction() < 0.5) {
      std::vector<std::size_t> indices;
      CParticleFilterCapable::computeResampling(
          CParticleFilter::prSystematic,
          std::vector<double>(portion.weights.log().begin(), portion.weights.log().end()), indices);
      portion.resample(indices);
      ++resamplings;
    }
  };
  for (std::size_t k = 1; k < stream.size(); ++k) {
    const auto& m = stream[k];
    own_portion_step(
        ours.translation(), [&] { ours.predict_translation(kDt); },
        [&] { ours.reweight_translation(m.position); }, m.observed);
    own_portion_step(
        ours.rotation(), [&] { ours.predict_rotation(kDt); },
        [&] { ours.reweight_rotation(m.orientation); }, m.observed);
  }
  ASSERT_GT(resamplings, 5);  // the comparison must cover resampling

  // Run B: MRPT's executeOn.
  PoseParticleFilter driven(options(), kSeed);
  driven.initialise(stream[0].position, stream[0].orientation);
  mrpt::random::getRandomGenerator().randomize(kMrptSeed);
  CParticleFilter pf;
  pf.m_options.PF_algorithm = CParticleFilter::pfStandardProposal;
  pf.m_options.resamplingMethod = CParticleFilter::prSystematic;
  pf.m_options.BETA = 0.5;
  MrptPortionAdapter translation(driven, PortionKind::kTranslation);
  MrptPortionAdapter rotation(driven, PortionKind::kRotation);
  for (std::size_t k = 1; k < stream.size(); ++k) {
    const auto& m = stream[k];
    mrpt::obs::CSensoryFrame frame;
    if (m.observed) {
      auto observation = mrpt::obs::CObservationRobotPose::Create();
      observation->pose = mrpt::poses::CPose3DPDFGaussian(make_pose(m.position, m.orientation));
      frame.insert(observation);
    }
    translation.set_time_step(kDt);
    rotation.set_time_step(kDt);
    pf.executeOn(translation, nullptr, &frame);
    pf.executeOn(rotation, nullptr, &frame);
  }

  EXPECT_EQ(ours.translation().states, driven.translation().states);
  EXPECT_EQ(ours.rotation().states, driven.rotation().states);
  const auto a = ours.translation_moments(), b = driven.translation_moments();
  EXPECT_LT((a.mean - b.mean).norm(), 1e-12);
  const auto ra = ours.rotation_moments(), rb = driven.rotation_moments();
  EXPECT_LT(so3::angle_between(ra.mean, rb.mean), 1e-12);
}

TEST(MrptPortionAdapter, PerformSubstitutionResetsWeights) {
  PoseParticleFilter filter(options(), 1);
  filter.initialise(Eigen::Vector3d::Zero(), Eigen::Quaterniond::Identity());
  MrptPortionAdapter adapter(filter, PortionKind::kTranslation);
  for (std::size_t i = 0; i < adapter.particlesCount(); ++i) adapter.setW(i, -double(i));
  std::vector<std::size_t> indices(adapter.particlesCount(), 0);
  adapter.performSubstitution(indices);
  for (std::size_t i = 0; i < adapter.particlesCount(); ++i) EXPECT_EQ(adapter.getW(i), 0.0);
  EXPECT_DOUBLE_EQ(adapter.ESS(), 1.0);
}

}  // namespace
}  // namespace opf
