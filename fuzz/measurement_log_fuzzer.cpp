// libFuzzer target: arbitrary bytes as a measurement log (fuzz_inputs.h).
#include "fuzz_inputs.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  opf::fuzz::measurement_log(data, size);
  return 0;
}
