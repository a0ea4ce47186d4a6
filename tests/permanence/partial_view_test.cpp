#include "opf/permanence/partial_view.h"

#include "opf/core/pose_conversion.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

namespace opf {
namespace {

Estimate estimate_at(const std::string& object, const Eigen::Vector3d& position) {
  Estimate e;
  e.object = object;
  e.pose.mean = make_pose(position, Eigen::Quaterniond::Identity());
  return e;
}

// The centroid of the part of a unit disc beyond a straight edge at distance c from its centre
// (the visible part), by numerical integration: its distance from the centre and the visible share.
std::pair<double, double> visible_centroid(double c) {
  const int n = 4000;
  double area = 0.0, moment = 0.0;
  for (int i = 0; i < n; ++i) {
    const double x = -1.0 + (i + 0.5) * 2.0 / n;
    if (x < c) continue;  // covered
    const double chord = 2.0 * std::sqrt(1.0 - x * x);
    area += chord * 2.0 / n;
    moment += x * chord * 2.0 / n;
  }
  return {moment / area, area / std::numbers::pi};
}

TEST(PartialView, TheCentroidShareHoldsForADiscUnderAStraightEdge) {
  // (1 - f) r is what a detector states; the centroid lies 0.85-0.93 of it from the centre for
  // every visible share from 5% to 95%: the constant's 0.87 is within 7% of each.
  for (double c = -0.9; c <= 0.9; c += 0.1) {
    const auto [offset, f] = visible_centroid(c);
    if (f < 0.05 || f > 0.95) continue;
    const double share = offset / (1.0 - f);
    EXPECT_GT(share, 0.84) << c;
    EXPECT_LT(share, 0.94) << c;
    EXPECT_NEAR(kPartialViewCentroidShare, share, 0.07) << c;
  }
}

TEST(PartialView, TheCorrectionPointsAwayFromTheCoversNearerTheCamera) {
  const OccluderOptions top_down;  // the line of sight is -z; reach 0.15 m
  const Eigen::Vector3d ball(0.5, 0.0, 0.0);
  // A hand 5 cm off in +y and 10 cm above: the visible part lies towards -y.
  std::vector<Estimate> estimates = {estimate_at("ball", ball),
                                     estimate_at("hand", {0.5, 0.05, 0.1})};
  const Frame frame;  // no detection states a radius: any object within reach covers
  EnsembleView view{frame, estimates};
  const auto away = away_from_cover(ball, 0.01, "ball", view, top_down);
  ASSERT_TRUE(away);
  EXPECT_NEAR((*away - Eigen::Vector3d(0, -1, 0)).norm(), 0.0, 1e-12);
  const PartialViewCentre centre = partial_view_centre(ball, 0.01, "ball", view, top_down);
  EXPECT_NEAR((centre.position - Eigen::Vector3d(0.5, 0.0087, 0.0)).norm(), 0.0, 1e-12);
  EXPECT_EQ(centre.known_share, kPartialViewCentroidShare);
  // No stated extra noise: the detection as it is, nothing known.
  EXPECT_EQ(partial_view_centre(ball, 0.0, "ball", view, top_down).position, ball);
  EXPECT_EQ(partial_view_centre(ball, 0.0, "ball", view, top_down).known_share, 0.0);
  // A cover within the extra noise of the centre leaves a ring in view: no direction.
  estimates[1] = estimate_at("hand", {0.5, 0.005, 0.1});
  EXPECT_FALSE(away_from_cover(ball, 0.01, "ball", view, top_down));
  // An object under the ball (further from the camera) covers nothing of it; one beyond reach
  // across the line of sight neither.
  estimates[1] = estimate_at("table", {0.5, 0.05, -0.1});
  EXPECT_FALSE(away_from_cover(ball, 0.01, "ball", view, top_down));
  estimates[1] = estimate_at("hand", {0.5, 0.2, 0.1});
  EXPECT_FALSE(away_from_cover(ball, 0.01, "ball", view, top_down));
}

TEST(PartialView, CoversOnSeveralSidesAverageAndOppositeOnesCancel) {
  const OccluderOptions top_down;
  const Eigen::Vector3d ball(0.5, 0.0, 0.0);
  // Two mugs' rims closing in from either side: the visible part stays centred.
  std::vector<Estimate> estimates = {estimate_at("mug_a", {0.5, 0.05, 0.05}),
                                     estimate_at("mug_b", {0.5, -0.05, 0.05})};
  const Frame frame;
  const EnsembleView view{frame, estimates};
  EXPECT_FALSE(away_from_cover(ball, 0.01, "ball", view, top_down));
  // At right angles: half of each direction, and a share of 0.87 / sqrt(2) known.
  estimates[1] = estimate_at("mug_b", {0.45, 0.0, 0.05});
  const auto away = away_from_cover(ball, 0.01, "ball", view, top_down);
  ASSERT_TRUE(away);
  EXPECT_NEAR((*away - Eigen::Vector3d(0.5, -0.5, 0)).norm(), 0.0, 1e-12);
  EXPECT_NEAR(partial_view_centre(ball, 0.01, "ball", view, top_down).known_share,
              kPartialViewCentroidShare / std::sqrt(2.0), 1e-12);
  // With the radii stated (as the detections last stated them, mug B's while it is itself
  // hidden), only an object whose silhouette overlaps the ball's covers it: mug A 5 cm off with
  // 2 cm + 2.5 cm radii does not, mug B (4.5 cm + 2.5 cm) does.
  const std::vector<StatedRadius> radii = {{"ball", 0.025}, {"mug_a", 0.02}, {"mug_b", 0.045}};
  const EnsembleView sized_view{frame, estimates, radii};
  const auto sized = away_from_cover(ball, 0.01, "ball", sized_view, top_down);
  ASSERT_TRUE(sized);
  EXPECT_NEAR((*sized - Eigen::Vector3d(1, 0, 0)).norm(), 0.0, 1e-12);
}

TEST(PartialView, NoLineOfSightNoDirection) {
  OccluderOptions in_3d;
  in_3d.plane = OccluderPlane::k3D;
  const std::vector<Estimate> estimates = {estimate_at("hand", {0.5, 0.05, 0.1})};
  const Frame frame;
  const EnsembleView view{frame, estimates};
  EXPECT_FALSE(away_from_cover({0.5, 0.0, 0.0}, 0.01, "ball", view, in_3d));
}

}  // namespace
}  // namespace opf
