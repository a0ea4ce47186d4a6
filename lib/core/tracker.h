#pragma once
// The Tracker: one estimator per object, created at the object's first detection, stepped frame by
// frame. Objects are kept in order of first appearance, which makes runs deterministic. The
// estimators of one frame run in parallel over a worker pool: each sees only the previous frame's
// estimates of the others, so the results are the same for any number of threads.

#include "opf/core/estimate.h"
#include "opf/core/estimator.h"
#include "opf/core/frame.h"
#include "opf/core/worker_pool.h"

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace opf {

/// Builds the estimator of one object. `seed` is derived per object from the tracker's seed.
using EstimatorFactory =
    std::function<std::unique_ptr<Estimator>(const std::string& object, std::uint64_t seed)>;

/// Throws std::runtime_error naming `estimator`, the object, its time and the field, if the
/// estimate's pose, covariance, trace or probability is not finite: a NaN written to a result
/// file would pass for an estimate. The estimator has stepped by then: its tracker cannot go on.
void refuse_non_finite(const Estimate& estimate, std::string_view estimator);

class Tracker {
 public:
  /// `threads` >= 1 threads step the objects of a frame (1: all on the caller's thread).
  Tracker(EstimatorFactory factory, std::uint64_t seed, std::size_t threads = 1);

  /// Steps every known object through `frame` (timestamps finite and increasing, else
  /// std::invalid_argument and nothing changes) and returns one estimate per object seen so far,
  /// in order of first appearance. An estimate that is not finite is refused (refuse_non_finite),
  /// and every later step throws std::logic_error: the estimators have stepped into that state.
  const std::vector<Estimate>& step(const Frame& frame);

  const std::vector<Estimate>& estimates() const { return estimates_; }
  /// The further hypotheses (hypothesis >= 1) the estimators held after the last step, in object
  /// order. They are not shown to the other estimators: a hypothesis is not an object.
  const std::vector<Estimate>& hypotheses() const { return hypotheses_; }

 private:
  /// Keeps the sizes the frame's detections state (stated_radii_).
  void remember_radii(const Frame& frame);

  EstimatorFactory factory_;
  std::uint64_t seed_;
  std::vector<std::string> objects_;
  std::vector<std::unique_ptr<Estimator>> estimators_;
  std::vector<Estimate> estimates_;
  std::vector<Estimate> hypotheses_;
  std::vector<StatedRadius> stated_radii_;  ///< each object's last stated size
  bool has_stepped_ = false;
  std::string refusal_;  ///< where an estimate was refused as not finite; empty while none was
  double last_t_ = 0.0;
  std::unique_ptr<WorkerPool> pool_;
};

/// Steps `tracker` through `frame` and gives the frame's rows as an estimate file lists them:
/// every object's main estimate, then the further hypotheses, each marked when the frame was
/// filled inside a gap. `rows` is cleared and refilled (its capacity kept from frame to frame).
void step_into_rows(Tracker& tracker, const Frame& frame, std::vector<Estimate>& rows);

}  // namespace opf
