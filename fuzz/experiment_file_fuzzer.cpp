// libFuzzer target: arbitrary bytes as an experiment file (fuzz_inputs.h).
#include "fuzz_inputs.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  opf::fuzz::experiment_file(data, size);
  return 0;
}
