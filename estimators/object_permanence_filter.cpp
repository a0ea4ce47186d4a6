#include "opf/estimators/object_permanence_filter.h"

#include "opf/core/pose_conversion.h"
#include "opf/core/random.h"
#include "opf/core/so3.h"
#include "opf/permanence/motion_classifier.h"
#include "opf/permanence/occluder_selection.h"

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

// The detector's jitter is read over the last 2 s of measurements: tens of samples at video
// rates, recent enough to follow a detector whose noise changes with the view.
constexpr double kDetectorNoiseWindow = 2.0;

// Each gap's member draws come from their own stream of the filter's seed.
constexpr std::uint64_t kMixtureStreams = 1000;

// The banks' validation gate: the chi-square 99.9% quantile with 3 degrees of freedom, on the
// position's squared Mahalanobis distance from the mixture's one-step prediction.
constexpr double kBankGateChiSquare = 16.266;

}  // namespace

void validate(const OpfOptions& options) {
  validate(options.particles);
  check_options(options, "OPF");
  const OptionChecker fixed("OPF");  // the constants that are not settings
  fixed.number("history_reset_gap", options.history_reset_gap,
               non_negative("a number of seconds >= 0"));
  fixed.number("occluder.departure_margin", options.occluder.departure_margin,
               non_negative("metres >= 0"));
  fixed.number("occluder.gate_sigmas", options.occluder.gate_sigmas, non_negative());
  if (options.occluder.plane == OccluderPlane::kLineOfSight && !options.occluder.camera_position)
    throw std::invalid_argument(
        "OPF option occluder.plane is line_of_sight but no camera position is given "
        "(opf.occluder.camera_position, or --camera X,Y,Z); plane auto takes a top-down camera");
}

ObjectPermanenceFilter::ObjectPermanenceFilter(const OpfOptions& options, std::string object,
                                               std::uint64_t seed)
    : options_((validate(options), options)),  // before the banks check their share
      object_(std::move(object)),
      seed_(seed),
      detector_jitter_(kDetectorNoiseWindow),
      translation_bank_(translation_bank_options(options.dynamics,
                                                 options.particles.observation_noise_translation)),
      rotation_bank_(
          rotation_bank_options(options.dynamics, options.particles.observation_noise_rotation)) {}

Estimate ObjectPermanenceFilter::initialise(double t, const mrpt::poses::CPose3D& first) {
  hypotheses_.clear();
  hypotheses_.emplace_back(PoseParticleFilter(options_.particles, seed_),
                           CovarianceInflation(options_.uncertainty));
  hypotheses_[0].filter.initialise(translation_of(first), orientation_of(first));
  history_.clear();
  detector_jitter_.clear();
  restart_banks();
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
  update_banks(t, position, orientation);
  history_.push_back({t, translation_of(estimate.pose.mean), orientation_of(estimate.pose.mean)});
  while (history_.size() > options_.history_length) history_.pop_front();
}

void ObjectPermanenceFilter::restart_banks() {
  translation_bank_ = MotionModelBank(translation_bank_.options());
  rotation_bank_ = RotationModelBank(rotation_bank_.options());
  held_.reset();
}

bool ObjectPermanenceFilter::bank_expects(double t, const Eigen::Vector3d& position) const {
  if (!translation_bank_.initialised()) return true;
  const BankPrediction p = translation_bank_.predict(t - translation_bank_.last_time());
  const double r = translation_bank_.options().observation_noise;
  const Eigen::Vector3d innovation = position - p.mean();
  const Eigen::Vector3d variance = p.variance().array() + r * r;
  return innovation.cwiseAbs2().cwiseQuotient(variance).sum() <= kBankGateChiSquare;
}

void ObjectPermanenceFilter::update_banks(double t, const Eigen::Vector3d& position,
                                          const Eigen::Quaterniond& orientation) {
  // A validation gate with two-in-a-row confirmation: one measurement the models cannot explain
  // is held back (a wrong detection must not set the velocity the particles drift by); when the
  // next one is outside too, both are taken (the object moved as no model predicted).
  if (!bank_expects(t, position)) {
    if (!held_) {
      held_ = HeldMeasurement{t, position, orientation};
      return;
    }
    translation_bank_.update(held_->t, held_->position);
    rotation_bank_.update(held_->t, held_->orientation);
  }
  held_.reset();
  translation_bank_.update(t, position);
  rotation_bank_.update(t, orientation);
}

void ObjectPermanenceFilter::predict_with_bank_velocity(Hypothesis& h, double dt) {
  // The body-frame angular velocity turns the estimate's orientation; as a world rotation it
  // turns every particle about the same axis (they lie within a few degrees of the estimate).
  const Eigen::Quaterniond q = history_.back().orientation.normalized();
  const Eigen::Quaterniond turn =
      q * so3::exp(rotation_bank_.angular_velocity() * dt) * q.conjugate();
  h.filter.predict(dt, translation_bank_.velocity() * dt, turn.normalized());
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
    // The object was seen in the previous frame too: the banks' velocity carries the particles.
    const bool drifts = options_.velocity_drift && !hidden_ && !history_.empty();
    for (std::size_t i = 0; i < hypotheses_.size(); ++i) {
      if (i == 0 && drifts)
        predict_with_bank_velocity(hypotheses_[0], dt);
      else
        hypotheses_[i].filter.predict(dt);
    }
    const Eigen::Vector3d position = translation_of(*measurement);
    const Eigen::Quaterniond orientation = orientation_of(*measurement);
    keep_hypothesis_explaining(position);
    Hypothesis& h = hypotheses_[0];
    const Source hidden_by = h.source;
    if (options_.adaptive_rotation_noise) adapt_rotation_noise(h);
    const bool lost = h.filter.update_with_measurement(
        position, orientation, hidden_ ? options_.reacquisition_gaussian_share : 0.0);
    const ResampleReport report = h.filter.normalise_and_resample();
    h.recovery = {.sensor_reset = lost, .weights_underflow = report.weights_underflow()};
    h.inflation.reset();
    h.source = Source::kMeasurement;
    h.trajectory.reset();
    h.mixture.reset();
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
    // Carried by another object, it moved as nothing in its own history did.
    if (hidden_ && hidden_by == Source::kOccluder) restart_banks();
    hidden_ = false;
    // The history sample holds the estimate itself: its moments are computed once per step.
    const Estimate estimate = make_estimate(h, 0);
    remember(t, position, orientation, estimate);
    return estimate;
  }

  if (!hidden_) {
    hidden_ = true;
    hidden_since_ = last_seen;
    // A held measurement is the last word before the gap: no next one will judge it.
    if (held_) {
      translation_bank_.update(held_->t, held_->position);
      rotation_bank_.update(held_->t, held_->orientation);
      held_.reset();
    }
    start_occlusion(last_seen, ensemble);
  }
  for (Hypothesis& h : hypotheses_) {
    if (h.mixture) {
      follow_mixture(h, last_seen, t);
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
  const bool bank = options_.dynamics.predictor == DynamicsPredictor::kBank;
  // A moving object goes to the dynamics module, a static one to the occluder module (paper
  // Sec. III-B); with the bank, a static object no occluder hides is predicted by the bank too
  // (whose constant-position members then carry the weight).
  if (options_.modules.dynamics && history_moves()) {
    if (bank) {
      start_mixture(h);
      return;
    }
    if (start_trajectory(h, last_seen)) return;
  }
  if (options_.modules.occluder && start_occluders(ensemble)) return;
  if (options_.modules.dynamics && bank) start_mixture(h);
}

bool ObjectPermanenceFilter::history_moves() const {
  const std::vector<TrajectorySample> window(history_.begin(), history_.end());
  if (window.size() < 2) return false;
  if (options_.motion.test == MotionTest::kMaxPairwise)
    return classify_motion(window, options_.motion) == Motion::kMoving;
  try {
    const TrajectoryModel line = fit_trajectory(window, options_.trajectory);
    return classify_fitted_motion(line, window.front().t, window.back().t, options_.motion) ==
           Motion::kMoving;
  } catch (const std::exception&) {
    return false;  // a degenerate window: treat the object as static
  }
}

bool ObjectPermanenceFilter::start_trajectory(Hypothesis& h, double last_seen) {
  const std::vector<TrajectorySample> window(history_.begin(), history_.end());
  const int needed =
      std::max(options_.trajectory.translation_order, options_.trajectory.rotation_order) + 1;
  if (static_cast<int>(window.size()) < std::max(needed, 2)) return false;
  try {
    h.trajectory = fit_trajectory(window, options_.trajectory);
  } catch (const std::exception&) {
    // A degenerate window cannot be fitted: treat the object as static and let the occluder
    // module try.
    return false;
  }
  h.source = Source::kTrajectory;
  h.last_carrier_position = h.trajectory->position(last_seen);
  h.last_carrier_orientation = h.trajectory->orientation(last_seen);
  return true;
}

void ObjectPermanenceFilter::start_mixture(Hypothesis& h) {
  h.mixture.emplace(derive_seed(seed_, kMixtureStreams + ++occlusions_));
  h.mixture->start(translation_bank_, rotation_bank_, h.filter);
  h.prediction_trace = 0.0;
  h.source = Source::kTrajectory;
}

bool ObjectPermanenceFilter::start_occluders(const EnsembleView& ensemble) {
  Hypothesis& h = hypotheses_[0];
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
  if (!choice.nearest) return false;

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
  return true;
}

void ObjectPermanenceFilter::follow_mixture(Hypothesis& h, double t_previous, double t) {
  // The particles ARE the prediction: moved along the mixture with no virtual measurement
  // pulling them back onto it (that would claim the model's own output as evidence).
  const double last = translation_bank_.last_time();
  const double h1 = t - last;
  h.mixture->advance(translation_bank_, rotation_bank_, t_previous - last, h1, h.filter);
  // Q~ = Q plus the prediction's added covariance, capped where the uncertainty module caps it.
  const double cap = (options_.uncertainty.max_scale - 1.0) * h.filter.observation_trace(1.0);
  const double trace = MixtureParticleMotion::added_trace(translation_bank_, rotation_bank_, h1);
  h.prediction_trace = std::min(trace, cap);
  h.recovery = {.trace_capped = trace >= cap && options_.modules.uncertainty};
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
  const Eigen::Vector3d up = options_.dynamics.up.normalized();
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
    const Eigen::Vector3d up = options_.dynamics.up.normalized();
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
  // Q~: the inflated Q of the uncertainty module, or, for the bank, Q plus the prediction's
  // added covariance (the same uncertainty the particles carry).
  estimate.observation_trace = h.mixture
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
      if (h.mixture)
        estimate.motion_model = MixtureParticleMotion::label(translation_bank_, rotation_bank_);
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
