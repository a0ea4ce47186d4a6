#pragma once
// The feedback module's human-intervention signal (paper Sec. III-C.1, Eq. 15): the uncertainty
// U = trace(Q~) and the alert raised when it reaches the safety threshold.

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

/// U >= epsilon_safe: the robot should stop, fall back to a safe mode or alert the operator.
inline bool safety_alert(double uncertainty, const FeedbackOptions& options) {
  return uncertainty >= options.epsilon_safe;
}

}  // namespace opf
