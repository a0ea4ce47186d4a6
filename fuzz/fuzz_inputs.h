#pragma once
// The fuzzed entry points: each takes arbitrary bytes as one user input file and must either
// accept it or throw InputError (the error that names file, line and field). Anything else, a
// crash, another exception, undefined behaviour, is a bug. libFuzzer drives them in the clang
// build (fuzz/CMakeLists.txt, scripts/run_fuzzers.sh); the test suite replays the corpus and
// every saved crash through them (tests/fuzz/fuzz_corpus_test.cpp).

#include <cstddef>
#include <cstdint>

namespace opf::fuzz {

/// A measurement log (io/measurement_log.h).
void measurement_log(const std::uint8_t* data, std::size_t size);

/// An estimator settings file (estimators/estimator_settings_yaml.h).
void estimator_settings(const std::uint8_t* data, std::size_t size);

/// An experiment file (sim/experiment_config.h).
void experiment_file(const std::uint8_t* data, std::size_t size);

/// A segmentation spec for `opf detect` (vision/segmentation_spec.h).
void segmentation_spec(const std::uint8_t* data, std::size_t size);

/// A sweep file of `opf sweep` (experiments/drivers/sweep_spec.h), as if it were
/// experiments/sweeps/fuzz.yaml of the source tree (its relative paths resolve there; a bare
/// experiment name is a bundled one, from $OPF_DATA_DIR or beside the program). A text that names
/// /proc, /sys or /dev is skipped: reading the machine's special files could block.
void sweep_file(const std::uint8_t* data, std::size_t size);

}  // namespace opf::fuzz
