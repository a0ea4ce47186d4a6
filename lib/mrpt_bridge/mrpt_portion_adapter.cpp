#include "opf/mrpt_bridge/mrpt_portion_adapter.h"

#include "opf/core/pose_conversion.h"

#include <mrpt/obs/CObservationRobotPose.h>
#include <mrpt/obs/CSensoryFrame.h>

#include <cmath>

namespace opf {

MrptPortionAdapter::MrptPortionAdapter(PoseParticleFilter& filter, PortionKind portion)
    : filter_(filter), portion_(portion) {}

LogWeights& MrptPortionAdapter::weights() {
  return portion_ == PortionKind::kTranslation ? filter_.translation().weights
                                               : filter_.rotation().weights;
}

const LogWeights& MrptPortionAdapter::weights() const {
  return portion_ == PortionKind::kTranslation ? filter_.translation().weights
                                               : filter_.rotation().weights;
}

double MrptPortionAdapter::getW(std::size_t i) const {
  return weights().log()[Eigen::Index(i)];
}

void MrptPortionAdapter::setW(std::size_t i, double log_w) {
  weights().log()[Eigen::Index(i)] = log_w;
}

std::size_t MrptPortionAdapter::particlesCount() const {
  return weights().size();
}

double MrptPortionAdapter::normalizeWeights(double* out_max_log_w) {
  Eigen::VectorXd& log_w = weights().log();
  const double max_log_w = log_w.maxCoeff();
  const double min_log_w = log_w.minCoeff();
  log_w.array() -= max_log_w;
  if (out_max_log_w) *out_max_log_w = max_log_w;
  return std::exp(max_log_w - min_log_w);
}

double MrptPortionAdapter::ESS() const {
  return weights().effective_sample_fraction();
}

void MrptPortionAdapter::performSubstitution(const std::vector<std::size_t>& indices) {
  if (portion_ == PortionKind::kTranslation)
    filter_.translation().resample(indices);
  else
    filter_.rotation().resample(indices);
  weights().log().setZero();  // uniform, in MRPT's max-is-zero convention
}

void MrptPortionAdapter::prediction_and_update_pfStandardProposal(
    const mrpt::obs::CActionCollection* /*action*/, const mrpt::obs::CSensoryFrame* observation,
    const mrpt::bayes::CParticleFilter::TParticleFilterOptions& /*options*/) {
  if (portion_ == PortionKind::kTranslation)
    filter_.predict_translation(dt_);
  else
    filter_.predict_rotation(dt_);
  if (!observation) return;
  const auto measurement = observation->getObservationByClass<mrpt::obs::CObservationRobotPose>();
  if (!measurement) return;
  if (portion_ == PortionKind::kTranslation)
    filter_.reweight_translation(translation_of(measurement->pose.mean));
  else
    filter_.reweight_rotation(orientation_of(measurement->pose.mean));
}

}  // namespace opf
