#include "opf/particles/student_t_densities.h"

#include "opf/particles/likelihood_kernels.h"

#include <stdexcept>

namespace opf {

void student_t_log_densities(const kalman::StudentTNoise& t, int dimensions,
                             std::span<const double> determinants,
                             std::span<const double> squared_distances, std::span<double> out) {
  if (determinants.size() != out.size() || squared_distances.size() != out.size())
    throw std::invalid_argument(
        "student_t_log_densities: one determinant and one squared distance per density");
  kernels::student_t_log_densities(determinants.data(), squared_distances.data(), out.size(), t.dof,
                                   dimensions, t.log_normaliser, out.data());
}

}  // namespace opf
