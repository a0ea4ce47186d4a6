#include "opf/permanence/bhattacharyya.h"

#include <Eigen/Cholesky>

#include <stdexcept>

namespace opf {
namespace {

double log_determinant(const Eigen::LLT<Eigen::MatrixXd>& factor) {
  return 2.0 * factor.matrixLLT().diagonal().array().log().sum();
}

Eigen::LLT<Eigen::MatrixXd> factorise(const Eigen::MatrixXd& covariance) {
  Eigen::LLT<Eigen::MatrixXd> factor(covariance);
  if (factor.info() != Eigen::Success)
    throw std::invalid_argument("bhattacharyya_distance: covariance is not positive definite");
  return factor;
}

}  // namespace

double bhattacharyya_distance(const Eigen::VectorXd& mean1, const Eigen::MatrixXd& covariance1,
                              const Eigen::VectorXd& mean2, const Eigen::MatrixXd& covariance2,
                              double regulariser) {
  const Eigen::Index n = mean1.size();
  if (mean2.size() != n || covariance1.rows() != n || covariance1.cols() != n ||
      covariance2.rows() != n || covariance2.cols() != n)
    throw std::invalid_argument("bhattacharyya_distance: dimensions differ");
  const Eigen::MatrixXd ridge = regulariser * Eigen::MatrixXd::Identity(n, n);
  const Eigen::MatrixXd s1 = covariance1 + ridge;
  const Eigen::MatrixXd s2 = covariance2 + ridge;
  const auto f1 = factorise(s1);
  const auto f2 = factorise(s2);
  const auto f = factorise(0.5 * (s1 + s2));
  const Eigen::VectorXd d = mean1 - mean2;
  const double mahalanobis = d.dot(f.solve(d));
  return 0.125 * mahalanobis +
         0.5 * (log_determinant(f) - 0.5 * (log_determinant(f1) + log_determinant(f2)));
}

}  // namespace opf
