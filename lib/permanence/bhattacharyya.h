#pragma once
// Bhattacharyya distance between two Gaussians (paper Sec. III-B.2, Eq. 13), the occluder module's
// measure of how much the hidden object's cloud overlaps another object's.

#include <Eigen/Core>

namespace opf {

/// D_B = 1/8 dmu^T S^-1 dmu + 1/2 ln( det S / sqrt(det S1 det S2) ), S = (S1 + S2) / 2, computed
/// with Cholesky factors and log-determinants (no raw determinants, no square root on the
/// Mahalanobis term: the authors' code gets both wrong). `regulariser` * I is added to S1 and S2
/// so near-singular particle covariances (a collapsed cloud) stay well defined.
double bhattacharyya_distance(const Eigen::VectorXd& mean1, const Eigen::MatrixXd& covariance1,
                              const Eigen::VectorXd& mean2, const Eigen::MatrixXd& covariance2,
                              double regulariser = 1e-10);

}  // namespace opf
