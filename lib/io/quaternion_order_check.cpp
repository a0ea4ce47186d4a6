#include "opf/io/quaternion_order_check.h"

#include "opf/core/pose_conversion.h"

#include <Eigen/Geometry>

#include <cmath>
#include <map>

namespace opf {

std::vector<std::string> objects_with_w_first_quaternions(const MeasurementLog& log) {
  struct Sums {
    std::size_t count = 0;
    double first = 0.0;  // sum of |x| as read
    double last = 0.0;   // sum of |w| as read
  };
  std::map<std::string, Sums> sums;
  for (const Frame& frame : log.frames)
    for (const Detection& detection : frame.detections) {
      const Eigen::Quaterniond q = orientation_of(detection.pose);
      Sums& s = sums[detection.object];
      ++s.count;
      s.first += std::abs(q.x());
      s.last += std::abs(q.w());
    }
  std::vector<std::string> suspects;
  for (const std::string& object : log.objects) {
    const Sums& s = sums[object];
    if (s.count < kMinDetectionsForOrderCheck) continue;
    const double n = static_cast<double>(s.count);
    if (s.first / n >= 0.9 && s.last / n <= 0.3) suspects.push_back(object);
  }
  return suspects;
}

std::string w_first_warning(const std::string& object, LogFormat format) {
  std::string message = "object '" + object +
                        "': its quaternions, read as qx, qy, qz, qw, stay near (+-1, 0, 0, 0): "
                        "half a turn about x throughout, or a log in w, x, y, z order";
  if (format == LogFormat::kCsv)
    message += " (then read it with --columns qw=qx,qx=qy,qy=qz,qz=qw)";
  return message;
}

}  // namespace opf
