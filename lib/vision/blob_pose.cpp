#include "opf/vision/blob_pose.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace opf::vision {

double principal_axis_angle(const cv::Moments& moments) {
  return 0.5 * std::atan2(2.0 * moments.mu11, moments.mu20 - moments.mu02);
}

double unwrap_half_turn(double angle, double previous) {
  return angle + std::numbers::pi * std::round((previous - angle) / std::numbers::pi);
}

double median_reference_area(std::span<const BlobSighting> sightings, std::size_t count) {
  if (sightings.empty() || count == 0)
    throw std::invalid_argument("reference area: no sightings to take the median of");
  std::vector<double> areas;
  for (std::size_t i = 0; i < std::min(count, sightings.size()); ++i)
    areas.push_back(sightings[i].area_px);
  std::sort(areas.begin(), areas.end());
  const std::size_t n = areas.size();
  return n % 2 == 1 ? areas[n / 2] : 0.5 * (areas[n / 2 - 1] + areas[n / 2]);
}

std::vector<BlobPose> blob_poses(std::span<const BlobSighting> sightings,
                                 const BlobPoseOptions& options) {
  if (!(options.metres_per_pixel > 0.0) || !(options.reference_depth > 0.0))
    throw std::invalid_argument("blob pose: metres_per_pixel and reference_depth must be > 0");
  std::vector<BlobPose> poses;
  if (sightings.empty()) return poses;
  const double reference_area = options.reference_area
                                    ? *options.reference_area
                                    : median_reference_area(sightings, options.reference_frames);
  if (!(reference_area > 0.0))
    throw std::invalid_argument("blob pose: the reference area must be > 0");
  poses.reserve(sightings.size());
  for (const BlobSighting& s : sightings) {
    if (!(s.area_px > 0.0))
      throw std::invalid_argument("blob pose: a sighting at frame " + std::to_string(s.frame) +
                                  " has no area");
    BlobPose pose;
    pose.frame = s.frame;
    pose.position = Eigen::Vector3d(
        s.centroid_px.x * options.metres_per_pixel, s.centroid_px.y * options.metres_per_pixel,
        options.reference_depth * std::sqrt(reference_area / s.area_px));
    pose.angle = poses.empty() ? s.axis_angle : unwrap_half_turn(s.axis_angle, poses.back().angle);
    pose.orientation = Eigen::Quaterniond(Eigen::AngleAxisd(pose.angle, Eigen::Vector3d::UnitZ()));
    if (pose.orientation.w() < 0.0) pose.orientation.coeffs() *= -1.0;
    poses.push_back(pose);
  }
  return poses;
}

}  // namespace opf::vision
