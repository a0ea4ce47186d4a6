#pragma once
// Calibration of a reported covariance against the truth: the normalised estimation error
// squared (NEES, Bar-Shalom, Li and Kirubarajan 2001, Sec. 5.4.2) of the position and of the
// orientation. For a consistent estimate the NEES of a 3-vector is chi-square with 3 degrees of
// freedom: mean 3, and at most kChiSquare3Dof95 in 95% of frames.

#include "opf/core/estimate.h"

#include <mrpt/poses/CPose3D.h>

namespace opf {

/// The 0.95 quantile of the chi-square distribution with 3 degrees of freedom.
inline constexpr double kChiSquare3Dof95 = 7.814727903251178;

/// e^T P^-1 e with e = p_est - p_true and P the estimate's 3x3 position covariance. +infinity
/// when P is not positive definite (a reported certainty the error contradicts).
double translation_nees(const Estimate& estimate, const mrpt::poses::CPose3D& truth);

/// The same for the orientation, in the body-frame tangent space of the estimate:
/// e = Log(R_est^T R_true), P = J^-1 P_ypr J^-T with J the yaw-pitch-roll Jacobian at the mean
/// (the inverse of the map the estimators report their covariance through). +infinity when P is
/// not positive definite or J is singular (pitch at +-pi/2).
double rotation_nees(const Estimate& estimate, const mrpt::poses::CPose3D& truth);

}  // namespace opf
