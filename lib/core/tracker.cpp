#include "opf/core/tracker.h"

#include "opf/core/random.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace opf {

Tracker::Tracker(EstimatorFactory factory, std::uint64_t seed, std::size_t threads)
    : factory_(std::move(factory)), seed_(seed), pool_(std::make_unique<WorkerPool>(threads)) {
  if (!factory_) throw std::invalid_argument("Tracker: no estimator factory");
}

const std::vector<Estimate>& Tracker::step(const Frame& frame) {
  if (!refusal_.empty())
    throw std::logic_error("Tracker: stopped at a refused estimate (" + refusal_ +
                           "); a new tracker starts again");
  // A non-finite time would pass every later comparison as false and stop the tracker for good.
  if (!std::isfinite(frame.t)) {
    std::ostringstream msg;
    msg << "Tracker: frame time " << frame.t << " s is not a finite number";
    throw std::invalid_argument(msg.str());
  }
  if (has_stepped_ && !(frame.t > last_t_)) {
    std::ostringstream msg;
    msg << "Tracker: frame time " << frame.t << " s does not follow the previous frame at "
        << last_t_ << " s";
    throw std::invalid_argument(msg.str());
  }
  has_stepped_ = true;
  last_t_ = frame.t;

  remember_radii(frame);
  // Every estimator sees the same, previous-frame picture of the others, whatever the order.
  const std::vector<Estimate> previous = estimates_;
  const EnsembleView view{frame, previous, stated_radii_};
  pool_->for_each(objects_.size(), [&](std::size_t i) {
    const Detection* detection = frame.find(objects_[i]);
    estimates_[i] = estimators_[i]->step(frame.t, detection ? &detection->pose : nullptr, view);
  });
  for (const Detection& detection : frame.detections) {
    if (std::find(objects_.begin(), objects_.end(), detection.object) != objects_.end()) continue;
    const std::uint64_t object_seed = derive_seed(seed_, objects_.size());
    objects_.push_back(detection.object);
    estimators_.push_back(factory_(detection.object, object_seed));
    Estimate first = estimators_.back()->initialise(frame.t, detection.pose);
    first.object = detection.object;
    estimates_.push_back(std::move(first));
  }
  hypotheses_.clear();
  try {
    for (std::size_t i = 0; i < objects_.size(); ++i) {
      estimates_[i].object = objects_[i];
      refuse_non_finite(estimates_[i], estimators_[i]->name());
      for (Estimate& extra : estimators_[i]->extra_hypotheses()) {
        extra.object = objects_[i];
        refuse_non_finite(extra, estimators_[i]->name());
        hypotheses_.push_back(std::move(extra));
      }
    }
  } catch (const std::runtime_error&) {
    // The estimators have stepped into the non-finite state: no later step could be trusted.
    std::ostringstream at;
    at << "t = " << frame.t << " s";
    refusal_ = at.str();
    throw;
  }
  return estimates_;
}

void refuse_non_finite(const Estimate& e, std::string_view estimator) {
  const char* what = nullptr;
  if (!e.pose.mean.m_coords.asEigen().allFinite() ||
      !e.pose.mean.getRotationMatrix().asEigen().allFinite())
    what = "pose";
  else if (!e.pose.cov.asEigen().allFinite())
    what = "covariance";
  else if (!std::isfinite(e.observation_trace))
    what = "trace(Q)";
  else if (!std::isfinite(e.probability))
    what = "probability";
  if (what == nullptr) return;
  std::ostringstream msg;
  msg << estimator << ": the estimate of '" << e.object << "' at t = " << e.t << " s";
  if (e.hypothesis > 0) msg << " (hypothesis " << e.hypothesis << ")";
  msg << " has a " << what << " that is not a finite number; no estimate is written from it, "
      << "and the tracker's state is lost with it. Inputs or settings far beyond any physical "
         "scale cause this: check the estimator's noise settings and the detections";
  throw std::runtime_error(msg.str());
}

void Tracker::remember_radii(const Frame& frame) {
  for (const Detection& d : frame.detections) {
    const bool radius = d.radius > 0.0, box = (d.box.array() > 0.0).all();
    if (!radius && !box) continue;
    auto known = std::find_if(stated_radii_.begin(), stated_radii_.end(),
                              [&](const StatedRadius& r) { return r.object == d.object; });
    if (known == stated_radii_.end()) known = stated_radii_.insert(known, {d.object});
    if (radius) known->radius = d.radius;
    if (box) known->box = d.box;
  }
}

void step_into_rows(Tracker& tracker, const Frame& frame, std::vector<Estimate>& rows) {
  rows = tracker.step(frame);
  rows.insert(rows.end(), tracker.hypotheses().begin(), tracker.hypotheses().end());
  for (Estimate& row : rows) row.recovery.frame_filled = frame.filled;
}

}  // namespace opf
