#include "opf/estimators/object_permanence_filter.h"

#include "opf/core/pose_conversion.h"
#include "opf/core/random.h"
#include "opf/core/so3.h"
#include "opf/permanence/motion_classifier.h"
#include "opf/permanence/occluder_selection.h"
#include "opf/permanence/second_difference_noise.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace opf {
namespace {

const Estimate* find_estimate(const EnsembleView& ensemble, const std::string& object) {
  for (const Estimate& e : ensemble.previous_estimates)
    if (e.object == object) return &e;
  return nullptr;
}

Eigen::Matrix3d translation_covariance(const Estimate& estimate) {
  return estimate.pose.cov.asEigen().topLeftCorner<3, 3>();
}

}  // namespace

void validate(const OpfOptions& options) {
  validate(options.particles);
  check_options(options, "OPF");
  if (options.occluder.plane == OccluderPlane::kLineOfSight && !options.occluder.camera_position)
    throw std::invalid_argument(
        "OPF option occluder.plane is line_of_sight but no camera position is given "
        "(opf.occluder.camera_position, or --camera X,Y,Z); plane auto takes a top-down camera");
}

ObjectPermanenceFilter::ObjectPermanenceFilter(const OpfOptions& options, std::string object,
                                               std::uint64_t seed)
    : options_(options),
      object_(std::move(object)),
      seed_(seed),
      detector_jitter_(options.dynamics.selection.history_window) {
  validate(options_);
}

Estimate ObjectPermanenceFilter::initialise(double t, const mrpt::poses::CPose3D& first) {
  hypotheses_.clear();
  hypotheses_.emplace_back(PoseParticleFilter(options_.particles, seed_),
                           CovarianceInflation(options_.uncertainty));
  hypotheses_[0].filter.initialise(translation_of(first), orientation_of(first));
  history_.clear();
  detector_jitter_.clear();
  displacement_spread_.clear();
  confirmed_motion_.reset();
  t_ = t;
  hidden_ = false;
  initialised_ = true;
  const Estimate estimate = make_estimate(hypotheses_[0], 0);
  remember(t, translation_of(first), orientation_of(first), estimate);
  return estimate;
}

void ObjectPermanenceFilter::remember(double t, const Eigen::Vector3d& position,
                                      const Eigen::Quaterniond& orientation,
                                      const Estimate& estimate) {
  detector_jitter_.add(t, position, orientation);
  displacement_spread_.add(t, position);
  history_.push_back({t, position, orientation, translation_of(estimate.pose.mean),
                      orientation_of(estimate.pose.mean)});
  if (options_.dynamics.predictor == DynamicsPredictor::kPaper) {
    while (history_.size() > options_.history_length) history_.pop_front();
  } else {
    const double window =
        std::max(options_.dynamics.selection.history_window, options_.velocity_window);
    while (history_.size() > 2 && t - history_.front().t > window) history_.pop_front();
  }
}

void ObjectPermanenceFilter::predict_with_recent_velocity(Hypothesis& h, double dt) {
  const auto velocity = recent_velocity(history_, options_.velocity_window);
  if (!velocity) {
    h.filter.predict(dt);
    return;
  }
  // The body-frame angular velocity turns the estimate's orientation; as a world rotation it
  // turns every particle about the same axis (they lie within a few degrees of the estimate).
  const Eigen::Quaterniond q = history_.back().estimated_orientation.normalized();
  const Eigen::Quaterniond turn = q * so3::exp(velocity->angular * dt) * q.conjugate();
  h.filter.predict(dt, velocity->linear * dt, turn.normalized());
}

// The detector's jitter is never taken wider than configured (a moving object's differences
// hold some of its motion, so the estimate is an upper bound), nor narrower than a tenth of it:
// 5000 particles diffused by the random walk cannot resolve a likelihood much narrower than their
// step.
constexpr double kJitterFloorShare = 0.1;

void ObjectPermanenceFilter::adapt_rotation_noise(Hypothesis& h) {
  const auto sigma = detector_jitter_.rotation_sigma();
  if (!sigma) return;
  const double configured = options_.particles.observation_noise_rotation;
  h.filter.set_rotation_likelihood_noise(
      std::clamp(*sigma, kJitterFloorShare * configured, configured));
}

void ObjectPermanenceFilter::adapt_translation_noise(Hypothesis& h) {
  const auto sigmas = detector_jitter_.translation_sigmas();
  if (!sigmas) return;
  const double configured = options_.particles.observation_noise_translation;
  h.filter.set_translation_likelihood_noise(
      sigmas->cwiseMax(kJitterFloorShare * configured).cwiseMin(configured));
}

Estimate ObjectPermanenceFilter::step(double t, const mrpt::poses::CPose3D* measurement,
                                      const EnsembleView& ensemble) {
  if (!initialised_) throw std::logic_error("ObjectPermanenceFilter::step before initialise");
  const double dt = t - t_;
  if (!(dt > 0.0)) {
    std::ostringstream msg;
    msg << "ObjectPermanenceFilter: time " << t << " s does not follow " << t_ << " s";
    throw std::invalid_argument(msg.str());
  }
  const double last_seen = t_;
  t_ = t;

  if (measurement) {
    // The object was seen in the previous frame too: its recent velocity carries the particles.
    const bool drifts = options_.velocity_drift && !hidden_;
    for (std::size_t i = 0; i < hypotheses_.size(); ++i) {
      if (i == 0 && drifts)
        predict_with_recent_velocity(hypotheses_[0], dt);
      else
        hypotheses_[i].filter.predict(dt);
    }
    const Eigen::Vector3d position = translation_of(*measurement);
    const Eigen::Quaterniond orientation = orientation_of(*measurement);
    keep_hypothesis_explaining(position);
    Hypothesis& h = hypotheses_[0];
    const Source hidden_by = h.source;
    if (options_.adaptive_rotation_noise) adapt_rotation_noise(h);
    if (options_.adaptive_translation_noise) adapt_translation_noise(h);
    const bool lost = h.filter.update_with_measurement(
        position, orientation, hidden_ ? options_.reacquisition_gaussian_share : 0.0);
    if (h.filter.translation_was_reset())
      confirmed_motion_.reset();
    else if (h.prediction) {
      confirmed_motion_ = std::move(h.prediction);
      reappeared_at_ = t;
      reappeared_where_ = position;
    }
    const ResampleReport report = h.filter.normalise_and_resample();
    h.recovery = {.sensor_reset = lost, .weights_underflow = report.weights_underflow()};
    h.inflation.reset();
    h.source = Source::kMeasurement;
    h.trajectory.reset();
    h.prediction.reset();
    h.prediction_trace = 0.0;
    h.occluder.clear();
    h.last_carrier_position.reset();
    h.carrier_track.clear();
    // The history restarts when the object turns up somewhere its history does not lead: after a
    // long occlusion in which it was carried by an occluder or only predicted (revealed in a new
    // place), or whenever the measurement was far outside the cloud (a translation reset). An
    // object the dynamics module carried through the gap keeps its history: its motion is still
    // that one, and a brief, partly covered glimpse is no better basis for the next fit. A reset of
    // the rotation portion alone (the orientation of a half-covered object read wrong) says nothing
    // against where the object was going.
    if (h.filter.translation_was_reset() || (hidden_ && hidden_by != Source::kTrajectory &&
                                             t - hidden_since_ > options_.history_reset_gap))
      history_.clear();
    hidden_ = false;
    // The history sample holds the estimate itself: its moments are computed once per step.
    const Estimate estimate = make_estimate(h, 0);
    remember(t, position, orientation, estimate);
    return estimate;
  }

  if (!hidden_) {
    hidden_ = true;
    hidden_since_ = last_seen;
    start_occlusion(last_seen, ensemble);
  }
  for (Hypothesis& h : hypotheses_) {
    if (h.prediction) {
      follow_prediction(h, last_seen, t);
      continue;
    }
    h.filter.predict(dt);
    const auto virtual_z = virtual_measurement(h, t, ensemble);
    if (virtual_z && options_.carry_particles) {
      // Carried at an offset, the object turns about its carrier; otherwise it moves with it.
      if (h.source == Source::kOccluder && h.at_offset)
        h.filter.carry(virtual_z->carrier_from, virtual_z->carrier_to, virtual_z->carrier_rotation);
      else
        h.filter.shift(virtual_z->carrier_to - virtual_z->carrier_from,
                       virtual_z->carrier_rotation);
    }
    // Without the uncertainty module Q~ stays Q; with it Q~ grows every hidden step, also when no
    // module supplies a virtual measurement, so the feedback module still sees the time hidden.
    if (options_.modules.uncertainty) h.inflation.step(virtual_z ? virtual_z->speed : 0.0, dt);
    if (virtual_z)
      h.filter.reweight(virtual_z->position, virtual_z->orientation, h.inflation.scale());
    const ResampleReport report = h.filter.normalise_and_resample();
    h.recovery = {.weights_underflow = report.weights_underflow(),
                  .trace_capped = h.inflation.capped()};
  }
  return make_estimate(hypotheses_[0], 0);
}

void ObjectPermanenceFilter::start_occlusion(double last_seen, const EnsembleView& ensemble) {
  // A hypothesis per occluder exists only while hidden; at onset there is one.
  hypotheses_.erase(hypotheses_.begin() + 1, hypotheses_.end());
  Hypothesis& h = hypotheses_[0];
  h.source = Source::kNone;

  if (options_.modules.dynamics && options_.dynamics.predictor == DynamicsPredictor::kSelected &&
      start_dynamics(h))
    return;
  const std::vector<TrajectorySample> window = estimate_history();
  const int needed =
      std::max(options_.trajectory.translation_order, options_.trajectory.rotation_order) + 1;
  if (options_.modules.dynamics && options_.dynamics.predictor == DynamicsPredictor::kPaper &&
      static_cast<int>(window.size()) >= std::max(needed, 2)) {
    const bool pairwise = options_.motion.test == MotionTest::kMaxPairwise;
    if (!pairwise || classify_motion(window, options_.motion) == Motion::kMoving) {
      try {
        TrajectoryModel model = fit_trajectory(window, options_.trajectory);
        if (pairwise || classify_fitted_motion(model, window.front().t, window.back().t,
                                               options_.motion) == Motion::kMoving) {
          h.trajectory = std::move(model);
          h.source = Source::kTrajectory;
          h.last_carrier_position = h.trajectory->position(last_seen);
          h.last_carrier_orientation = h.trajectory->orientation(last_seen);
          return;
        }
      } catch (const std::exception&) {
        // A degenerate window cannot be fitted: treat the object as static and let the occluder
        // module try.
      }
    }
  }
  if (!options_.modules.occluder) return;

  std::vector<OccluderCandidate> candidates;
  std::vector<const Estimate*> candidate_estimates;
  for (const Estimate& e : ensemble.previous_estimates) {
    if (e.object == object_) continue;
    candidates.push_back({e.object, translation_of(e.pose.mean), translation_covariance(e)});
    candidate_estimates.push_back(&e);
  }
  const TranslationMoments own = h.filter.translation_moments();
  const OccluderChoice choice =
      choose_occluders(own.mean, own.covariance, candidates, options_.occluder);
  if (!choice.nearest) return;

  h.position_at_onset = own.mean;
  h.orientation_at_onset = h.filter.rotation_moments().mean;
  if (choice.second) {
    Hypothesis twin = h;  // O_i': a copy of the filter that follows the second occluder
    twin.filter.reseed(derive_seed(seed_, ++spawned_));
    follow_occluder(twin, candidates[*choice.second].object, *candidate_estimates[*choice.second],
                    ensemble);
    follow_occluder(h, candidates[*choice.nearest].object, *candidate_estimates[*choice.nearest],
                    ensemble);
    hypotheses_.push_back(std::move(twin));
  } else {
    follow_occluder(h, candidates[*choice.nearest].object, *candidate_estimates[*choice.nearest],
                    ensemble);
  }
}

std::vector<TrajectorySample> ObjectPermanenceFilter::estimate_history() const {
  std::vector<TrajectorySample> window;
  window.reserve(history_.size());
  for (const MotionSample& sample : history_)
    window.push_back({sample.t, sample.estimated_position, sample.estimated_orientation});
  return window;
}

namespace {

// Sets the translation particles' spread about their mean, per world axis, to `scale` times what
// the history shows of the estimate's error where the cloud is wider: the mean squared distance
// between the estimates and the measurements, plus the detector's noise read from the
// measurements (second_difference_noise.h). With e the estimate's error and n the noise,
// E[e^2] = E[(e - n)^2] - sigma^2 + 2 E[e n] <= E[(e - n)^2] + sigma^2 whenever the estimate does
// not amplify the noise (E[e n] <= sigma^2): a bound however closely it follows the measurements.
// With `widen`, also where the cloud is narrower and the detector noisier than the configured
// observation noise (a walker's depth read from her size): the cloud, the posterior under that
// noise, then claims more than any detection of the object when it reappears can show. Where the
// detector is finer than configured, the cloud is already cautious and stays as it is.
void spread_to_measured_discrepancy(PoseParticleFilter& filter,
                                    std::span<const MotionSample> history, double scale,
                                    bool widen) {
  if (history.size() < 3) return;
  Eigen::Matrix3Xd measured(3, static_cast<Eigen::Index>(history.size()));
  Eigen::Vector3d squares = Eigen::Vector3d::Zero();
  for (std::size_t k = 0; k < history.size(); ++k) {
    measured.col(static_cast<Eigen::Index>(k)) = history[k].measured_position;
    squares += (history[k].estimated_position - history[k].measured_position).cwiseAbs2();
  }
  const Eigen::Vector3d noise = noise_variance_per_axis(measured);
  const Eigen::Vector3d target =
      scale * scale * (squares / static_cast<double>(history.size()) + noise);
  const double configured = filter.options().observation_noise_translation;
  const TranslationMoments cloud = filter.translation_moments();
  auto& states = filter.translation().states;
  for (int axis = 0; axis < 3; ++axis) {
    const double variance = cloud.covariance(axis, axis);
    const bool widens = widen && noise(axis) > configured * configured;
    // A collapsed axis (every particle alike) has no shape to widen.
    if (!(variance > 0.0) || (!widens && !(variance > target(axis)))) continue;
    const double factor = std::sqrt(target(axis) / variance);
    states.row(axis) =
        (cloud.mean(axis) + factor * (states.row(axis).array() - cloud.mean(axis))).matrix();
  }
}

}  // namespace

bool ObjectPermanenceFilter::start_dynamics(Hypothesis& h) {
  // Seen again only briefly since the dynamics module last carried it, where that prediction
  // said: the motion goes on. (A glimpse of a few frames would read as static, handing a moving
  // object to its occluder; fitted together with the frames before the gap, a model through a
  // hole of seconds runs wild.) Brief: since the history's last gap longer than
  // `velocity_window`, under four samples or under `velocity_window` of time.
  std::size_t first = history_.empty() ? 0 : history_.size() - 1;
  while (first > 0 && history_[first].t - history_[first - 1].t <= options_.velocity_window)
    --first;
  const bool brief = history_.size() - first < 4 ||
                     history_.back().t - history_[first].t < options_.velocity_window;
  const auto follow = [&](MotionPrediction prediction) {
    if (options_.dynamics.selection.spread_beyond_validation)
      prediction.track_spread = displacement_spread_.profile();
    h.prediction = std::move(prediction);
    h.prediction_trace = 0.0;
    h.source = Source::kTrajectory;
    return true;
  };
  const auto continue_from_last = [&](const MotionPrediction& confirmed) {
    const MotionSample& last = history_.back();
    return follow(
        continued(confirmed, last.t, last.estimated_position, last.estimated_orientation));
  };
  if (brief && confirmed_motion_ && !history_.empty())
    return continue_from_last(*confirmed_motion_);
  // The motion the last gap confirmed stays the fallback while the history cannot be fitted
  // anew: seen again for a few frames after a long gap, the history is those frames and the
  // ones before the gap, with no second of consecutive frames to validate a model on.
  const std::optional<MotionPrediction> fallback = std::move(confirmed_motion_);
  confirmed_motion_.reset();
  // Moving or static is decided as with the paper's predictor (the motion test over the
  // history), so a static object still goes to the occluder module.
  const std::vector<TrajectorySample> window = estimate_history();
  if (window.size() < 2) return false;
  if (options_.motion.test == MotionTest::kMaxPairwise) {
    if (classify_motion(window, options_.motion) != Motion::kMoving) return false;
  } else {
    try {
      const TrajectoryModel line = fit_trajectory(window, options_.trajectory);
      if (classify_fitted_motion(line, window.front().t, window.back().t, options_.motion) !=
          Motion::kMoving)
        return false;
    } catch (const std::exception&) {
      return false;  // a degenerate window: treat the object as static
    }
  }
  const std::vector<MotionSample> samples(history_.begin(), history_.end());
  auto prediction = predict_motion(samples, options_.dynamics.selection);
  // Seen for longer than a glimpse, the object has had time to change its motion: an axis whose
  // motion did not bring it nearer where it reappeared than holding still would have holds still
  // (a walker who turned back during a gap is not carried on the old way through every next one).
  if (!prediction)
    return fallback ? continue_from_last(confirmed_by(*fallback, reappeared_at_, reappeared_where_))
                    : false;
  if (options_.measured_onset_spread)
    spread_to_measured_discrepancy(h.filter, samples, options_.dynamics.selection.uncertainty_scale,
                                   options_.widen_onset_spread);
  return follow(std::move(*prediction));
}

void ObjectPermanenceFilter::follow_prediction(Hypothesis& h, double t_previous, double t) {
  // The particles ARE the prediction: moved by the model's motion since the previous step and
  // spread by the growth of its covariance, with no virtual measurement pulling them back onto
  // the model (that would claim the model's own output as evidence and shrink the cloud).
  const MotionPrediction& p = *h.prediction;
  const double h0 = t_previous - p.t_last;
  const double h1 = t - p.t_last;
  // The spread stops growing where Q~ reaches the uncertainty module's cap, as Q~ itself does.
  const double q = h.filter.observation_trace(1.0);
  const double cap = (options_.uncertainty.max_scale - 1.0) * q;
  const double trace = p.translation_variance(h1).sum() + 3.0 * p.rotation_variance(h1);
  const bool capped = trace >= cap;
  // Bounded: after hold_after s, or once capped, the object is held where the prediction left it.
  if (!capped && h0 < options_.hold_after) {
    const double until = std::min(h1, options_.hold_after);
    h.filter.shift(p.position(until) - p.position(h0),
                   (p.orientation(until) * p.orientation(h0).conjugate()).normalized());
  }
  if (!capped) {
    const Eigen::Vector3d translation_growth =
        (p.translation_variance(h1) - p.translation_variance(h0)).cwiseMax(0.0);
    const double rotation_growth = std::max(0.0, p.rotation_variance(h1) - p.rotation_variance(h0));
    h.filter.diffuse(translation_growth.cwiseSqrt(), std::sqrt(rotation_growth));
  }
  h.prediction_trace = std::min(trace, cap);
  h.recovery = {.trace_capped = capped && options_.modules.uncertainty};
}

namespace {

// The occluder's pose as the carry reads it: its position from its measurement this frame when
// it has one (its estimate is a frame old and lags a moving occluder), its orientation from its
// filtered estimate when it has one and `orientation_from_estimate` (a single detection's
// rotation noise would bias the whole carry).
struct CarrierPose {
  Eigen::Vector3d position;
  Eigen::Quaterniond orientation;
};

CarrierPose carrier_pose(const Detection* detection, const Estimate* estimate,
                         bool orientation_from_estimate) {
  const mrpt::poses::CPose3D& for_position = detection ? detection->pose : estimate->pose.mean;
  const mrpt::poses::CPose3D& for_orientation =
      (estimate && (orientation_from_estimate || !detection)) ? estimate->pose.mean
                                                              : detection->pose;
  return {translation_of(for_position), orientation_of(for_orientation).normalized()};
}

double horizontal_distance(const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                           const Eigen::Vector3d& up) {
  const Eigen::Vector3d d = a - b;
  return (d - up * up.dot(d)).norm();
}

}  // namespace

void ObjectPermanenceFilter::follow_occluder(Hypothesis& hypothesis, const std::string& occluder,
                                             const Estimate& occluder_estimate,
                                             const EnsembleView& ensemble) const {
  hypothesis.source = Source::kOccluder;
  hypothesis.occluder = occluder;
  const CarrierPose reference = carrier_pose(ensemble.frame.find(occluder), &occluder_estimate,
                                             options_.occluder.orientation_from_estimate);
  hypothesis.occluder_position_at_onset = reference.position;
  hypothesis.occluder_orientation_at_onset = reference.orientation;
  hypothesis.last_carrier_position = reference.position;
  hypothesis.last_carrier_orientation = reference.orientation;
  hypothesis.carrier_track.clear();
  // A cover at the object's level (a cup slid over a ball) moves it only by pushing it: it waits
  // for the occluder's departure. One above it (a hand, a lifted tray) is followed from onset.
  const Eigen::Vector3d up = options_.dynamics.selection.up.normalized();
  const bool level = std::abs(up.dot(reference.position - hypothesis.position_at_onset)) <=
                     options_.occluder.reach;
  const bool wait = options_.occluder.carry_from_departure && level;
  hypothesis.carrying = !wait;
  hypothesis.at_offset = options_.occluder.keep_offset || wait;
  hypothesis.closest_distance =
      horizontal_distance(reference.position, hypothesis.position_at_onset, up);
}

std::optional<ObjectPermanenceFilter::VirtualMeasurement>
ObjectPermanenceFilter::virtual_measurement(Hypothesis& h, double t, const EnsembleView& ensemble) {
  VirtualMeasurement z;
  Eigen::Vector3d carrier_position;
  Eigen::Quaterniond carrier_orientation;
  Eigen::Vector3d speed_position;
  if (h.source == Source::kTrajectory) {
    z.position = carrier_position = h.trajectory->position(t);
    z.orientation = carrier_orientation = h.trajectory->orientation(t);
  } else if (h.source == Source::kOccluder) {
    // The occluder's measurement this frame (the paper's y_k^j), or its estimate when it is
    // hidden itself (a chain of occlusions).
    const Estimate* occluder_estimate = find_estimate(ensemble, h.occluder);
    const Detection* occluder_detection = ensemble.frame.find(h.occluder);
    if (!occluder_estimate && !occluder_detection) return std::nullopt;
    const CarrierPose occluder = carrier_pose(occluder_detection, occluder_estimate,
                                              options_.occluder.orientation_from_estimate);
    const Eigen::Vector3d up = options_.dynamics.selection.up.normalized();
    if (!h.carrying) {
      // Still closing in over the object: it stays where it was covered, and the carry will
      // start from the occluder's closest approach. Read from its measurements: its filtered
      // estimate lags a cup closing in and overshoots where it stops short.
      const double d = horizontal_distance(occluder.position, h.position_at_onset, up);
      if (d <= h.closest_distance) {
        h.closest_distance = d;
        h.occluder_position_at_onset = occluder.position;
        h.occluder_orientation_at_onset = occluder.orientation;
        h.last_carrier_position = occluder.position;
        h.last_carrier_orientation = occluder.orientation;
      }
      // Departed: further from the object than at the closest approach, and moved off that
      // place by the margin (tangentially too: a cup that stopped beside the ball and drags it
      // sideways barely changes its distance).
      const bool receding = d > h.closest_distance;
      const bool moved = horizontal_distance(occluder.position, h.occluder_position_at_onset, up) >
                         options_.occluder.departure_margin;
      if (!receding || !moved) return std::nullopt;
      h.carrying = true;
    }
    const Eigen::Quaterniond carried =
        occluder.orientation * h.occluder_orientation_at_onset.conjugate();
    z.position = occluder.position;
    const Eigen::Vector3d onset_offset =
        carried * (h.position_at_onset - h.occluder_position_at_onset);
    if (h.at_offset) {
      z.position += onset_offset;
    } else if (options_.occluder.keep_depth) {
      // Only the offset's vertical component: the object keeps its own height.
      z.position += up * up.dot(onset_offset);
    }
    z.orientation = (carried * h.orientation_at_onset).normalized();
    carrier_position = occluder.position;
    carrier_orientation = occluder.orientation;
    // Its speed for the uncertainty module from the filtered estimate: a still occluder reads
    // as still rather than jittering with its measurement noise.
    speed_position =
        occluder_estimate ? translation_of(occluder_estimate->pose.mean) : occluder.position;
  } else {
    return std::nullopt;
  }
  if (h.last_carrier_position) {
    z.carrier_from = *h.last_carrier_position;
    z.carrier_to = carrier_position;
    z.carrier_rotation =
        (carrier_orientation * h.last_carrier_orientation.conjugate()).normalized();
  }
  if (h.source == Source::kTrajectory) {
    z.speed = h.trajectory->velocity(t).norm();
  } else {
    h.carrier_track.emplace_back(t, speed_position);
    while (h.carrier_track.size() > 2 &&
           t - h.carrier_track[1].first >= options_.uncertainty.speed_window)
      h.carrier_track.pop_front();
    // Divided by at least the window: right after onset the baseline is a frame or two, and a
    // still occluder's jitter over one frame would read as speed.
    const auto& [t0, p0] = h.carrier_track.front();
    z.speed = (speed_position - p0).norm() /
              std::max(t - t0, std::max(options_.uncertainty.speed_window, 1e-9));
  }
  h.last_carrier_position = carrier_position;
  h.last_carrier_orientation = carrier_orientation;
  return z;
}

void ObjectPermanenceFilter::keep_hypothesis_explaining(const Eigen::Vector3d& position) {
  if (hypotheses_.size() < 2) return;
  std::size_t best = 0;
  double best_evidence = hypotheses_[0].filter.translation_log_evidence(position);
  for (std::size_t i = 1; i < hypotheses_.size(); ++i) {
    const double evidence = hypotheses_[i].filter.translation_log_evidence(position);
    if (evidence > best_evidence) {
      best = i;
      best_evidence = evidence;
    }
  }
  if (best != 0) hypotheses_[0] = std::move(hypotheses_[best]);
  hypotheses_.erase(hypotheses_.begin() + 1, hypotheses_.end());
}

Estimate ObjectPermanenceFilter::make_estimate(const Hypothesis& h, int index) const {
  Estimate estimate;
  estimate.object = object_;
  estimate.t = t_;
  estimate.pose = h.filter.estimate();
  // Q~: the inflated Q of the uncertainty module, or, for the selected predictor, Q plus the
  // prediction's covariance (the same uncertainty the particles carry).
  estimate.observation_trace = h.prediction
                                   ? h.filter.observation_trace(1.0) +
                                         (options_.modules.uncertainty ? h.prediction_trace : 0.0)
                                   : h.filter.observation_trace(h.inflation.scale());
  estimate.alert = safety_alert(estimate.observation_trace, options_.feedback);
  estimate.hypothesis = index;
  estimate.recovery = h.recovery;
  switch (h.source) {
    case Source::kMeasurement:
      estimate.mode = EstimateMode::kMeasured;
      break;
    case Source::kTrajectory:
      estimate.mode = EstimateMode::kDynamics;
      if (h.prediction) estimate.motion_model = describe(*h.prediction);
      break;
    case Source::kOccluder:
      estimate.mode = EstimateMode::kOccluder;
      break;
    case Source::kNone:
      estimate.mode = EstimateMode::kPredicted;
      break;
  }
  return estimate;
}

std::vector<Estimate> ObjectPermanenceFilter::extra_hypotheses() const {
  std::vector<Estimate> extras;
  for (std::size_t i = 1; i < hypotheses_.size(); ++i)
    extras.push_back(make_estimate(hypotheses_[i], static_cast<int>(i)));
  return extras;
}

}  // namespace opf
