// libFuzzer target for one loader: the input is a file with extension HOLEFILL_FUZZ_EXTENSION.
#include <cstdint>
#include <cstdio>
#include <cstdlib>

#include "fuzz_inputs.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string problem = holefill::fuzz::load_input(
      std::string(reinterpret_cast<const char*>(data), size), HOLEFILL_FUZZ_EXTENSION);
  if (!problem.empty()) {
    std::fprintf(stderr, "broken promise: %s\n", problem.c_str());
    std::abort();
  }
  return 0;
}
