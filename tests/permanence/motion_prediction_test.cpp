#include "opf/permanence/motion_prediction.h"

#include "opf/core/random.h"
#include "opf/core/so3.h"
#include "opf/fit/local_polynomial.h"
#include "opf/fit/wandering_velocity.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <initializer_list>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <vector>

namespace opf {
namespace {

using PositionAt = std::function<Eigen::Vector3d(double)>;
using OrientationAt = std::function<Eigen::Quaterniond(double)>;

Eigen::Quaterniond still(double) {
  return Eigen::Quaterniond::Identity();
}

// `seconds` of history at `rate` Hz ending at t = 5 s, measured with sigma_p / sigma_r noise;
// the estimates are the true poses (a filter that neither lags nor jitters).
std::vector<MotionSample> history(double rate, double seconds, const PositionAt& p,
                                  const OrientationAt& q, double sigma_p, double sigma_r,
                                  std::uint64_t seed) {
  Random random(seed);
  std::vector<MotionSample> samples;
  const int count = static_cast<int>(std::lround(seconds * rate)) + 1;
  for (int k = 0; k < count; ++k) {
    const double t = 5.0 - (count - 1 - k) / rate;
    MotionSample s;
    s.t = t;
    s.measured_position =
        p(t) + sigma_p * Eigen::Vector3d(random.normal(), random.normal(), random.normal());
    s.measured_orientation =
        q(t) *
        so3::exp(sigma_r * Eigen::Vector3d(random.normal(), random.normal(), random.normal()));
    s.estimated_position = p(t);
    s.estimated_orientation = q(t);
    samples.push_back(s);
  }
  return samples;
}

TEST(MotionPrediction, ConstantVelocityIsFoundAtEveryFrameRate) {
  const Eigen::Vector3d v(0.2, -0.1, 0.05);
  const PositionAt line = [&](double t) {
    return Eigen::Vector3d(Eigen::Vector3d(0.3, 0.1, 0.0) + v * t);
  };
  for (const double rate : {10.0, 30.0, 100.0}) {
    const auto samples = history(rate, 2.0, line, still, 0.002, 0.01, 11);
    const auto prediction = predict_motion(samples, MotionPredictionOptions{});
    ASSERT_TRUE(prediction) << rate << " Hz";
    for (int axis = 0; axis < 3; ++axis)
      EXPECT_EQ(prediction->translation_models[static_cast<std::size_t>(axis)],
                TranslationModel::kConstantVelocity)
          << rate << " Hz, axis " << axis;
    // The velocity of a 2 mm-noise line over at least 0.4 s is known to ~3 mm/s per axis at
    // 10 Hz: 0.6 s ahead the prediction is within 5 mm of the line (3 sigma over three axes).
    EXPECT_LT((prediction->position(0.6) - line(5.6)).norm(), 0.005) << rate << " Hz";
    // Still orientation, 0.01 rad noise: whichever rotation model weighs most, the prediction
    // stays within a few noise sigmas of it.
    EXPECT_LT(so3::angle_between(prediction->orientation(0.6), still(5.6)), 0.03) << rate << " Hz";
  }
}

TEST(MotionPrediction, AStillObjectIsHeld) {
  const PositionAt fixed = [](double) { return Eigen::Vector3d(0.5, 0.0, 0.02); };
  const auto prediction =
      predict_motion(history(30.0, 2.0, fixed, still, 0.002, 0.01, 5), MotionPredictionOptions{});
  ASSERT_TRUE(prediction);
  // Held, or a line whose slope is noise: 2 mm over a 1.6 s window gives a velocity of
  // sigma sqrt(12 / 48) / 1.6 s = 0.6 mm/s per axis, 4 mm in 1 s at 4 sigma over three axes.
  const bool constant = prediction->translation_model == TranslationModel::kConstantPosition ||
                        prediction->translation_model == TranslationModel::kConstantVelocity;
  EXPECT_TRUE(constant) << to_string(prediction->translation_model);
  EXPECT_LT((prediction->position(1.0) - fixed(0.0)).norm(), 0.004);
}

TEST(MotionPrediction, AThrownBallIsBallisticFromAThirdOfASecond) {
  // The paper's baseball: 0.3 s of motion capture at 100 Hz (1 mm) before a 0.5 s dropout.
  const Eigen::Vector3d p0(0, 0, 1), v0(2, 0.5, 3), g(0, 0, -9.81);
  const PositionAt flight = [&](double t) {
    const double s = t - 4.7;
    return Eigen::Vector3d(p0 + v0 * s + 0.5 * g * s * s);
  };
  const auto prediction = predict_motion(history(100.0, 0.3, flight, still, 0.001, 0.005, 2),
                                         MotionPredictionOptions{});
  ASSERT_TRUE(prediction);
  EXPECT_EQ(prediction->translation_models[2], TranslationModel::kBallistic);
  // The velocity from 1 mm noise over <= 0.3 s is known to ~2 cm/s (4 sigma): 1 cm at 0.5 s.
  EXPECT_LT((prediction->position(0.5) - flight(5.5)).norm(), 0.01);
  // Without gravity as a candidate (here too short a history for a fitted acceleration at every
  // validation origin) the prediction is worse than with gravity known.
  MotionPredictionOptions no_gravity;
  no_gravity.ballistic = false;
  const auto fallback =
      predict_motion(history(100.0, 0.3, flight, still, 0.001, 0.005, 2), no_gravity);
  ASSERT_TRUE(fallback);
  EXPECT_GT((fallback->position(0.5) - flight(5.5)).norm(),
            (prediction->position(0.5) - flight(5.5)).norm());
}

TEST(MotionPrediction, GravityFollowsTheConfiguredUpAxis) {
  // y up (a camera frame): the ballistic model must fall along -y.
  const PositionAt flight = [](double t) {
    const double s = t - 4.7;
    return Eigen::Vector3d(1.0 * s, 2.0 * s - 4.905 * s * s, 0.0);
  };
  MotionPredictionOptions options;
  options.up = Eigen::Vector3d::UnitY();
  const auto prediction =
      predict_motion(history(100.0, 0.3, flight, still, 0.001, 0.005, 9), options);
  ASSERT_TRUE(prediction);
  EXPECT_EQ(prediction->translation_models[1], TranslationModel::kBallistic);
  // 30 samples over 0.3 s know the velocity to 2 mm/s per axis, under 1 mm at 0.4 s; the
  // constant-acceleration model's weight (its acceleration known to ~0.1 m/s^2) adds up to 1 cm.
  EXPECT_LT((prediction->position(0.4) - flight(5.4)).norm(), 0.015);
}

TEST(MotionPrediction, ARecentTurnIsFollowedNotTheWholeWindow) {
  // Moving at +0.3 m/s along x for 1.4 s, then back at -0.3 m/s for the last 0.6 s: a line over
  // the whole window says about +0.1 m/s, so 0.5 s on it would be +0.05 m.
  const PositionAt reversal = [](double t) {
    const double s = t - 3.0;
    return Eigen::Vector3d(s < 1.4 ? 0.3 * s : 0.42 - 0.3 * (s - 1.4), 0.0, 0.0);
  };
  const auto prediction = predict_motion(history(30.0, 2.0, reversal, still, 0.001, 0.01, 4),
                                         MotionPredictionOptions{});
  ASSERT_TRUE(prediction);
  // It goes back, as the object does now (-0.15 m in 0.5 s), hedged by the turn so recent that
  // holding still scored well too; the truth stays within two predicted sigmas.
  const double moved = prediction->position(0.5).x() - reversal(5.0).x();
  EXPECT_LT(moved, -0.05) << to_string(prediction->translation_models[0]);
  EXPECT_LT(std::abs(prediction->position(0.5).x() - reversal(5.5).x()),
            2.0 * std::sqrt(prediction->translation_variance(0.5).x()));
}

TEST(MotionPrediction, SpinIsExtrapolatedAboutTheRecentAxis) {
  const Eigen::Vector3d axis = Eigen::Vector3d(0.0, 1.0, 0.0);
  const OrientationAt spin = [&](double t) { return so3::exp(5.0 * t * axis); };
  const PositionAt roll = [](double t) { return Eigen::Vector3d(0.1 * t, 0.0, 0.02); };
  const auto samples = history(30.0, 2.0, roll, spin, 0.002, 0.01, 8);
  const auto prediction = predict_motion(samples, MotionPredictionOptions{});
  ASSERT_TRUE(prediction);
  EXPECT_EQ(prediction->rotation_model, RotationModel::kConstantAngularVelocity);
  // 5 rad/s for 0.5 s is 2.5 rad. The recent origins' weight (validation_memory) lets windows of
  // 0.8 s win as well as 1.6 s: over 0.8 s (24 samples of 0.01 rad) the rate is known to
  // 9 mrad/s per axis and the fit's end to 4 mrad, so 0.5 s ahead the error is ~10 mrad; 0.03 rad
  // is three of those. The prediction's own two sigmas cover it too.
  const double error = so3::angle_between(prediction->orientation(0.5), spin(5.5));
  EXPECT_LT(error, 0.03);
  EXPECT_LT(error, 2.0 * std::sqrt(prediction->rotation_variance(0.5)));
}

TEST(MotionPrediction, VarianceStartsAtZeroAndGrowsWithTimeHidden) {
  // A wandering object: the variance must grow with the horizon, and cover what the model
  // cannot know. Brownian velocity (0.5 m/s^2 / sqrt(Hz)) over 2 s at 30 Hz.
  Random random(21);
  Eigen::Vector3d v(0.1, 0.0, 0.0), p = Eigen::Vector3d::Zero();
  std::vector<Eigen::Vector3d> path;
  for (int k = 0; k < 61; ++k) {
    path.push_back(p);
    v += 0.5 * std::sqrt(1.0 / 30.0) * Eigen::Vector3d(random.normal(), random.normal(), 0.0);
    p += v / 30.0;
  }
  const PositionAt wander = [&](double t) {
    return path[static_cast<std::size_t>(std::lround((t - 3.0) * 30.0))];
  };
  const auto prediction =
      predict_motion(history(30.0, 2.0, wander, still, 0.002, 0.01, 1), MotionPredictionOptions{});
  ASSERT_TRUE(prediction);
  EXPECT_EQ(prediction->translation_variance(0.0).norm(), 0.0);
  double previous = 0.0;
  for (const double h : {0.1, 0.2, 0.4, 0.8}) {
    const double variance = prediction->translation_variance(h).sum();
    EXPECT_GT(variance, previous) << h;
    previous = variance;
  }
}

TEST(MotionPrediction, TooShortAHistoryPredictsNothing) {
  const PositionAt line = [](double t) { return Eigen::Vector3d(t, 0, 0); };
  EXPECT_FALSE(
      predict_motion(history(30.0, 0.1, line, still, 0.0, 0.0, 1), MotionPredictionOptions{}));
}

TEST(MotionPrediction, RecentVelocityIsTheSlopeOfTheLastWindow) {
  const Eigen::Vector3d axis = Eigen::Vector3d(0.0, 0.0, 1.0);
  const auto samples = history(
      30.0, 1.0, [](double t) { return Eigen::Vector3d(0.5 * t, 0.0, 0.0); },
      [&](double t) { return so3::exp(2.7 * t * axis); }, 0.0, 0.0, 1);
  const std::deque<MotionSample> recent(samples.begin(), samples.end());
  const auto velocity = recent_velocity(recent, 0.3);
  ASSERT_TRUE(velocity);
  EXPECT_LT((velocity->linear - Eigen::Vector3d(0.5, 0, 0)).norm(), 1e-9);
  EXPECT_LT((velocity->angular - 2.7 * axis).norm(), 1e-6);
}

// The drift's velocity is shrunk by v^2 / (v^2 + se^2). A still object measured at 10 Hz with
// 14 mm of noise (depth from apparent size): the least-squares slope of 4 samples is noise, its
// squared standard error estimated from 2 residual degrees of freedom; the shrunk slope's mean
// magnitude is 0.61 of the raw slope's (Monte Carlo of this estimator, 40 000 draws). A clear
// motion, 0.5 m/s with 2 mm noise at 30 Hz, keeps its speed (se/v = 1.3%: gain 0.9998).
TEST(MotionPrediction, RecentVelocityShrinksASlopeBuriedInNoise) {
  double raw_sum = 0.0, drift_sum = 0.0;
  for (std::uint64_t seed = 1; seed <= 400; ++seed) {
    const auto samples = history(
        10.0, 0.3, [](double) { return Eigen::Vector3d(0.3, 0.2, 1.0); }, still, 0.014, 0.0, seed);
    const std::deque<MotionSample> recent(samples.begin(), samples.end());
    const auto velocity = recent_velocity(recent, 0.3);
    ASSERT_TRUE(velocity);
    // The raw least-squares slope of the same samples, per axis.
    double tm = 0.0;
    for (const auto& s : samples) tm += s.t / 4.0;
    for (int axis = 0; axis < 3; ++axis) {
      double pm = 0.0, stt = 0.0, stp = 0.0;
      for (const auto& s : samples) pm += s.measured_position[axis] / 4.0;
      for (const auto& s : samples) {
        stt += (s.t - tm) * (s.t - tm);
        stp += (s.t - tm) * (s.measured_position[axis] - pm);
      }
      raw_sum += std::abs(stp / stt);
      drift_sum += std::abs(velocity->linear[axis]);
    }
  }
  EXPECT_GT(drift_sum / raw_sum, 0.52);
  EXPECT_LT(drift_sum / raw_sum, 0.70);

  double speed_sum = 0.0;
  for (std::uint64_t seed = 1; seed <= 50; ++seed) {
    const auto samples = history(
        30.0, 0.3, [](double t) { return Eigen::Vector3d(0.5 * t, 0.0, 0.0); }, still, 0.002, 0.0,
        seed);
    const auto velocity = recent_velocity({samples.begin(), samples.end()}, 0.3);
    ASSERT_TRUE(velocity);
    speed_sum += velocity->linear.x();
  }
  EXPECT_NEAR(speed_sum / 50.0, 0.5, 0.005);
}

// The samples' times and measured positions, as the fits and filters take them.
struct MeasuredSeries {
  std::vector<double> t;
  Eigen::Matrix3Xd position;
};

MeasuredSeries measured_series(const std::vector<MotionSample>& samples) {
  MeasuredSeries series{{}, Eigen::Matrix3Xd(3, static_cast<Eigen::Index>(samples.size()))};
  for (std::size_t k = 0; k < samples.size(); ++k) {
    series.t.push_back(samples[k].t);
    series.position.col(static_cast<Eigen::Index>(k)) = samples[k].measured_position;
  }
  return series;
}

// The constant-velocity fit's rate on each axis against the same robust line without the shrinkage
// (fitted here to the same samples): sums of |rate| over the axes the model was kept on.
struct RateSums {
  double shrunk = 0.0;
  double raw = 0.0;
};

// Sums the rates of the prediction's constant-velocity fits on `axes` (every axis by default),
// shrunk and as a plain least-squares line over the same window would have them.
void add_constant_velocity_rates(const std::vector<MotionSample>& samples,
                                 const MotionPrediction& prediction, RateSums& sums,
                                 std::initializer_list<int> axes = {0, 1, 2}) {
  const MeasuredSeries series = measured_series(samples);
  const std::vector<double>& t = series.t;
  const Eigen::Matrix3Xd& values = series.position;
  for (const int axis : axes)
    for (const WeightedFit& m : prediction.translation[static_cast<std::size_t>(axis)]) {
      if (m.fit.order != 1 || m.fit.known_acceleration.squaredNorm() > 0.0) continue;
      LocalPolynomial raw;
      ASSERT_TRUE(fit_local_polynomial(t, values, t.back() - m.window, t.back(), 1,
                                       Eigen::Vector3d::Zero(),
                                       MotionPredictionOptions{}.robust_iterations, raw));
      sums.shrunk += std::abs(m.fit.rate(prediction.t_last)(axis));
      sums.raw += std::abs(raw.rate(t.back())(axis));
    }
}

// A fitted constant velocity is shrunk by its significance, v^2 / (v^2 + se^2), as the velocity
// drift is: a still object whose size-read depth jitters by 14 mm at 10 Hz (a pedestrian's) is
// carried through a gap at a fraction of the noise's slope, while a clear motion keeps its speed.
TEST(MotionPrediction, AFittedRateBuriedInNoiseIsShrunk) {
  // The fitted lines alone: the wandering velocity's filter is no fit to shrink.
  MotionPredictionOptions options;
  options.wandering_velocity = false;
  RateSums noise;
  for (std::uint64_t seed = 1; seed <= 100; ++seed) {
    const auto samples = history(
        10.0, 2.0, [](double) { return Eigen::Vector3d(0.3, 0.2, 1.0); }, still, 0.014, 0.0, seed);
    const auto prediction = predict_motion(samples, options);
    ASSERT_TRUE(prediction);
    add_constant_velocity_rates(samples, *prediction, noise);
  }
  // For a slope that is pure noise, v ~ N(0, se^2), the shrunk |v| averages E|z|^3 / (z^2 + 1)
  // over E|z| = 0.57 of the raw one (z standard normal); 300 slopes know it to about +-0.03.
  EXPECT_GT(noise.shrunk / noise.raw, 0.50);
  EXPECT_LT(noise.shrunk / noise.raw, 0.67);
  RateSums clear;
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    const auto samples = history(
        30.0, 2.0, [](double t) { return Eigen::Vector3d(0.5 * t, 0.0, 0.0); }, still, 0.002, 0.0,
        seed);
    const auto prediction = predict_motion(samples, options);
    ASSERT_TRUE(prediction);
    add_constant_velocity_rates(samples, *prediction, clear, {0});  // the moving axis
  }
  // 0.5 m/s against a standard error of about 13 mm/s (0.2 s of 30 Hz, 2 mm): a gain of 0.999.
  EXPECT_GT(clear.shrunk / clear.raw, 0.997);
  EXPECT_LE(clear.shrunk / clear.raw, 1.0);
}

// Under gravity the line through the last 0.3 s has the velocity of its middle, 1.47 m/s behind
// the ball's: a thrown ball at 100 Hz with 1 mm noise gets the quadratic's velocity at the last
// sample instead (its curvature stands 10 standard errors out of the noise). A straight motion
// with the same noise keeps the line's slope (no curvature to find).
TEST(MotionPrediction, RecentVelocityOfAnAcceleratingObjectIsItsVelocityNow) {
  const auto thrown = [](double t) {
    return Eigen::Vector3d(2.0 * t, 0.0, 6.0 * t - 0.5 * 9.81 * t * t);
  };
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    const auto samples = history(100.0, 0.3, thrown, still, 0.001, 0.0, seed);
    const auto velocity = recent_velocity({samples.begin(), samples.end()}, 0.3);
    ASSERT_TRUE(velocity);
    // The true velocity at t = 5 s: (2, 0, 6 - 9.81 * 5); the quadratic's slope at the end has a
    // standard error of ~0.04 m/s here.
    EXPECT_NEAR(velocity->linear.z(), 6.0 - 9.81 * 5.0, 0.15) << seed;
    EXPECT_NEAR(velocity->linear.x(), 2.0, 0.05) << seed;
  }
  const auto samples = history(
      100.0, 0.3, [](double t) { return Eigen::Vector3d(0.5 * t, 0.0, 0.0); }, still, 0.001, 0.0,
      3);
  const auto velocity = recent_velocity({samples.begin(), samples.end()}, 0.3);
  ASSERT_TRUE(velocity);
  EXPECT_NEAR(velocity->linear.x(), 0.5, 0.02);
}

// A ball that starts rolling inside the history (still until 3.8 s, then 7 rad/s and 0.175 m/s,
// as general_op's ball does 1.2 s before the tray hides it): the step in angular velocity is one
// manoeuvre, not a wander that goes on. The spin is predicted (constant angular velocity) and
// the rotation's variance one second on stays under (0.3 rad)^2; read as a wander (the lagged
// second differences' plain variance, 7.6 rad^2/s^3 there) it was 2.5 rad^2, a spread of
// several radians over which the particles' mean is meaningless.
TEST(MotionPrediction, AStartInsideTheHistoryIsNotAWander) {
  const Eigen::Vector3d axis = Eigen::Vector3d::UnitX();
  const auto samples = history(
      30.0, 1.6, [](double t) { return Eigen::Vector3d(0.4, 0.175 * std::max(0.0, t - 3.8), 0); },
      [&](double t) { return so3::exp(7.0 * std::max(0.0, t - 3.8) * axis); }, 0.002, 0.01, 5);
  const auto prediction = predict_motion(samples, MotionPredictionOptions{});
  ASSERT_TRUE(prediction);
  EXPECT_EQ(prediction->rotation_model, RotationModel::kConstantAngularVelocity);
  EXPECT_LT(prediction->rotation_variance(1.0), 0.09);
  // Where it is one second on (t = 6 s: 7 x 2.2 rad turned), within 0.1 rad.
  const Eigen::Quaterniond truth = so3::exp(7.0 * 2.2 * axis);
  EXPECT_LT(so3::angle_between(prediction->orientation(1.0), truth), 0.1);
}

// A hand-moved object's velocity wanders: white random acceleration (0.05 m^2/s^3, about 0.2 m/s
// of velocity change per second) measured at 30 Hz with 1 mm noise. The wandering velocity's
// filters weigh the newest samples most, as the process asks, where the fitted lines weigh a window
// alike: 0.3 s into a gap they miss the object by less.
TEST(MotionPrediction, AWanderingVelocityIsFollowedByTheFilterThatModelsIt) {
  const double rate = 30.0, q = 0.05, h = 0.3, sigma = 0.001;
  MotionPredictionOptions lines;
  lines.wandering_velocity = false;
  double with_filter = 0.0, lines_only = 0.0, optimal = 0.0;
  for (std::uint64_t seed = 1; seed <= 200; ++seed) {
    // The truth from t = 3 s (2 s of history) to 5.3 s: a velocity step of sqrt(q / rate) per
    // frame and axis.
    Random random(seed + 1000);
    std::vector<Eigen::Vector3d> truth{Eigen::Vector3d::Zero()};
    Eigen::Vector3d velocity(0.2, -0.1, 0.0);
    for (int k = 1; k <= 69; ++k) {
      velocity +=
          std::sqrt(q / rate) * Eigen::Vector3d(random.normal(), random.normal(), random.normal());
      truth.push_back(truth.back() + velocity / rate);
    }
    const PositionAt at = [&](double t) {
      return truth[static_cast<std::size_t>(std::lround((t - 3.0) * rate))];
    };
    const auto samples = history(rate, 2.0, at, still, sigma, 0.0, seed);
    const auto with = predict_motion(samples, MotionPredictionOptions{});
    const auto without = predict_motion(samples, lines);
    ASSERT_TRUE(with && without);
    with_filter += (with->position(h) - at(5.0 + h)).squaredNorm();
    lines_only += (without->position(h) - at(5.0 + h)).squaredNorm();
    // The best there is: the filter told the true intensity and noise.
    const MeasuredSeries series = measured_series(samples);
    const auto told = wandering_velocity_filter(series.t, series.position,
                                                Eigen::Vector3d::Constant(sigma * sigma),
                                                Eigen::Vector3d::Constant(q));
    optimal += (told.back().line.value(5.0 + h) - at(5.0 + h)).squaredNorm();
  }
  // Root mean squared errors over 600 axis-gaps, paired (the same motions): 54 mm with the
  // filters, 63 mm with the lines alone, 41 mm for the told filter.
  EXPECT_LT(std::sqrt(with_filter / lines_only), 0.92);
  EXPECT_LT(std::sqrt(with_filter / optimal), 1.45);
  EXPECT_GT(std::sqrt(with_filter / optimal), 1.0);
}

// Beyond the 0.5 s the models are validated to, a hand that swings an object back and forth
// (5 cm, a 2 s period, 1 mm noise at 30 Hz) turns back within the second, while a line goes on.
// With the coast (the default), each axis's motion stops about where its validation says
// extrapolating stops paying: the swing is predicted better 1-1.5 s ahead, the line goes on.
TEST(MotionPrediction, BeyondTheValidationAMotionCoastsAsFarAsItsValidationSays) {
  const MotionPredictionOptions coasting;  // the default
  MotionPredictionOptions carried_on;
  carried_on.coast_beyond_validation = false;
  double coasted = 0.0, straight_on = 0.0;
  for (std::uint64_t seed = 1; seed <= 100; ++seed) {
    const double phase = 2.0 * std::numbers::pi * static_cast<double>(seed) / 100.0;
    const PositionAt swing = [&](double t) {
      return Eigen::Vector3d(0.05 * std::sin(std::numbers::pi * t + phase), 0.0, 0.0);
    };
    const auto samples = history(30.0, 2.0, swing, still, 0.001, 0.0, seed);
    const auto with = predict_motion(samples, coasting);
    const auto without = predict_motion(samples, carried_on);
    ASSERT_TRUE(with && without);
    for (const double h : {1.0, 1.5}) {
      coasted += (with->position(h) - swing(5.0 + h)).squaredNorm();
      straight_on += (without->position(h) - swing(5.0 + h)).squaredNorm();
    }
  }
  // RMS over 200 gaps' late frames: 93 mm coasted, 157 mm carried on.
  EXPECT_LT(std::sqrt(coasted / straight_on), 0.7);
  const PositionAt line = [](double t) { return Eigen::Vector3d(0.2 * t, 0.0, 0.0); };
  const auto samples = history(30.0, 2.0, line, still, 0.001, 0.0, 7);
  const auto with = predict_motion(samples, coasting);
  const auto without = predict_motion(samples, carried_on);
  ASSERT_TRUE(with && without);
  // Predicted to within the noise, the line does not coast at all; its still axes stop at the
  // horizon: 1.0 mm off at 1.5 s (1.4 mm carried on).
  EXPECT_EQ(with->coast.x(), std::numeric_limits<double>::infinity());
  EXPECT_EQ(with->coast.y(), 0.0);
  EXPECT_LT((with->position(1.5) - line(6.5)).norm(), 0.003);
}

// Beyond the validation horizon an axis that holds still is as uncertain as the object's track
// says it moves in the time held; an axis whose motion goes on keeps the growth its validation
// fitted. A line along x (predicted to within the noise: it goes on) whose y and z stop at the
// horizon, and a track that moved 0.1 m RMS in 0.5 s and 0.2 m in 1 s on every axis.
TEST(MotionPrediction, HeldStillBeyondTheValidationTheSpreadIsTheTracks) {
  const PositionAt line = [](double t) { return Eigen::Vector3d(0.2 * t, 0.0, 0.0); };
  const auto samples = history(30.0, 2.0, line, still, 0.001, 0.0, 7);
  const auto fitted = predict_motion(samples, MotionPredictionOptions{});
  ASSERT_TRUE(fitted);
  ASSERT_EQ(fitted->coast.x(), std::numeric_limits<double>::infinity());
  ASSERT_EQ(fitted->coast.y(), 0.0);
  MotionPrediction spread = *fitted;
  spread.track_spread = {{0.5, 1.0},
                         {Eigen::Vector3d::Constant(0.01), Eigen::Vector3d::Constant(0.04)}};
  const double horizon = fitted->validated_until - fitted->t_last;
  ASSERT_GT(horizon, 0.4);
  for (const double h : {0.5 * horizon, horizon})
    EXPECT_EQ(spread.translation_variance(h), fitted->translation_variance(h)) << h;
  const double h = horizon + 0.75;  // held 0.75 s: 0.025 m^2 more than at the horizon
  EXPECT_EQ(spread.translation_variance(h).x(), fitted->translation_variance(h).x());
  EXPECT_DOUBLE_EQ(spread.translation_variance(h).y(),
                   fitted->translation_variance(horizon).y() + 0.025);
  EXPECT_GT(spread.translation_variance(h).y(), 10.0 * fitted->translation_variance(h).y());
}

// The combination's sharpness k weighs each model as its validation error in excess of the
// noise to the power -k: at 0 every model and window of an axis weighs alike, and the best
// model's share falls from Bates and Granger's (k = 1) as k falls. A swing, where the models
// predict unequally well.
TEST(MotionPrediction, TheCombinationsSharpnessShrinksItsWeightsTowardsEqual) {
  const PositionAt swing = [](double t) {
    return Eigen::Vector3d(0.05 * std::sin(std::numbers::pi * t), 0.0, 0.0);
  };
  const auto samples = history(30.0, 2.0, swing, still, 0.001, 0.0, 3);
  const auto heaviest = [&](double sharpness) {
    MotionPredictionOptions options;
    // The same k whatever the validation shows.
    options.combination_sharpness = options.still_sharpness = sharpness;
    options.misspecified_noise_ratio = 0.0;
    options.misspecified_within = 0.0;  // every model shrunk alike
    const auto prediction = predict_motion(samples, options);
    EXPECT_TRUE(prediction);
    std::vector<double> weights;
    for (const WeightedFit& m : prediction->translation[0]) weights.push_back(m.weight);
    return std::pair(*std::max_element(weights.begin(), weights.end()),
                     *std::min_element(weights.begin(), weights.end()));
  };
  const auto [bates_granger, bates_granger_least] = heaviest(1.0);
  const auto [shrunk, shrunk_least] = heaviest(0.5);
  const auto [equal, equal_least] = heaviest(0.0);
  EXPECT_GT(bates_granger, 1.2 * shrunk);
  EXPECT_GT(shrunk, 1.2 * equal);
  EXPECT_LT(bates_granger_least, shrunk_least);
  EXPECT_DOUBLE_EQ(equal, equal_least);
}

// The weights of the models on `axis` under `options`.
std::vector<double> axis_weights(const std::vector<MotionSample>& samples,
                                 const MotionPredictionOptions& options, int axis) {
  const auto prediction = predict_motion(samples, options);
  EXPECT_TRUE(prediction);
  std::vector<double> weights;
  if (prediction)
    for (const WeightedFit& m : prediction->translation[static_cast<std::size_t>(axis)])
      weights.push_back(m.weight);
  return weights;
}

// Options whose sharpness is k whatever the validation shows.
MotionPredictionOptions sharpness_everywhere(double k) {
  MotionPredictionOptions options;
  options.combination_sharpness = options.misspecified_sharpness = options.still_sharpness = k;
  return options;
}

// The default weights on `axis` are the ones of sharpness `k` everywhere, and not those of `other`.
void expect_sharpness(const std::vector<MotionSample>& samples, int axis, double k, double other) {
  const std::vector<double> defaults = axis_weights(samples, MotionPredictionOptions{}, axis);
  const std::vector<double> expected = axis_weights(samples, sharpness_everywhere(k), axis);
  const std::vector<double> different = axis_weights(samples, sharpness_everywhere(other), axis);
  ASSERT_EQ(defaults.size(), expected.size());
  ASSERT_EQ(defaults.size(), different.size());
  ASSERT_GT(defaults.size(), 2u);
  double apart = 0.0;
  for (std::size_t c = 0; c < defaults.size(); ++c) {
    EXPECT_DOUBLE_EQ(defaults[c], expected[c]) << "model " << c;
    apart = std::max(apart, std::abs(defaults[c] - different[c]));
  }
  EXPECT_GT(apart, 0.01);
}

// The sharpness follows what the validation shows on each axis (30 Hz, 2 s of history):
// - an object at rest, measured with 2 mm noise: holding still predicts best, k = 2;
// - a line at 0.2 m/s with 2 mm noise, a motion the models describe: a constant velocity predicts
//   best, to within the noise's variance times 6, and keeps Bates and Granger's k = 1;
// - a drift with a 2 cm wobble at 1.5 Hz, measured to 0.1 mm: no model describes it, the best
//   misses by far more than twice that ratio, k = 0.5.
TEST(MotionPrediction, TheSharpnessFollowsWhatTheValidationShows) {
  const PositionAt rest = [](double) { return Eigen::Vector3d(0.5, 0.0, 0.02); };
  expect_sharpness(history(30.0, 2.0, rest, still, 0.002, 0.0, 5), 0, 2.0, 1.0);
  const PositionAt line = [](double t) { return Eigen::Vector3d(0.2 * t, 0.0, 0.0); };
  expect_sharpness(history(30.0, 2.0, line, still, 0.002, 0.0, 5), 0, 1.0, 0.5);
  const PositionAt wobble = [](double t) {
    return Eigen::Vector3d(0.3 * t + 0.02 * std::sin(3.0 * std::numbers::pi * t), 0.0, 0.0);
  };
  expect_sharpness(history(30.0, 2.0, wobble, still, 0.0001, 0.0, 5), 0, 0.5, 1.0);
}

// An object accelerating at 0.8 m/s^2, seen for 1 s at 100 Hz with 1 mm noise: the fits at the
// earliest validation origins have 0.2 s of history, their parameter error puts even the exact
// model's validation error far above the noise, and the weights are shrunk. Shrunk among the
// models near the best only, the prediction (RMS over 10 seeds, 0.2, 0.5 and 1 s ahead) stays
// within 1.25x of Bates and Granger's throughout (1.07x); shrinking every model alike lets the
// constant velocities, 0.4 m off after 1 s, take a tenth of the weight (3.1x).
TEST(MotionPrediction, ShrinkingSparesTheClearlyWorseModels) {
  const PositionAt accelerating = [](double t) {
    return Eigen::Vector3d(0.3 * t + 0.4 * t * t, 0.0, 0.0);
  };
  MotionPredictionOptions every_model;
  every_model.misspecified_within = 0.0;
  const auto rms = [&](const MotionPredictionOptions& options) {
    double sum = 0.0;
    for (std::uint64_t seed = 1; seed <= 10; ++seed) {
      const auto prediction =
          predict_motion(history(100.0, 1.0, accelerating, still, 0.001, 0.0, seed), options);
      EXPECT_TRUE(prediction);
      if (!prediction) continue;
      for (const double h : {0.2, 0.5, 1.0})
        sum += (prediction->position(h) - accelerating(5.0 + h)).squaredNorm();
    }
    return std::sqrt(sum / 30.0);
  };
  const double bates_granger = rms(sharpness_everywhere(1.0));
  EXPECT_LT(rms(MotionPredictionOptions{}), 1.25 * bates_granger);
  EXPECT_GT(rms(every_model), 2.0 * bates_granger);
}

// Fit windows as long as the history or longer are one fit: with 0.3 s of history the windows
// 0.2 and 0.4 s join (0.4 s fits the whole history), 0.8 and 1.6 s, the same fit again, do not.
TEST(MotionPrediction, WindowsLongerThanTheHistoryJoinOnce) {
  const PositionAt line = [](double t) { return Eigen::Vector3d(0.2 * t, 0.0, 0.0); };
  const auto prediction =
      predict_motion(history(30.0, 0.3, line, still, 0.002, 0.0, 5), MotionPredictionOptions{});
  ASSERT_TRUE(prediction);
  for (const auto& fits : prediction->translation) {
    std::vector<double> windows;
    for (const WeightedFit& m : fits) windows.push_back(m.window);
    EXPECT_EQ(std::count(windows.begin(), windows.end(), 0.8), 0);
    EXPECT_EQ(std::count(windows.begin(), windows.end(), 1.6), 0);
    EXPECT_GT(std::count(windows.begin(), windows.end(), 0.4), 0);
  }
}

// A walker's depth read from its apparent size swings with its gait: a 2 cm oscillation once a
// second about a steady mean, measured at 30 Hz with 1 mm noise. Over the first frames of a gap
// the current swing's velocity predicts it; half a swing on, only the mean does. Weighted per
// horizon, each model leads where it predicted best; one set of weights, judged mostly on the
// longer horizons (their errors are the larger), holds too soon.
TEST(MotionPrediction, EachHorizonIsLedByTheModelThatPredictedItBest) {
  const double rate = 30.0, amplitude = 0.02, period = 1.0, sigma = 0.001;
  // Without the coast beyond the validation horizon, whose length each combination reads from
  // its own errors there, and with Bates and Granger's weights throughout.
  MotionPredictionOptions by_horizon_options = sharpness_everywhere(1.0);
  by_horizon_options.coast_beyond_validation = false;
  MotionPredictionOptions one_set = by_horizon_options;
  one_set.weights_by_horizon = false;
  double near_by_horizon = 0.0, near_one_set = 0.0, far_difference = 0.0;
  for (std::uint64_t seed = 1; seed <= 100; ++seed) {
    const double phase = 2.0 * std::numbers::pi * static_cast<double>(seed) / 100.0;
    const PositionAt at = [&](double t) {
      return Eigen::Vector3d(0.0, 0.0,
                             amplitude * std::sin(2.0 * std::numbers::pi * t / period + phase));
    };
    const auto samples = history(rate, 2.0, at, still, sigma, 0.0, seed);
    const auto by_horizon = predict_motion(samples, by_horizon_options);
    const auto single = predict_motion(samples, one_set);
    ASSERT_TRUE(by_horizon && single);
    for (const double h : {0.1, 0.2}) {
      near_by_horizon += (by_horizon->position(h) - at(5.0 + h)).squaredNorm();
      near_one_set += (single->position(h) - at(5.0 + h)).squaredNorm();
    }
    // From the validation's horizon on, both use the weights judged on every error.
    far_difference =
        std::max(far_difference, (by_horizon->position(0.6) - single->position(0.6)).norm());
  }
  // RMS over 200 gaps' first frames: 10.1 mm per horizon, 11.5 mm with one set of weights.
  EXPECT_LT(std::sqrt(near_by_horizon / near_one_set), 0.9);
  EXPECT_LT(far_difference, 1e-12);
}

// A position that wanders by itself (a random walk, 3 mm per frame and axis at 30 Hz, as a
// detector's centroid drifting with the segmentation), measured with 1 mm noise: its variance
// grows in proportion to the time ahead. Fitted with h^2 and up only, the variance bends under
// the later horizons' errors and the first frames of a gap are the least covered; with the h term
// they are covered as the later ones.
TEST(MotionPrediction, APositionThatWandersIsCoveredFromTheFirstFrame) {
  const double rate = 30.0, step = 0.003, sigma = 0.001;
  MotionPredictionOptions without;
  without.diffusion_growth = false;
  int covered_with = 0, covered_without = 0, count = 0;
  std::vector<double> ratios;
  for (std::uint64_t seed = 1; seed <= 100; ++seed) {
    Random random(seed + 2000);
    std::vector<Eigen::Vector3d> truth{Eigen::Vector3d::Zero()};
    for (int k = 1; k <= 64; ++k)
      truth.push_back(truth.back() +
                      step * Eigen::Vector3d(random.normal(), random.normal(), random.normal()));
    const PositionAt at = [&](double t) {
      return truth[static_cast<std::size_t>(std::lround((t - 3.0) * rate))];
    };
    const auto samples = history(rate, 2.0, at, still, sigma, 0.0, seed);
    const auto with = predict_motion(samples, MotionPredictionOptions{});
    const auto off = predict_motion(samples, without);
    ASSERT_TRUE(with && off);
    for (int frame = 1; frame <= 3; ++frame) {
      const double h = frame / rate;
      const double error_with = (with->position(h) - at(5.0 + h)).norm();
      const double sd_with = std::sqrt(with->translation_variance(h).sum());
      covered_with += error_with <= 2.0 * sd_with;
      covered_without += (off->position(h) - at(5.0 + h)).norm() <=
                         2.0 * std::sqrt(off->translation_variance(h).sum());
      ratios.push_back(error_with / sd_with);
      ++count;
    }
  }
  std::nth_element(ratios.begin(), ratios.begin() + count / 2, ratios.end());
  const double median_ratio = ratios[static_cast<std::size_t>(count / 2)];
  // Of 300 first-three-frame errors within 2 sqrt(trace): 299 with the h term, 240 without; the
  // median error / sqrt(trace) with it is 0.63.
  EXPECT_GE(covered_with, 0.95 * count);
  EXPECT_LT(covered_without, 0.85 * count);
  EXPECT_GT(median_ratio, 0.25);  // not useless caution either
}

TEST(MotionPrediction, OptionsOutOfRangeAreRefused) {
  MotionPredictionOptions options;
  options.fit_windows = {};
  EXPECT_THROW(validate(options), std::invalid_argument);
  options = {};
  options.up = Eigen::Vector3d::Zero();
  EXPECT_THROW(validate(options), std::invalid_argument);
  options = {};
  options.uncertainty_scale = 0.0;
  EXPECT_THROW(validate(options), std::invalid_argument);
}

}  // namespace
}  // namespace opf
