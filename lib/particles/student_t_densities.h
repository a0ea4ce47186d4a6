#pragma once
// The Student-t log-densities of many innovations at once (core/linear_kalman.h's
// student_t_log_density, each from det S and d^2 = r^T S^-1 r): what the motion-model banks weigh
// their members by every frame. One vectorised pass (likelihood_kernels.h), where libm's log and
// log1p, two per member, cost more than the members' updates themselves.

#include "opf/core/linear_kalman.h"

#include <span>

namespace opf {

/// out[i] = log t_dof(r_i; 0, S_i) in `dimensions` dimensions (those `t` was made for), from
/// determinants[i] = det S_i (positive) and squared_distances[i] = d_i^2; to about one ulp of the
/// log of each term. Throws std::invalid_argument unless the three spans have one size.
void student_t_log_densities(const kalman::StudentTNoise& t, int dimensions,
                             std::span<const double> determinants,
                             std::span<const double> squared_distances, std::span<double> out);

}  // namespace opf
