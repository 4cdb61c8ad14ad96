// libFuzzer entry point: the input bytes choose the operations and their parameters
// (tests/fuzz/operation_fuzzer.h) on a torus with irregular vertices and on a patch with a
// boundary. Build with -DFI_BUILD_LIBFUZZER=ON (clang), run e.g.
//   build-fuzz/tests/libfuzzer_operations -max_total_time=600
#include <cstdlib>

#include "operation_fuzzer.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  for (int which = 0; which < 2; ++which) {
    fuzz::TMesh m;
    if (which == 0) test::Icosphere(m, 2);
    else test::HexPatch(m, 5);
    fuzz::ByteChoices choices(data, size);
    fuzz::FuzzStats st = fuzz::OperationFuzzer(m, choices).Run(64);
    if (!st.ok()) {
      std::fprintf(stderr, "%s\n", st.failure.c_str());
      std::abort();
    }
  }
  return 0;
}
