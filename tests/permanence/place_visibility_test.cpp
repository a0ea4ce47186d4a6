#include "opf/permanence/place_visibility.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace opf {
namespace {

const Eigen::Matrix3d kTight = Eigen::Matrix3d::Identity() * 1e-6;  // 1 mm std per axis
const Eigen::Vector3d kPlace(0.5, 0.0, 0.0);

double phi(double x) {
  return 0.5 * std::erfc(-x / std::sqrt(2.0));
}

TEST(PlaceVisibility, CoveringProbabilityIsPhiOfTheMarginOverTheSpreadAlongTheOffset) {
  const Eigen::Matrix2d spread = Eigen::Vector2d(1e-4, 4e-4).asDiagonal();  // 1 cm along x, 2 on y
  // On the edge: one half. Two standard deviations inside: Phi(2). Along y the spread is 2 cm.
  EXPECT_NEAR(covering_probability(Eigen::Vector2d(0.1, 0.0), spread, 0.1), 0.5, 1e-12);
  EXPECT_NEAR(covering_probability(Eigen::Vector2d(0.1, 0.0), spread, 0.12), phi(2.0), 1e-12);
  EXPECT_NEAR(covering_probability(Eigen::Vector2d(0.0, 0.1), spread, 0.12), phi(1.0), 1e-12);
  EXPECT_NEAR(covering_probability(Eigen::Vector2d(0.14, 0.0), spread, 0.1), phi(-4.0), 1e-12);
  // At a zero offset, the spread along the first axis.
  EXPECT_NEAR(covering_probability(Eigen::Vector2d::Zero(), spread, 0.01), phi(1.0), 1e-12);
}

// A cover of no stated size, its radius uniform on [0, R]: the mean of Phi((rho - |m|) / sigma)
// over rho, here by the midpoint rule over 20000 radii. With no spread, the share of radii beyond
// the offset, 1 - |m| / R.
TEST(PlaceVisibility, AnUnknownRadiusCoversByTheShareOfRadiiThatReachThePlace) {
  const Eigen::Matrix2d spread = Eigen::Vector2d(1e-4, 4e-4).asDiagonal();  // 1 cm along x, 2 on y
  constexpr double kR = 0.15;
  const auto by_midpoints = [&](const Eigen::Vector2d& offset) {
    constexpr int kN = 20000;
    double sum = 0.0;
    for (int i = 0; i < kN; ++i) sum += covering_probability(offset, spread, (i + 0.5) * kR / kN);
    return sum / kN;
  };
  for (const Eigen::Vector2d& offset :
       {Eigen::Vector2d(0.0, 0.0), Eigen::Vector2d(0.03, 0.0), Eigen::Vector2d(0.0, 0.1),
        Eigen::Vector2d(0.15, 0.0), Eigen::Vector2d(0.2, 0.0)})
    EXPECT_NEAR(covering_probability_of_unknown_radius(offset, spread, kR), by_midpoints(offset),
                1e-7)
        << offset.transpose();
  const Eigen::Matrix2d none = Eigen::Matrix2d::Identity() * 1e-20;
  EXPECT_NEAR(covering_probability_of_unknown_radius(Eigen::Vector2d(0.03, 0.0), none, kR), 0.8,
              1e-9);
  EXPECT_NEAR(covering_probability_of_unknown_radius(Eigen::Vector2d(0.0, 0.12), none, kR), 0.2,
              1e-9);
  EXPECT_EQ(covering_probability_of_unknown_radius(Eigen::Vector2d(0.2, 0.0), none, kR), 0.0);
  EXPECT_EQ(covering_probability_of_unknown_radius(Eigen::Vector2d(0.0, 0.0), spread, 0.0), 0.0);
}

TEST(PlaceVisibility, APlaceIsSeenWhenNoTrackedObjectIsNearItsLineOfSight) {
  const OccluderOptions top_down;  // no camera: the line of sight is -z
  const auto seen = [&](const std::vector<ViewBlocker>& blockers) {
    return seen_probability(kPlace, kTight, blockers, 0.08, top_down);
  };
  EXPECT_EQ(seen({}), 1.0);
  // A hand 5 cm across the line of sight, 12 cm above: within the 8 cm it hides.
  EXPECT_LT(seen({{Eigen::Vector3d(0.5, 0.05, 0.12), kTight}}), 1e-9);
  // 30 cm across: clear.
  EXPECT_GT(seen({{Eigen::Vector3d(0.5, 0.3, 0.12), kTight}}), 1.0 - 1e-9);
  // Under the place (the table, or an object below it) hides nothing.
  EXPECT_EQ(seen({{Eigen::Vector3d(0.5, 0.0, -0.2), kTight}}), 1.0);
  // Two on the edge each cover it half the time, independently: a quarter.
  EXPECT_NEAR(seen({{Eigen::Vector3d(0.58, 0.0, 0.1), Eigen::Matrix3d::Zero()},
                    {Eigen::Vector3d(0.42, 0.0, 0.1), Eigen::Matrix3d::Zero()}}),
              0.25, 1e-6);
}

TEST(PlaceVisibility, AnObliqueCameraLooksAlongItsOwnRay) {
  OccluderOptions oblique;
  oblique.camera_position = Eigen::Vector4d(0.5, -1.0, 1.0, 1.0);
  // On the ray from the camera to the place, 0.2 m away from it across the table: it hides the
  // place from this camera, though not from one straight above.
  const std::vector<ViewBlocker> on_the_ray = {{Eigen::Vector3d(0.5, -0.2, 0.2), kTight}};
  EXPECT_LT(seen_probability(kPlace, kTight, on_the_ray, 0.08, oblique), 1e-9);
  EXPECT_GT(seen_probability(kPlace, kTight, on_the_ray, 0.08, OccluderOptions{}), 1.0 - 1e-9);
}

TEST(PlaceVisibility, AStatedRadiusCoversInPlaceOfTheFallback) {
  const OccluderOptions top_down;
  const auto seen = [&](const ViewBlocker& blocker) {
    return seen_probability(kPlace, kTight, std::vector{blocker}, 0.08, top_down);
  };
  // A hand whose detector states a 0.1 m silhouette: 9 cm across covers the place though the
  // 8 cm fallback would not; 11 cm clears it, seven combined standard deviations (1.4 mm) out.
  const auto hand_at = [](double across, double radius) {
    return ViewBlocker{Eigen::Vector3d(0.5, across, 0.12), kTight, radius};
  };
  EXPECT_LT(seen(hand_at(0.09, 0.1)), 1e-9);
  EXPECT_GT(seen(hand_at(0.11, 0.1)), 1.0 - 1e-9);
  EXPECT_NEAR(seen(hand_at(0.1, 0.1)), 0.5, 1e-9);  // on the edge
  // A radius stated smaller than the fallback: 6 cm across is clear of a 4 cm cup.
  EXPECT_GT(seen(hand_at(0.06, 0.04)), 1.0 - 1e-9);
  EXPECT_LT(seen(hand_at(0.06, 0.0)), 1e-9);  // not stated: the fallback's 8 cm
  // Behind the place by more than its radius: hides nothing.
  EXPECT_EQ(seen({Eigen::Vector3d(0.5, 0.0, -0.2), kTight, 0.1}), 1.0);
}

// A cup hidden itself (under the hand that moves it), its estimate 5 cm off either way (its own
// motion extrapolated): over a place 2 cm from its centre, its 4.5 cm silhouette covers it only at
// Phi(2.5 / 5.0) = 0.69 as a stranger standing in the way. For the hypothesis that the place is
// carried by that cup, where the cup is does not matter, only their offset, known to 1 mm: it is
// covered (Phi(25)). Another object blocking the same place still counts with its spread.
TEST(PlaceVisibility, ACarrierCoversThePlaceItCarriesByTheirOffsetAlone) {
  const OccluderOptions top_down;
  const Eigen::Matrix3d lost = Eigen::Matrix3d::Identity() * 2.5e-3;  // 5 cm std per axis
  ViewBlocker cup{kPlace + Eigen::Vector3d(0.02, 0.0, 0.05), lost, 0.045};
  const double across = std::sqrt(2.5e-3 + 1e-6);  // the spreads combined
  EXPECT_NEAR(seen_probability(kPlace, kTight, std::vector{cup}, 0.08, top_down),
              1.0 - phi(0.025 / across), 1e-12);
  cup.carries_the_place = true;
  EXPECT_NEAR(seen_probability(kPlace, kTight, std::vector{cup}, 0.08, top_down),
              1.0 - phi(0.025 / 1e-3), 1e-12);
  const ViewBlocker stranger{kPlace + Eigen::Vector3d(-0.02, 0.0, 0.05), lost, 0.045};
  EXPECT_NEAR(seen_probability(kPlace, kTight, std::vector{cup, stranger}, 0.08, top_down),
              (1.0 - phi(0.025 / 1e-3)) * (1.0 - phi(0.025 / across)), 1e-12);
}

// A 14 cm square plate turned 45 degrees about the vertical, 12 cm above the place: its corners
// reach 9.9 cm from its centre along x and y, its sides 7 cm along the diagonals. Its stated box
// covers what its corners do and clears what lies past its sides, where the disc of its area
// (7.9 cm) says the opposite.
TEST(PlaceVisibility, AStatedBoxCoversWithItsCornersAndClearsPastItsSides) {
  const OccluderOptions top_down;
  const Eigen::Vector3d plate(0.14, 0.14, 0.04);
  const Eigen::Quaterniond turned(Eigen::AngleAxisd(M_PI / 4, Eigen::Vector3d::UnitZ()));
  const auto seen = [&](const Eigen::Vector3d& across, const Eigen::Vector3d& box) {
    const ViewBlocker hand{kPlace + across + Eigen::Vector3d(0, 0, 0.12), kTight, 0.079, box,
                           turned};
    return seen_probability(kPlace, kTight, std::vector{hand}, 0.08, top_down);
  };
  const Eigen::Vector3d under_a_corner(0.09, 0.0, 0.0);
  const Eigen::Vector3d past_a_side = 0.075 * Eigen::Vector3d(1, 1, 0).normalized();
  // 9 mm short of the corner: 6.4 mm inside both sides that meet there (1.4 mm combined spread).
  const double sigma = std::sqrt(2e-6);
  const double inside = (0.07 * std::sqrt(2.0) - 0.09) / std::sqrt(2.0);
  EXPECT_NEAR(seen(under_a_corner, plate), 1.0 - phi(inside / sigma), 1e-12);
  EXPECT_LT(seen(under_a_corner, plate), 1e-5);
  EXPECT_GT(seen(under_a_corner, Eigen::Vector3d::Zero()), 1.0 - 1e-9);     // the disc: 1.1 cm out
  EXPECT_NEAR(seen(past_a_side, plate), 1.0 - phi(-0.005 / sigma), 1e-12);  // 5 mm out
  EXPECT_GT(seen(past_a_side, plate), 0.99);
  EXPECT_NEAR(seen(past_a_side, Eigen::Vector3d::Zero()), 1.0 - phi(0.004 / sigma), 1e-12);
  // On a side's middle: on the edge, one half.
  EXPECT_NEAR(seen(0.07 * Eigen::Vector3d(1, 1, 0).normalized(), plate), 0.5, 1e-9);
}

// The particle filter's covariance of a measured object is the steady state of its random walk
// (0.05 m/sqrt(s), 30 Hz) under the configured 10 mm, 7.7 mm per axis; at the 2 mm a detector
// shows, 1.95 mm. What a hidden object's covariance has grown by stays; a covariance already
// below the steady state, or a detector noisier than configured, changes nothing to less.
TEST(PlaceVisibility, ACovarianceAtTheDetectorsNoiseLosesWhatTheConfiguredNoiseAdded) {
  const double q = 0.05 * 0.05 / 30.0;
  const auto steady = [q](double n) { return 0.5 * (-q + std::sqrt(q * q + 4.0 * q * n * n)); };
  EXPECT_NEAR(std::sqrt(steady(0.01)), 0.0077, 1e-4);
  EXPECT_NEAR(std::sqrt(steady(0.002)), 0.00195, 1e-5);
  const Eigen::Matrix3d measured = steady(0.01) * Eigen::Matrix3d::Identity();
  EXPECT_TRUE(at_detector_noise(measured, 0.01, 0.002, 0.05, 1.0 / 30)
                  .isApprox(steady(0.002) * Eigen::Matrix3d::Identity(), 1e-9));
  const Eigen::Matrix3d grown =
      measured + Eigen::Vector3d(4e-4, 1e-4, 0).asDiagonal().toDenseMatrix();
  EXPECT_TRUE(at_detector_noise(grown, 0.01, 0.002, 0.05, 1.0 / 30)
                  .isApprox(steady(0.002) * Eigen::Matrix3d::Identity() +
                                Eigen::Vector3d(4e-4, 1e-4, 0).asDiagonal().toDenseMatrix(),
                            1e-9));
  EXPECT_TRUE(at_detector_noise(1e-6 * Eigen::Matrix3d::Identity(), 0.01, 0.002, 0.05, 1.0 / 30)
                  .isApprox(steady(0.002) * Eigen::Matrix3d::Identity(), 1e-9));
  EXPECT_EQ(at_detector_noise(measured, 0.01, 0.02, 0.05, 1.0 / 30), measured);
}

TEST(PlaceVisibility, TheHidingRadiusIsTheOccludersOffsetWhenTheObjectWasLastSeenAtMostReach) {
  const OccluderOptions options;  // reach 0.15 m
  EXPECT_NEAR(hiding_radius(kPlace, Eigen::Vector3d(0.56, 0.08, 0.12), options), 0.1, 1e-12);
  EXPECT_EQ(hiding_radius(kPlace, Eigen::Vector3d(0.8, 0.0, 0.12), options), 0.15);
}

}  // namespace
}  // namespace opf
