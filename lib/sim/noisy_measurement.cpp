#include "opf/sim/noisy_measurement.h"

#include "opf/core/pose_conversion.h"
#include "opf/core/so3.h"

#include <stdexcept>

namespace opf::sim {

Frame noisy_measurement(const CameraFrame& camera, const SceneSnapshot& truth,
                        const MeasurementSettings& settings, Random& noise) {
  Frame frame{camera.t, {}};
  for (const Sighting& s : camera.sightings) {
    double draws[6];
    noise.fill_normal(draws);
    if (!measured(s, settings)) continue;
    std::size_t index = truth.bodies.size();
    for (std::size_t i = 0; i < truth.bodies.size(); ++i)
      if (truth.bodies[i].name == s.object) index = i;
    if (index == truth.bodies.size())
      throw std::invalid_argument("noisy_measurement: no body named '" + s.object + "'");
    const Eigen::Vector3d position =
        s.position + settings.position_noise * Eigen::Vector3d(draws[0], draws[1], draws[2]);
    const Eigen::Quaterniond orientation =
        truth.poses[index].orientation *
        so3::exp(settings.orientation_noise * Eigen::Vector3d(draws[3], draws[4], draws[5]));
    frame.detections.push_back({s.object, make_pose(position, orientation), s.partial_view_offset,
                                settings.state_sizes ? s.radius : 0.0,
                                settings.state_sizes ? s.box : Eigen::Vector3d::Zero()});
  }
  return frame;
}

}  // namespace opf::sim
