// Every seed input and every saved crash of the fuzz targets (tests/fuzz/corpus/<target>/ and
// tests/fuzz/regressions/<target>/) through the fuzzed entry points, in the regular build: each
// must be accepted or rejected with an InputError, never crash or break a reader's promise.

#include "fuzz_inputs.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <string>
#include <vector>

namespace opf {
namespace {

namespace fs = std::filesystem;

std::size_t replay(const std::string& target,
                   const std::function<void(const std::uint8_t*, std::size_t)>& entry) {
  std::size_t files = 0;
  for (const char* kind : {"corpus", "regressions"}) {
    const fs::path dir = fs::path(OPF_SOURCE_DIR) / "tests" / "fuzz" / kind / target;
    for (const auto& file : fs::directory_iterator(dir)) {
      if (!file.is_regular_file() || file.path().filename().string().front() == '.') continue;
      std::ifstream in(file.path(), std::ios::binary);
      const std::string bytes((std::istreambuf_iterator<char>(in)), {});
      EXPECT_NO_THROW(entry(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size()))
          << file.path();
      ++files;
    }
  }
  return files;
}

TEST(FuzzCorpus, MeasurementLogInputsAreAcceptedOrRejectedCleanly) {
  EXPECT_GE(replay("measurement_log", fuzz::measurement_log), 6u);
}

TEST(FuzzCorpus, EstimatorSettingsInputsAreAcceptedOrRejectedCleanly) {
  EXPECT_GE(replay("estimator_settings", fuzz::estimator_settings), 4u);
}

TEST(FuzzCorpus, ExperimentFileInputsAreAcceptedOrRejectedCleanly) {
  EXPECT_GE(replay("experiment_file", fuzz::experiment_file), 7u);
}

TEST(FuzzCorpus, SegmentationSpecInputsAreAcceptedOrRejectedCleanly) {
  EXPECT_GE(replay("segmentation_spec", fuzz::segmentation_spec), 3u);
}

TEST(FuzzCorpus, SweepFileInputsAreAcceptedOrRejectedCleanly) {
  EXPECT_GE(replay("sweep_file", fuzz::sweep_file), 11u);
}

}  // namespace
}  // namespace opf
