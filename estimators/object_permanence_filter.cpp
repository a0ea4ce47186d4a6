#include "opf/estimators/object_permanence_filter.h"

#include "opf/core/pose_conversion.h"
#include "opf/core/random.h"
#include "opf/core/so3.h"
#include "opf/permanence/bank_motion.h"
#include "opf/permanence/hypothesis_probabilities.h"
#include "opf/permanence/motion_classifier.h"
#include "opf/permanence/occluder_carry.h"
#include "opf/permanence/occluder_selection.h"
#include "opf/permanence/partial_view.h"
#include "opf/permanence/place_visibility.h"
#include "opf/permanence/trajectory_motion.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string_view>

namespace opf {
namespace {

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

// The occluders that carry a hypothesis. With the gate, every probable one (and the object left
// in place is one more); without it, the paper's rule: the nearest, and O_i' for a runner-up
// within epsilon_occ.
std::vector<WeightedOccluder> hypothesis_occluders(const OccluderChoice& choice, bool gate) {
  if (gate) return probable_occluders(choice, kOccluderHypothesisFloor, kMaxOccluderHypotheses);
  if (choice.second) return {{*choice.nearest, 0.5}, {*choice.second, 0.5}};
  return {{*choice.nearest, 1.0}};
}

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
  hypotheses_.emplace_back(PoseParticleFilter(options_.particles, seed_));
  hypotheses_[0].filter.initialise(translation_of(first), orientation_of(first));
  hypotheses_[0].last = {hypotheses_[0].filter.observation_trace(1.0), {}};
  history_.clear();
  detector_jitter_.clear();
  restart_banks();
  t_ = t;
  hidden_ = false;
  initialised_ = true;
  const Estimate estimate = make_estimate(hypotheses_[0], 0);
  remember(t, translation_of(first), orientation_of(first), estimate, 0.0);
  return estimate;
}

void ObjectPermanenceFilter::remember(double t, const Eigen::Vector3d& position,
                                      const Eigen::Quaterniond& orientation,
                                      const Estimate& estimate, double extra_noise,
                                      const PartialViewBias& stretch_prior) {
  detector_jitter_.add(t, position, orientation);
  update_banks(t, position, orientation, extra_noise, stretch_prior);
  history_.push_back({t, translation_of(estimate.pose.mean), orientation_of(estimate.pose.mean)});
  while (history_.size() > options_.history_length) history_.pop_front();
}

void ObjectPermanenceFilter::restart_banks() {
  translation_bank_ = MotionModelBank(translation_bank_.options());
  rotation_bank_ = RotationModelBank(rotation_bank_.options());
  held_.reset();
}

bool ObjectPermanenceFilter::bank_expects(double t, const Eigen::Vector3d& position,
                                          double extra_noise) const {
  if (!translation_bank_.initialised()) return true;
  const BankPrediction p = translation_bank_.predict(t - translation_bank_.last_time());
  const double r = observation_sigma(translation_bank_.options().observation_noise, extra_noise);
  const Eigen::Vector3d innovation = position - p.mean();
  const Eigen::Vector3d variance = p.variance().array() + r * r;
  return innovation.cwiseAbs2().cwiseQuotient(variance).sum() <= kBankGateChiSquare;
}

void ObjectPermanenceFilter::update_banks(double t, const Eigen::Vector3d& position,
                                          const Eigen::Quaterniond& orientation, double extra_noise,
                                          const PartialViewBias& stretch_prior) {
  // A validation gate with two-in-a-row confirmation: one measurement the models cannot explain
  // is held back (a wrong detection must not set the velocity the particles drift by); when the
  // next one is outside too, both are taken (the object moved as no model predicted).
  if (!bank_expects(t, position, extra_noise)) {
    if (!held_) {
      held_ = HeldMeasurement{t, position, orientation, extra_noise, stretch_prior};
      return;
    }
    take_held_measurement();
  }
  held_.reset();
  translation_bank_.update(t, position, extra_noise, stretch_prior);
  rotation_bank_.update(t, orientation);
}

void ObjectPermanenceFilter::take_held_measurement() {
  if (!held_) return;
  translation_bank_.update(held_->t, held_->position, held_->extra_noise, held_->stretch_prior);
  rotation_bank_.update(held_->t, held_->orientation);
  held_.reset();
}

void ObjectPermanenceFilter::predict_with_bank_velocity(Hypothesis& h, double dt) {
  // The body-frame angular velocity turns the estimate's orientation; as a world rotation it
  // turns every particle about the same axis (they lie within a few degrees of the estimate).
  const Eigen::Quaterniond q = history_.back().orientation.normalized();
  const Eigen::Quaterniond turn =
      q * so3::exp(rotation_bank_.angular_velocity() * dt) * q.conjugate();
  h.filter.predict(dt, translation_bank_.velocity() * dt, turn.normalized(),
                   translation_bank_.variance_growth(dt), rotation_bank_.variance_growth(dt));
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
    return update(t, dt, *measurement,
                  options_.detector_noise ? stated_extra_noise(ensemble, measurement) : 0.0,
                  ensemble);
  }
  if (!hidden_) {
    hidden_ = true;
    hidden_since_ = last_seen;
    take_held_measurement();  // the last word before the gap: no next one will judge it
    start_occlusion(last_seen, ensemble);
  }
  for (Hypothesis& h : hypotheses_) h.last = h.motion->step(last_seen, t, ensemble, h.filter);
  if (options_.occluder.gate) weigh_by_what_is_not_seen(ensemble, dt);
  return make_estimate(hypotheses_[0], 0);
}

Estimate ObjectPermanenceFilter::update(double t, double dt,
                                        const mrpt::poses::CPose3D& measurement, double extra_noise,
                                        const EnsembleView& ensemble) {
  // The banks' motion carries the particles to the measurement: seen in the previous frame too,
  // by the banks' velocity; after a gap, on along the mixture they followed through it.
  const bool drifts = options_.velocity_drift && !history_.empty();
  for (std::size_t i = 0; i < hypotheses_.size(); ++i) {
    Hypothesis& each = hypotheses_[i];
    if (drifts && hidden_ && each.motion && each.motion->predicts_the_measurement())
      each.motion->step(t - dt, t, ensemble, each.filter);
    else if (drifts && !hidden_ && i == 0)
      predict_with_bank_velocity(each, dt);
    else
      each.filter.predict(dt);
  }
  const Eigen::Vector3d position = translation_of(measurement);
  const Eigen::Quaterniond orientation = orientation_of(measurement);
  // This detection's noise in every likelihood it enters, the hypotheses' evidence included; the
  // configured noise again afterwards, for the virtual measurements of a gap (paper Eq. 14).
  for (Hypothesis& each : hypotheses_) each.filter.set_translation_extra_noise(extra_noise);
  keep_hypothesis_explaining(position);
  Hypothesis& h = hypotheses_[0];
  const EstimateMode hidden_by = h.motion ? h.motion->mode() : EstimateMode::kMeasured;
  if (options_.detector_noise) adapt_rotation_noise(h);
  // A partial view is off towards its visible part: the known part of that is taken off the
  // detection (partial_view.h); the rest, extra noise times the bias s shared by the stretch of
  // partial views, has its mean estimated by the banks and its spread counts as the detection's
  // extra noise (docs/dynamics.md, "Partial views").
  const PartialViewCentre centre =
      partial_view_centre(position, extra_noise, object_, ensemble, options_.occluder);
  const Eigen::Vector3d detected = centre.position;
  PartialViewBias stretch_prior;  // s when a stretch begins
  stretch_prior.variance = 1.0 - centre.known_share * centre.known_share;
  Eigen::Vector3d seen = detected;
  if (extra_noise > 0.0) {
    // A gap ended the banks' stretch (start_occlusion): after one, a stretch begins afresh.
    const PartialViewBias bias = translation_bank_.in_partial_views()
                                     ? translation_bank_.partial_view_bias()
                                     : stretch_prior;
    seen -= extra_noise * bias.mean;
    h.filter.set_translation_extra_noise(extra_noise * std::sqrt(bias.variance));
  }
  const bool lost =
      h.filter.update_with_measurement(seen, orientation, options_.gaussian_update_share);
  h.filter.set_translation_extra_noise(0.0);
  const ResampleReport report = h.filter.normalise_and_resample();
  h.motion.reset();
  h.last = {h.filter.observation_trace(1.0),
            {.sensor_reset = lost, .weights_underflow = report.weights_underflow()}};
  // The history restarts when the object turns up somewhere its history does not lead: after a
  // long occlusion in which it was carried by an occluder or only held (revealed in a new place),
  // or whenever the measurement was far outside the cloud (a translation reset). An object the
  // dynamics module carried through the gap keeps its history: its motion is still that one. A
  // reset of the rotation portion alone (the orientation of a half-covered object read wrong)
  // says nothing against where the object was going.
  if (h.filter.translation_was_reset() || (hidden_ && hidden_by != EstimateMode::kDynamics &&
                                           t - hidden_since_ > options_.history_reset_gap))
    history_.clear();
  // Carried by another object, it moved as nothing in its own history did.
  if (hidden_ && hidden_by == EstimateMode::kCarried) restart_banks();
  hidden_ = false;
  // The history sample holds the estimate itself: its moments are computed once per step.
  const Estimate estimate = make_estimate(h, 0);
  remember(t, detected, orientation, estimate, extra_noise, stretch_prior);
  return estimate;
}

void ObjectPermanenceFilter::start_occlusion(double last_seen, const EnsembleView& ensemble) {
  // Seen again, the object shows another side: its partial views' bias starts afresh.
  translation_bank_.end_partial_views();
  // A hypothesis per occluder exists only while hidden; at onset there is one.
  hypotheses_.erase(hypotheses_.begin() + 1, hypotheses_.end());
  const bool bank = options_.dynamics.predictor == DynamicsPredictor::kBank;
  // A moving object goes to the dynamics module, a static one to the occluder module (paper
  // Sec. III-B); with the bank, a static object no occluder hides is predicted by the bank too
  // (whose constant-position members then carry the weight). With the gate, a moving object may
  // also be carried by what hides it (a cup under the hand that moves it): its own motion and
  // each plausible carrier are hypotheses, weighed by what the camera does not see.
  if (options_.modules.dynamics && history_moves()) {
    Hypothesis& h = hypotheses_[0];
    h.motion = bank ? bank_mixture(h.filter) : fitted_trajectory(last_seen);
    if (h.motion) {
      if (options_.modules.occluder && options_.occluder.gate)
        start_occluders(ensemble, /*beside_own_motion=*/true);
      return;
    }
  }
  // The occluder module may add a hypothesis: hypotheses_ is not referenced across the call.
  if (options_.modules.occluder && start_occluders(ensemble, /*beside_own_motion=*/false)) return;
  Hypothesis& h = hypotheses_[0];
  if (options_.modules.dynamics && bank)
    h.motion = bank_mixture(h.filter);
  else
    h.motion = std::make_unique<HeldMotion>(virtual_measurement_settings());
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

std::unique_ptr<HiddenMotion> ObjectPermanenceFilter::fitted_trajectory(double last_seen) const {
  const std::vector<TrajectorySample> window(history_.begin(), history_.end());
  const int needed =
      std::max(options_.trajectory.translation_order, options_.trajectory.rotation_order) + 1;
  if (static_cast<int>(window.size()) < std::max(needed, 2)) return nullptr;
  try {
    return std::make_unique<TrajectoryMotion>(
        virtual_measurement_settings(), fit_trajectory(window, options_.trajectory), last_seen);
  } catch (const std::exception&) {
    // A degenerate window cannot be fitted: treat the object as static and let the occluder
    // module try.
    return nullptr;
  }
}

std::unique_ptr<HiddenMotion> ObjectPermanenceFilter::bank_mixture(PoseParticleFilter& filter) {
  return std::make_unique<BankMotion>(translation_bank_, rotation_bank_, filter,
                                      options_.uncertainty, options_.modules.uncertainty,
                                      derive_seed(seed_, kMixtureStreams + ++occlusions_));
}

VirtualMeasurementMotion::Settings ObjectPermanenceFilter::virtual_measurement_settings() const {
  return {options_.uncertainty, options_.modules.uncertainty, options_.carry_particles,
          options_.detector_noise};
}

bool ObjectPermanenceFilter::start_occluders(const EnsembleView& ensemble, bool beside_own_motion) {
  Hypothesis& h = hypotheses_[0];
  std::vector<OccluderCandidate> candidates;
  std::vector<const Estimate*> candidate_estimates;
  for (const Estimate& e : ensemble.previous_estimates) {
    if (e.object == object_) continue;
    candidates.push_back({e.object, translation_of(e.pose.mean), translation_covariance(e),
                          stated_radius(ensemble, e.object)});
    candidate_estimates.push_back(&e);
  }
  const TranslationMoments own = h.filter.translation_moments();
  const OccluderChoice choice =
      choose_occluders(own.mean, own.covariance, candidates, options_.occluder);
  if (!choice.nearest) return false;

  const bool with_left = options_.occluder.gate;
  const std::vector<WeightedOccluder> occluders = hypothesis_occluders(choice, with_left);
  const std::size_t k0 = occluders[0].candidate;
  // The occluder's estimate is the last frame's, when this object was still seen.
  hiding_radius_ = hiding_radius(own.mean, candidates[k0].mean, options_.occluder);
  place_covariance_ = own.covariance;
  // Still, it is left or carried from its place (the measured hiding radius above stays the offset
  // between the two particle filters' estimates the ensemble held when it was last seen).
  const Eigen::Quaterniond orientation = h.filter.rotation_moments().mean;
  const Eigen::Vector3d place =
      beside_own_motion ? own.mean : move_to_bank_place(h.filter, own.mean);
  const auto carry = [&](std::size_t k) {
    return std::make_unique<OccluderCarry>(virtual_measurement_settings(), options_.occluder,
                                           options_.dynamics.up, place, orientation,
                                           candidates[k].object, *candidate_estimates[k], ensemble);
  };
  const double carried_share = with_left ? 1.0 - kLeftPrior : 1.0;
  // The others copy the filter as it is at onset, before hypothesis 0 moves.
  const std::optional<PoseParticleFilter> at_onset =
      occluders.size() > 1 || with_left || beside_own_motion ? std::optional(h.filter)
                                                             : std::nullopt;
  const auto spawn = [&](std::unique_ptr<HiddenMotion> motion, double probability) {
    Hypothesis twin(*at_onset);  // O_i' (another occluder), the object left, or its carrier
    twin.filter.reseed(derive_seed(seed_, ++spawned_));
    twin.motion = std::move(motion);
    twin.probability = probability;
    hypotheses_.push_back(std::move(twin));
  };
  if (beside_own_motion) {  // its own motion takes the place of `left`, at the same odds
    for (const WeightedOccluder& o : occluders)
      spawn(carry(o.candidate), carried_share * o.probability);
    hypotheses_[0].probability = kLeftPrior;
    most_probable_first();
    return true;
  }
  for (std::size_t k = 1; k < occluders.size(); ++k)
    spawn(carry(occluders[k].candidate), carried_share * occluders[k].probability);
  hypotheses_[0].motion = carry(k0);
  hypotheses_[0].probability = carried_share * occluders[0].probability;
  if (with_left) {
    spawn(std::make_unique<HeldMotion>(virtual_measurement_settings(), EstimateMode::kLeft),
          kLeftPrior);
    // Left first: the main estimate at onset.
    std::rotate(hypotheses_.begin(), hypotheses_.end() - 1, hypotheses_.end());
    most_probable_first();
  }
  return true;
}

Eigen::Vector3d ObjectPermanenceFilter::move_to_bank_place(PoseParticleFilter& filter,
                                                           const Eigen::Vector3d& mean) const {
  if (options_.dynamics.predictor != DynamicsPredictor::kBank || !translation_bank_.initialised())
    return mean;
  const Eigen::Vector3d place = translation_bank_.predict(0.0).mean();
  filter.shift(place - mean, Eigen::Quaterniond::Identity());
  return place;
}

void ObjectPermanenceFilter::keep_hypothesis_explaining(const Eigen::Vector3d& position) {
  if (hypotheses_.size() < 2) return;
  std::vector<double> log_evidence;
  for (const Hypothesis& h : hypotheses_)
    log_evidence.push_back(h.filter.translation_log_evidence(position));
  const std::size_t best = most_probable_given(probabilities(), log_evidence);
  if (best != 0) hypotheses_[0] = std::move(hypotheses_[best]);
  hypotheses_.erase(hypotheses_.begin() + 1, hypotheses_.end());
  hypotheses_[0].probability = 1.0;
}

void ObjectPermanenceFilter::weigh_by_what_is_not_seen(const EnsembleView& ensemble, double dt) {
  if (hypotheses_.size() < 2) return;
  // Where the objects are, as well as the detector tells: each covariance at the detector's own
  // noise, read from this object's detections (place_visibility.h, at_detector_noise), never
  // below a tenth of the configured noise, as for the rotation likelihood.
  const double configured = options_.particles.observation_noise_translation;
  const std::optional<double> read = detector_jitter_.translation_sigma();
  const auto known = [&](const Eigen::Matrix3d& covariance) {
    if (!read) return covariance;
    return at_detector_noise(covariance, configured,
                             std::max(*read, kJitterFloorShare * configured),
                             options_.particles.process_noise_translation, dt);
  };
  std::vector<ViewBlocker> blockers;
  std::vector<std::string_view> blocking_objects;
  for (const Estimate& e : ensemble.previous_estimates) {
    if (e.object == object_) continue;
    blockers.push_back({translation_of(e.pose.mean), known(translation_covariance(e)),
                        stated_radius(ensemble, e.object), stated_box(ensemble, e.object),
                        orientation_of(e.pose.mean)});
    blocking_objects.push_back(e.object);
  }
  const Eigen::Matrix3d place_covariance = known(place_covariance_);
  // p(no detection | the object at the place) = 1 - P(seen) (1 - P_miss).
  for (Hypothesis& h : hypotheses_) {
    const Eigen::Vector3d place = h.filter.translation_moments().mean;
    // A carried hypothesis is that the object moves with its carrier: the carrier covers the
    // place by the offset the carry keeps them at, wherever its estimate is and however unsure
    // (hidden itself, or a frame old).
    std::vector<ViewBlocker> around = blockers;
    if (const auto offset = h.motion ? h.motion->carrier_offset() : std::nullopt)
      for (std::size_t k = 0; k < around.size(); ++k)
        if (blocking_objects[k] == h.motion->label()) {
          around[k].mean = place + *offset;
          around[k].carries_the_place = true;
        }
    const double seen =
        seen_probability(place, place_covariance, around, hiding_radius_, options_.occluder);
    if (std::isfinite(seen)) h.probability *= no_detection_likelihood(seen);
  }
  normalise_probabilities();
  most_probable_first();
}

void ObjectPermanenceFilter::normalise_probabilities() {
  double total = 0.0;
  for (const Hypothesis& h : hypotheses_) total += h.probability;
  for (Hypothesis& h : hypotheses_) h.probability /= total;
}

std::vector<double> ObjectPermanenceFilter::probabilities() const {
  std::vector<double> p;
  for (const Hypothesis& h : hypotheses_) p.push_back(h.probability);
  return p;
}

void ObjectPermanenceFilter::most_probable_first() {
  std::vector<Hypothesis> ordered;
  for (const std::size_t i : hypothesis_order(probabilities()))
    ordered.push_back(std::move(hypotheses_[i]));
  hypotheses_ = std::move(ordered);
  normalise_probabilities();
}

Estimate ObjectPermanenceFilter::make_estimate(const Hypothesis& h, int index) const {
  Estimate estimate;
  estimate.object = object_;
  estimate.t = t_;
  estimate.pose = h.filter.estimate();
  estimate.observation_trace = h.last.observation_trace;
  estimate.hypothesis = index;
  estimate.probability = h.probability;
  estimate.recovery = h.last.recovery;
  estimate.mode = h.motion ? h.motion->mode() : EstimateMode::kMeasured;
  if (h.motion) estimate.motion_model = h.motion->label();
  return estimate;
}

ObjectPermanenceFilter::Hypothesis::Hypothesis(const Hypothesis& other)
    : filter(other.filter),
      motion(other.motion ? other.motion->clone() : nullptr),
      last(other.last),
      probability(other.probability) {}

ObjectPermanenceFilter::Hypothesis& ObjectPermanenceFilter::Hypothesis::operator=(
    const Hypothesis& other) {
  if (this != &other) *this = Hypothesis(other);
  return *this;
}

std::vector<Estimate> ObjectPermanenceFilter::extra_hypotheses() const {
  std::vector<Estimate> extras;
  for (std::size_t i = 1; i < hypotheses_.size(); ++i)
    extras.push_back(make_estimate(hypotheses_[i], static_cast<int>(i)));
  return extras;
}

}  // namespace opf
