// libFuzzer target: arbitrary bytes as an estimator settings file (fuzz_inputs.h).
#include "fuzz_inputs.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  opf::fuzz::estimator_settings(data, size);
  return 0;
}
