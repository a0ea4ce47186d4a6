#include "opf/permanence/occluder_selection.h"

#include "opf/permanence/place_visibility.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include <limits>
#include <numbers>
#include <vector>

namespace opf {
namespace {

const Eigen::Matrix3d kCloud = Eigen::Matrix3d::Identity() * 1e-4;  // 1 cm std per axis

OccluderCandidate at(const std::string& name, double x, double y, double z) {
  return {name, Eigen::Vector3d(x, y, z), kCloud};
}

TEST(OccluderSelection, NearestCandidateIsTheOccluder) {
  const std::vector<OccluderCandidate> candidates = {at("right_mug", 0.4, -0.15, 0.03),
                                                     at("left_mug", 0.4, 0.09, 0.03),
                                                     at("tray", 0.55, -0.09, 0.2)};
  const auto choice = choose_occluders({0.4, 0.06, 0.0}, kCloud, candidates, OccluderOptions{});
  ASSERT_TRUE(choice.nearest);
  EXPECT_EQ(candidates[*choice.nearest].object, "left_mug");
  EXPECT_FALSE(choice.ambiguous());
}

TEST(OccluderSelection, TwoEquallyCloseCandidatesAreAmbiguous) {
  const std::vector<OccluderCandidate> candidates = {
      at("a", 0.4, 0.05, 0.03), at("b", 0.4, -0.05, 0.03), at("far", 0.9, 0.0, 0.03)};
  const auto choice = choose_occluders({0.4, 0.0, 0.0}, kCloud, candidates, OccluderOptions{});
  ASSERT_TRUE(choice.ambiguous());
  EXPECT_NEAR(choice.nearest_distance, choice.second_distance, 1e-9);
  EXPECT_NE(*choice.nearest, *choice.second);
  EXPECT_NE(candidates[*choice.nearest].object, "far");
  EXPECT_NE(candidates[*choice.second].object, "far");
}

TEST(OccluderSelection, EpsilonOccDecidesBetweenOneAndTwo) {
  // epsilon_occ is in metres: the means are 4.0 and 4.2 cm away across the line of sight (top
  // down: in x-y), a gap of 2 mm. Their D_B differ by 0.205 (1 cm clouds: d^2 / (8 * 1e-4)),
  // which says nothing of how close the call is in the scene.
  const std::vector<OccluderCandidate> candidates = {at("a", 0.04, 0.0, 0.0),
                                                     at("b", -0.042, 0.0, 0.0)};
  OccluderOptions options;
  options.epsilon_occ = 0.0019;
  auto choice = choose_occluders({0, 0, 0}, kCloud, candidates, options);
  EXPECT_FALSE(choice.ambiguous());
  EXPECT_NEAR(choice.nearest_offset, 0.040, 1e-12);
  EXPECT_NEAR(choice.second_offset, 0.042, 1e-12);
  options.epsilon_occ = 0.0021;
  choice = choose_occluders({0, 0, 0}, kCloud, candidates, options);
  EXPECT_TRUE(choice.ambiguous());
  EXPECT_EQ(candidates[*choice.nearest].object, "a");
  // The default, the paper's 0.01 read as metres: a 2 mm difference is a tie.
  EXPECT_TRUE(choose_occluders({0, 0, 0}, kCloud, candidates, OccluderOptions{}).ambiguous());
}

// With the gate every plausible candidate is weighed by the probability that it hides the
// object. These state no size: each may reach anywhere up to `reach` (0.15 m) across the line of
// sight, no extent more likely, so a candidate 5 cm off covers the object with probability about
// 1 - 5/15, one 8 cm off 1 - 8/15, one 15 cm off only by the offset's spread (1.4 cm: two 1 cm
// clouds), (sigma / R) phi(0) = 0.038; normalised, nearest first. 0.4 m away the gate turns the
// candidate away.
TEST(OccluderSelection, EveryPlausibleCandidateIsWeighedByHowLikelyItHidesTheObject) {
  const std::vector<OccluderCandidate> candidates = {
      at("edge", 0.0, 0.15, 0.0), at("near", 0.05, 0.0, 0.03), at("far", 0.4, 0.0, 0.0),
      at("next", -0.08, 0.0, 0.03)};
  const OccluderChoice choice = choose_occluders({0, 0, 0}, kCloud, candidates, {});
  ASSERT_EQ(choice.weighted.size(), 3u);
  EXPECT_EQ(candidates[choice.weighted[0].candidate].object, "near");
  EXPECT_EQ(candidates[choice.weighted[1].candidate].object, "next");
  EXPECT_EQ(candidates[choice.weighted[2].candidate].object, "edge");
  const Eigen::Matrix2d spread = Eigen::Matrix2d::Identity() * 2e-4;
  const auto covering = [&](double across) {
    return covering_probability_of_unknown_radius(Eigen::Vector2d(across, 0), spread, 0.15);
  };
  const double near = covering(0.05), next = covering(0.08), edge = covering(0.15);
  EXPECT_NEAR(near, 1.0 - 0.05 / 0.15, 1e-3);
  EXPECT_NEAR(edge, std::sqrt(2e-4) / 0.15 * std::numbers::inv_sqrtpi / std::numbers::sqrt2, 1e-4);
  EXPECT_NEAR(choice.weighted[0].probability, near / (near + next + edge), 1e-9);
  EXPECT_NEAR(choice.weighted[1].probability, next / (near + next + edge), 1e-9);
  EXPECT_NEAR(choice.weighted[2].probability, edge / (near + next + edge), 1e-9);
  // A floor of 25% leaves the two nearer ones, renormalised; at most one, the nearest alone.
  const std::vector<WeightedOccluder> two = probable_occluders(choice, 0.25, 4);
  ASSERT_EQ(two.size(), 2u);
  EXPECT_NEAR(two[0].probability + two[1].probability, 1.0, 1e-12);
  EXPECT_NEAR(two[1].probability, next / (near + next), 1e-9);
  const std::vector<WeightedOccluder> one = probable_occluders(choice, 0.0, 1);
  ASSERT_EQ(one.size(), 1u);
  EXPECT_EQ(candidates[one[0].candidate].object, "near");
  EXPECT_EQ(one[0].probability, 1.0);
  // The paper's rule (no gate) weighs nothing: the nearest, and a tie by epsilon_occ.
  OccluderOptions paper;
  paper.gate = false;
  EXPECT_TRUE(choose_occluders({0, 0, 0}, kCloud, candidates, paper).weighted.empty());
}

// A candidate whose size is stated hides the object within its own silhouette, not within
// `reach`: a grip of radius 3 cm, 6 cm off across the line of sight, is 2.1 sigma short of
// covering it (the offset's spread 1.4 cm: Phi(-2.1) = 0.017), a tray of radius 10 cm as far
// off covers it (Phi(2.8) = 0.998); without sizes both are within 0.15 m and equally likely.
TEST(OccluderSelection, AStatedSizeIsTheReachOfItsCover) {
  std::vector<OccluderCandidate> candidates = {at("grip", 0.06, 0.0, 0.2),
                                               at("tray", -0.06, 0.0, 0.2)};
  OccluderChoice choice = choose_occluders({0, 0, 0}, kCloud, candidates, {});
  ASSERT_EQ(choice.weighted.size(), 2u);
  EXPECT_NEAR(choice.weighted[0].probability, 0.5, 1e-6);
  candidates[0].radius = 0.03;
  candidates[1].radius = 0.10;
  choice = choose_occluders({0, 0, 0}, kCloud, candidates, {});
  ASSERT_EQ(choice.weighted.size(), 2u);
  const auto probability_of = [&](const std::string& name) {
    for (const WeightedOccluder& w : choice.weighted)
      if (candidates[w.candidate].object == name) return w.probability;
    return -1.0;
  };
  const auto phi = [](double z) { return 0.5 * std::erfc(-z / std::sqrt(2.0)); };
  const double spread = std::sqrt(2e-4), grip = phi(-0.03 / spread), tray = phi(0.04 / spread);
  EXPECT_NEAR(probability_of("grip"), grip / (grip + tray), 1e-9);
  EXPECT_NEAR(probability_of("tray"), tray / (grip + tray), 1e-9);
  // Beyond its size and three sigma, the gate turns it away.
  candidates[0].mean.x() = 0.08;
  EXPECT_EQ(choose_occluders({0, 0, 0}, kCloud, candidates, {}).weighted.size(), 1u);
}

TEST(OccluderSelection, LineOfSightNeedsTheCamera) {
  const std::vector<OccluderCandidate> candidates = {at("tray", 0.4, 0.0, 0.2)};
  OccluderOptions options;
  options.plane = OccluderPlane::kLineOfSight;
  EXPECT_THROW(choose_occluders({0.4, 0.0, 0.0}, kCloud, candidates, options),
               std::invalid_argument);
  // auto without a camera: a top-down camera, the x-y plane.
  options.plane = OccluderPlane::kAuto;
  const Eigen::MatrixXd p = occlusion_plane_projection({0.4, 0.0, 0.0}, options);
  ASSERT_EQ(p.rows(), 2);
  EXPECT_NEAR(std::abs(p.row(0).dot(Eigen::RowVector3d::UnitZ())), 0.0, 1e-12);
  EXPECT_NEAR(std::abs(p.row(1).dot(Eigen::RowVector3d::UnitZ())), 0.0, 1e-12);
}

TEST(OccluderSelection, LineOfSightIgnoresDepthAlongTheRay) {
  // A top-down camera: the tray 20 cm above the ball covers it; a mug beside it at the same
  // height does not, though it is closer in 3-D.
  const std::vector<OccluderCandidate> candidates = {at("tray", 0.4, 0.0, 0.2),
                                                     at("mug", 0.4, 0.12, 0.0)};
  OccluderOptions options;
  options.camera_position = Eigen::Vector4d(0.4, 0.0, 0.8, 1.0);
  const auto sight = choose_occluders({0.4, 0.0, 0.0}, kCloud, candidates, options);
  EXPECT_EQ(candidates[*sight.nearest].object, "tray");
  options.plane = OccluderPlane::k3D;
  const auto full = choose_occluders({0.4, 0.0, 0.0}, kCloud, candidates, options);
  EXPECT_EQ(candidates[*full.nearest].object, "mug");
}

TEST(OccluderSelection, ObliqueLineOfSightProjectsAlongTheRay) {
  // Camera off to the side: the occluder lies on the ray from the camera to the object.
  const Eigen::Vector3d camera(0.0, 0.0, 1.0), hidden(1.0, 0.0, 0.0);
  const Eigen::Vector3d on_ray = camera + 0.7 * (hidden - camera);
  const std::vector<OccluderCandidate> candidates = {
      at("on_ray", on_ray.x(), on_ray.y(), on_ray.z()), at("above", 1.0, 0.0, 0.25)};
  OccluderOptions options;
  options.camera_position = camera.homogeneous();
  const auto choice = choose_occluders(hidden, kCloud, candidates, options);
  EXPECT_EQ(candidates[*choice.nearest].object, "on_ray");
  const Eigen::MatrixXd p = occlusion_plane_projection(hidden, options);
  EXPECT_LT((p * (hidden - camera)).norm(), 1e-12);
  EXPECT_LT((p * p.transpose() - Eigen::Matrix2d::Identity()).norm(), 1e-12);
}

TEST(OccluderSelection, ACameraAtInfinitySeesEveryPointAlongOneRay) {
  // A log of `opf detect`: z is the depth away from the camera, every line of sight along +z:
  // the camera is at infinity towards -z, (0, 0, -1, 0).
  OccluderOptions options;
  options.camera_position = Eigen::Vector4d(0.0, 0.0, -1.0, 0.0);
  for (const Eigen::Vector3d& place : {Eigen::Vector3d(0.1, 0.2, 1.0), Eigen::Vector3d(-3, 5, 9)})
    EXPECT_LT((*line_of_sight(place, options) - Eigen::Vector3d::UnitZ()).norm(), 1e-15);
  // A cup 0.3 m nearer the camera (smaller depth) over the ball hides it; one 0.3 m deeper, at
  // the same image position, is behind it. Taken as straight down (-z) it would be the reverse.
  const std::vector<OccluderCandidate> nearer = {at("cup", 0.4, 0.0, 0.7)};
  const std::vector<OccluderCandidate> deeper = {at("cup", 0.4, 0.0, 1.3)};
  const Eigen::Vector3d ball(0.4, 0.0, 1.0);
  EXPECT_TRUE(choose_occluders(ball, kCloud, nearer, options).nearest);
  EXPECT_FALSE(choose_occluders(ball, kCloud, deeper, options).nearest);
  options.camera_position.reset();
  EXPECT_FALSE(choose_occluders(ball, kCloud, nearer, options).nearest);
  EXPECT_TRUE(choose_occluders(ball, kCloud, deeper, options).nearest);
  // The same as a camera far away on the axis, and as (0, 0, -2, 0): only the direction counts.
  options.camera_position = Eigen::Vector4d(0.4, 0.0, -1e6, 1.0);
  const Eigen::Vector3d far = *line_of_sight(ball, options);
  options.camera_position = Eigen::Vector4d(0.0, 0.0, -2.0, 0.0);
  EXPECT_LT((far - *line_of_sight(ball, options)).norm(), 1e-12);
}

TEST(OccluderSelection, NoCandidateNoOccluderOneCandidateIsIt) {
  EXPECT_FALSE(choose_occluders({0, 0, 0}, kCloud, {}, OccluderOptions{}).nearest);
  const std::vector<OccluderCandidate> one = {at("only", 0.1, 0.05, 0.1)};
  const auto choice = choose_occluders({0, 0, 0}, kCloud, one, OccluderOptions{});
  EXPECT_EQ(choice.nearest, 0u);
  EXPECT_FALSE(choice.ambiguous());
}

// The gate: 1 cm clouds, so the reach across the line of sight is 0.15 + 3 sqrt(2e-4) = 0.192 m.
TEST(OccluderSelection, TheGateTurnsAwayACandidateTooFarToHideTheObject) {
  const std::vector<OccluderCandidate> hand = {at("hand", 0.28, 0.0, 0.1)};
  const auto gated = choose_occluders({0, 0, 0}, kCloud, hand, OccluderOptions{});
  EXPECT_FALSE(gated.nearest);
  EXPECT_EQ(gated.implausible, 1u);
  // The paper's rule: the nearest candidate, however far.
  OccluderOptions paper;
  paper.gate = false;
  EXPECT_EQ(choose_occluders({0, 0, 0}, kCloud, hand, paper).nearest, 0u);
  // Just inside and just outside the reach.
  EXPECT_TRUE(choose_occluders({0, 0, 0}, kCloud, {{at("in", 0.19, 0.0, 0.1)}}, {}).nearest);
  EXPECT_FALSE(choose_occluders({0, 0, 0}, kCloud, {{at("out", 0.195, 0.0, 0.1)}}, {}).nearest);
  // A wide cloud widens the gate: 5 cm per axis adds 3 * sqrt(2.5e-3 + 1e-4) = 0.153 m.
  const Eigen::Matrix3d wide = Eigen::Matrix3d::Identity() * 2.5e-3;
  EXPECT_TRUE(choose_occluders({0, 0, 0}, wide, hand, {}).nearest);
}

TEST(OccluderSelection, TheGateLeavesOutACandidateBehindTheObjectAndKeepsThePlausibleOne) {
  // Top-down: the table-level mug 5 cm beside the ball can hide it only if it is not below it.
  const std::vector<OccluderCandidate> candidates = {at("below", 0.0, 0.05, -0.2),
                                                     at("above", 0.0, -0.08, 0.2)};
  const auto choice = choose_occluders({0, 0, 0}, kCloud, candidates, OccluderOptions{});
  ASSERT_TRUE(choice.nearest);
  EXPECT_EQ(candidates[*choice.nearest].object, "above");
  EXPECT_EQ(choice.implausible, 1u);
  EXPECT_FALSE(choice.ambiguous());
}

TEST(OccluderSelection, DegenerateOrNonFiniteCandidatesArePassedOverWithoutThrowing) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  std::vector<OccluderCandidate> candidates = {
      {"nan_mean", Eigen::Vector3d(nan, 0, 0), kCloud},
      {"inf_cov", Eigen::Vector3d(0.01, 0, 0.1),
       Eigen::Matrix3d::Identity() * std::numeric_limits<double>::infinity()},
      {"negative_cov", Eigen::Vector3d(0.02, 0, 0.1), -Eigen::Matrix3d::Identity()},
      at("good", 0.05, 0.0, 0.1)};
  OccluderChoice choice;
  ASSERT_NO_THROW(choice = choose_occluders({0, 0, 0}, kCloud, candidates, OccluderOptions{}));
  ASSERT_TRUE(choice.nearest);
  EXPECT_EQ(candidates[*choice.nearest].object, "good");
  EXPECT_FALSE(choice.ambiguous());
  // A hidden object with a broken estimate has no occluder (and no exception either).
  EXPECT_FALSE(choose_occluders({nan, 0, 0}, kCloud, candidates, OccluderOptions{}).nearest);
}

}  // namespace
}  // namespace opf
