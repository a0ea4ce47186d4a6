#pragma once
// Conversions between MRPT poses (the API boundary) and the Eigen translation + quaternion form
// the filters compute in.

#include <mrpt/poses/CPose3D.h>
#include <mrpt/poses/CPose3DPDFGaussian.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace opf {

Eigen::Vector3d translation_of(const mrpt::poses::CPose3D& pose);
Eigen::Quaterniond orientation_of(const mrpt::poses::CPose3D& pose);
mrpt::poses::CPose3D make_pose(const Eigen::Vector3d& translation,
                               const Eigen::Quaterniond& orientation);

/// d(yaw, pitch, roll) / d(delta) for the body-frame step pose * exp(delta): the Euler-angle
/// kinematics of MRPT's Z-Y-X convention (singular at pitch = +-pi/2).
Eigen::Matrix3d yaw_pitch_roll_jacobian(const mrpt::poses::CPose3D& pose);

/// A Gaussian pose in MRPT's (x, y, z, yaw, pitch, roll) parametrisation from a translation
/// covariance and an orientation covariance in the body-frame tangent space at `orientation`.
/// The tangent block is mapped to yaw-pitch-roll with the Jacobian at the mean (first order), and
/// translation and orientation are taken as uncorrelated (separate particle portions, paper III-A).
mrpt::poses::CPose3DPDFGaussian make_pose_pdf(const Eigen::Vector3d& translation,
                                              const Eigen::Matrix3d& translation_covariance,
                                              const Eigen::Quaterniond& orientation,
                                              const Eigen::Matrix3d& tangent_covariance);

}  // namespace opf
