#pragma once
// A point in homogeneous coordinates, as settings and command lines give a camera: three numbers
// are a point (w = 1); four end in w = 1 (the same) or w = 0, the point at infinity in the
// direction (x, y, z): a camera there sees every point along the same ray, an orthographic view
// (Hartley & Zisserman, Multiple View Geometry, 2nd ed., sec. 2.2.2). Another w is refused as
// more likely a mistake (four numbers meant as something else) than a scaled point.

#include <Eigen/Core>

#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace opf {

/// (x, y, z, w) from three numbers (w = 1) or four; none when there are not three or four, one
/// is not finite, w is neither 0 nor 1, or a point at infinity has no direction.
std::optional<Eigen::Vector4d> homogeneous_point(std::span<const double> numbers);

/// The same from the text a command line gives, "X,Y,Z" or "X,Y,Z,W" (empty parts skipped); none
/// also when a part is not wholly a number.
std::optional<Eigen::Vector4d> homogeneous_point_from_text(const std::string& text);

/// The words an error message expects for a camera given that way.
inline constexpr std::string_view kHomogeneousCameraExpectation =
    "X,Y,Z in metres (a camera there) or X,Y,Z,0 (a camera infinitely far in the direction "
    "X,Y,Z: parallel lines of sight)";

}  // namespace opf
