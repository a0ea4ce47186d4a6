#include "opf/particles/student_t_densities.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

namespace opf {
namespace {

// The vectorised pass is the scalar density (linear_kalman.h) to a few ulp of its terms, in one
// dimension and in three, from a tiny innovation to an outlier 1e6 sigma out, at the lengths a
// vector loop splits into a body and a remainder.
TEST(StudentTDensities, AreTheScalarDensities) {
  for (const int dims : {1, 3}) {
    const kalman::StudentTNoise t =
        dims == 1 ? kalman::student_t_noise<1>(1.0) : kalman::student_t_noise<3>(4.0);
    for (const std::size_t n : {1u, 7u, 8u, 17u, 48u}) {
      std::vector<double> determinants, distances;
      for (std::size_t i = 0; i < n; ++i) {
        determinants.push_back(std::pow(10.0, -12.0 + 0.5 * static_cast<double>(i % 25)));
        distances.push_back(i % 5 == 4 ? 1e12 : 1e-9 * std::pow(7.0, static_cast<double>(i % 13)));
      }
      std::vector<double> out(n);
      student_t_log_densities(t, dims, determinants, distances, out);
      for (std::size_t i = 0; i < n; ++i) {
        const double expected =
            kalman::student_t_log_density(t, distances[i], std::log(determinants[i]), dims);
        EXPECT_NEAR(out[i], expected, 1e-14 * (1.0 + std::abs(expected))) << dims << " " << i;
      }
    }
  }
}

TEST(StudentTDensities, RefuseSpansOfDifferentSizes) {
  const std::vector<double> two(2, 1.0), three(3, 1.0);
  std::vector<double> out(2);
  EXPECT_THROW(student_t_log_densities(kalman::student_t_noise<1>(1.0), 1, two, three, out),
               std::invalid_argument);
}

}  // namespace
}  // namespace opf
