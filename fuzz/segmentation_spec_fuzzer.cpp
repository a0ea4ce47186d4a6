// libFuzzer target: arbitrary bytes as a segmentation spec for opf detect (fuzz_inputs.h).
#include "fuzz_inputs.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  opf::fuzz::segmentation_spec(data, size);
  return 0;
}
