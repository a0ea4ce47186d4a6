#pragma once
// The feedback module's threshold (paper Sec. III-C.1, Eq. 15): the alert is raised when the
// uncertainty U = trace(Q~) reaches it (safety_alert, core/estimate.h).

#include "opf/core/option_schema.h"

namespace opf {

struct FeedbackOptions {
  /// epsilon_safe is free in the paper. Default: about 13x trace(Q) of the default observation
  /// noise (3 * 0.01^2 + 3 * 0.05^2 = 0.0078), i.e. alert after Q~ grew by an order of magnitude.
  double epsilon_safe = 0.1;
};

/// The settings file's `opf.feedback:` section (core/option_schema.h).
template <class Visitor>
void describe_options(Visitor& v, FeedbackOptions& o) {
  v.number("epsilon_safe", o.epsilon_safe, positive());
}

}  // namespace opf
