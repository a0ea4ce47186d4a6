#include "opf/core/error_accumulator.h"

#include <gtest/gtest.h>

namespace opf {
namespace {

Estimate estimate_at(double x, EstimateMode mode) {
  Estimate e;
  e.pose = mrpt::poses::CPose3DPDFGaussian(mrpt::poses::CPose3D(x, 0, 0, 0, 0, 0));
  e.mode = mode;
  return e;
}

TEST(ErrorAccumulator, MeansOverAllFramesAndOverUnobservedFrames) {
  ErrorAccumulator errors;
  const mrpt::poses::CPose3D truth(0, 0, 0, 0.1, 0, 0);
  errors.add(estimate_at(0.1, EstimateMode::kMeasured), truth);
  errors.add(estimate_at(0.3, EstimateMode::kPredicted), truth);
  errors.add(estimate_at(0.5, EstimateMode::kPredicted), truth);
  const RunErrors r = errors.result();
  EXPECT_EQ(r.frames, 3u);
  EXPECT_EQ(r.unobserved_frames, 2u);
  EXPECT_NEAR(r.translation, 0.3, 1e-15);
  EXPECT_NEAR(r.translation_unobserved, 0.4, 1e-15);
  EXPECT_NEAR(r.rotation_paper, 0.1, 1e-12);
  EXPECT_NEAR(r.rotation_geodesic, 0.1, 1e-12);
}

TEST(ErrorAccumulator, EmptyRunIsAnError) {
  EXPECT_THROW(ErrorAccumulator().result(), std::logic_error);
}

}  // namespace
}  // namespace opf
