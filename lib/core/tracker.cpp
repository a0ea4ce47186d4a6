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
  for (std::size_t i = 0; i < objects_.size(); ++i) {
    estimates_[i].object = objects_[i];
    for (Estimate& extra : estimators_[i]->extra_hypotheses()) {
      extra.object = objects_[i];
      hypotheses_.push_back(std::move(extra));
    }
  }
  return estimates_;
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

}  // namespace opf
