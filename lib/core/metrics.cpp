#include "opf/core/metrics.h"

#include "opf/core/pose_conversion.h"
#include "opf/core/so3.h"

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace opf {

double translation_error(const mrpt::poses::CPose3D& estimate, const mrpt::poses::CPose3D& truth) {
  return (translation_of(estimate) - translation_of(truth)).norm();
}

double rotation_error_paper(const mrpt::poses::CPose3D& estimate,
                            const mrpt::poses::CPose3D& truth) {
  const auto wrap = [](double a) { return std::remainder(a, 2.0 * std::numbers::pi); };
  const double dy = wrap(estimate.yaw() - truth.yaw());
  const double dp = wrap(estimate.pitch() - truth.pitch());
  const double dr = wrap(estimate.roll() - truth.roll());
  return std::sqrt(dy * dy + dp * dp + dr * dr);
}

double rotation_error_geodesic(const mrpt::poses::CPose3D& estimate,
                               const mrpt::poses::CPose3D& truth) {
  return so3::angle_between(orientation_of(estimate), orientation_of(truth));
}

MeanStd mean_std(std::span<const double> values) {
  if (values.empty()) throw std::invalid_argument("mean_std: no values");
  double sum = 0.0;
  for (double v : values) sum += v;
  const double mean = sum / static_cast<double>(values.size());
  if (values.size() < 2) return {mean, 0.0, values.size()};
  double squares = 0.0;
  for (double v : values) squares += (v - mean) * (v - mean);
  return {mean, std::sqrt(squares / static_cast<double>(values.size() - 1)), values.size()};
}

}  // namespace opf
