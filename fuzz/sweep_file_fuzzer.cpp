// libFuzzer target: arbitrary bytes as a sweep file (fuzz_inputs.h).
#include "fuzz_inputs.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  opf::fuzz::sweep_file(data, size);
  return 0;
}
