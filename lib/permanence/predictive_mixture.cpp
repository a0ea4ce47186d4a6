#include "opf/permanence/predictive_mixture.h"

namespace opf {

double AxisMixture::mean() const {
  double m = 0.0;
  for (const MemberPrediction& c : members) m += c.weight * c.mean;
  return m;
}

double AxisMixture::variance() const {
  const double m = mean();
  double v = 0.0;
  for (const MemberPrediction& c : members) {
    const double d = c.mean - m;
    v += c.weight * (c.variance + d * d);
  }
  return v;
}

}  // namespace opf
