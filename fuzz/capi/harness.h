/* The cagd C ABI fuzz harness (fuzz/capi/README.md): random call sequences over every
 * cagd_* function of include/cagd.h, with the "no silent garbage" oracle. One harness,
 * three drivers: a seeded random run (main.c: CI short run, valgrind run, long run), a
 * libFuzzer entry point (libfuzzer.c) and the cargo test of tests/capi-c (fuzz.rs). */
#ifndef CAGD_FUZZ_HARNESS_H
#define CAGD_FUZZ_HARNESS_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

/* Runs `calls` cagd calls driven by a xorshift generator seeded from `seed`, in sessions
 * of at most `session_calls` calls; every handle is freed at the end of each session.
 * Prints a per-function table (calls, CAGD_OK count) to stdout when `verbose`. On an
 * oracle violation prints the function, the session seed and the call index to stderr
 * and abort()s. Returns the number of calls made. */
uint64_t cagd_fuzz_run_seed(uint64_t seed, uint64_t calls, uint64_t session_calls,
                            int verbose);

/* Runs one session driven by `data` (libFuzzer): every decision consumes bytes; the
 * session ends when the bytes run out. Every handle is freed before returning. */
uint64_t cagd_fuzz_run_bytes(const uint8_t *data, size_t len);

/* Oracle violations counted in keep-going mode (CAGD_FUZZ_KEEP_GOING=1); 0 otherwise. */
extern uint64_t fz_violations;

/* The number of cagd_* functions the harness calls (for a sanity check by the drivers). */
size_t cagd_fuzz_n_functions(void);

#ifdef __cplusplus
}
#endif

#endif
