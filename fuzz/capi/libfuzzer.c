/* libFuzzer entry point of the cagd C ABI fuzz harness (coverage-guided mode, see
 * fuzz/capi/README.md): the input bytes drive every decision of one session. */
#include "harness.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
    (void)cagd_fuzz_run_bytes(data, size);
    return 0;
}
