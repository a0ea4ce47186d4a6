#include "opf/particles/particle_portion.h"

#include "opf/particles/resampling_kernels.h"

#include <stdexcept>
#include <utility>

namespace opf {

template <int Dim, class Scalar>
void ParticlePortion<Dim, Scalar>::resample(const std::vector<std::size_t>& indices) {
  if (!indices.empty() && kernels::largest_index(indices.data(), indices.size()) >= size())
    throw std::out_of_range("ParticlePortion::resample: bad index");
  // A fresh matrix rather than a kept spare: freed and allocated again step after step, the
  // same memory serves every filter on a thread and stays in cache across an ensemble.
  States next(Dim, Eigen::Index(indices.size()));
  kernels::gather_rows(states.data(), size(), Dim, indices.data(), indices.size(), next.data());
  if (columns.rows() > 0) {
    Columns moved(columns.rows(), Eigen::Index(indices.size()));
    kernels::gather_rows(columns.data(), size(), std::size_t(columns.rows()), indices.data(),
                         indices.size(), moved.data());
    columns = std::move(moved);
  }
  states = std::move(next);
  weights = LogWeights(indices.size());
}

template <int Dim, class Scalar>
void ParticlePortion<Dim, Scalar>::resample_systematic(const std::vector<float>& relative,
                                                       double offset) {
  if (relative.size() != size())
    throw std::invalid_argument("ParticlePortion::resample_systematic: one weight per particle");
  if (columns.rows() > 0)
    throw std::logic_error("ParticlePortion::resample_systematic: the columns need resample()");
  States next(Dim, states.cols());
  kernels::systematic_resample(relative.data(), size(), offset, states.data(), Dim, next.data());
  states = std::move(next);
  weights.reset();
}

template struct ParticlePortion<3>;
template struct ParticlePortion<4>;

}  // namespace opf
