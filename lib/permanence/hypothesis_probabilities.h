#pragma once
// The occluder module's hypotheses and their probabilities (docs/occluder.md, "Carried or left"):
// the prior at onset, the negative information of a hidden frame, which hypothesis is the main
// estimate, which are dropped, and the reveal. Functions of the probabilities alone, so that the
// rules are stated and tested apart from the filters they weigh.

#include <cstddef>
#include <span>
#include <vector>

namespace opf {

/// Carried or left, before any evidence: odds of 2:1 that a cover leaves the object where it was
/// last seen (the carried third shared by the plausible occluders): an object stays put unless the
/// evidence says otherwise.
inline constexpr double kLeftPrior = 2.0 / 3.0;
/// Plausible occluders below 5% carry no hypothesis, and at most four do (the cups game has
/// three).
inline constexpr double kOccluderHypothesisFloor = 0.05;
inline constexpr std::size_t kMaxOccluderHypotheses = 4;
/// The detector's miss probability per frame for an object in clear view.
inline constexpr double kDetectorMissProbability = 0.1;
/// Jeffreys' "substantial" evidence: the odds by which another hypothesis must be more probable
/// than the main one to replace it.
inline constexpr double kSubstantialBayesFactor = 3.1622776601683795;  // 10^(1/2)
/// A hypothesis the evidence has brought below one in a thousand is dropped: three frames with its
/// place seen and empty.
inline constexpr double kNegligibleProbability = 1e-3;

/// p(no detection | the object at a place the camera sees with probability `seen`):
/// 1 - seen (1 - P_miss), the factor on a hypothesis's probability in a hidden frame.
double no_detection_likelihood(double seen);

/// The hypotheses kept, in their new order, from their probabilities (index 0 the main estimate).
/// The main one keeps its place unless the most probable other is at least
/// kSubstantialBayesFactor times as probable (then that one leads); the rest follow most probable
/// first, ties in their order; those below kNegligibleProbability are dropped, the first always
/// kept.
std::vector<std::size_t> hypothesis_order(std::span<const double> probabilities);

/// The reveal: the hypothesis with the largest probability times evidence for the measurement
/// (`log_evidence`: ln p(z | h) per hypothesis), the first of a tie. Needs one or more.
std::size_t most_probable_given(std::span<const double> probabilities,
                                std::span<const double> log_evidence);

}  // namespace opf
