#define _POSIX_C_SOURCE 199309L
/* Seeded random driver of the cagd C ABI fuzz harness (fuzz/capi/README.md).
 * Usage: cagd-capi-fuzz [--calls N] [--seed S] [--session N] [--quiet]
 * Environment: CAGD_FUZZ_CALLS and CAGD_FUZZ_SEED give the defaults of --calls / --seed
 * (the long mode is CAGD_FUZZ_CALLS=10000000). Exit 0 when every call passed the oracle;
 * a violation is printed and abort()s. */
#include "harness.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

static uint64_t parse_u64(const char *s, const char *what) {
    char *end = NULL;
    unsigned long long v = strtoull(s, &end, 0);
    if (end == s || *end != '\0') {
        fprintf(stderr, "cagd-capi-fuzz: %s: not a number: %s\n", what, s);
        exit(2);
    }
    return (uint64_t)v;
}

int main(int argc, char **argv) {
    uint64_t calls = 20000, seed = 20261126, session = 400;
    int verbose = 1;
    const char *e = getenv("CAGD_FUZZ_CALLS");
    if (e != NULL && *e != '\0') calls = parse_u64(e, "CAGD_FUZZ_CALLS");
    e = getenv("CAGD_FUZZ_SEED");
    if (e != NULL && *e != '\0') seed = parse_u64(e, "CAGD_FUZZ_SEED");
    for (int i = 1; i < argc; ++i) {
        if (strcmp(argv[i], "--calls") == 0 && i + 1 < argc) {
            calls = parse_u64(argv[++i], "--calls");
        } else if (strcmp(argv[i], "--seed") == 0 && i + 1 < argc) {
            seed = parse_u64(argv[++i], "--seed");
        } else if (strcmp(argv[i], "--session") == 0 && i + 1 < argc) {
            session = parse_u64(argv[++i], "--session");
        } else if (strcmp(argv[i], "--quiet") == 0) {
            verbose = 0;
        } else {
            fprintf(stderr,
                    "usage: %s [--calls N] [--seed S] [--session N] [--quiet]\n", argv[0]);
            return 2;
        }
    }
    struct timespec t0, t1;
    clock_gettime(CLOCK_MONOTONIC, &t0);
    uint64_t made = cagd_fuzz_run_seed(seed, calls, session, verbose);
    clock_gettime(CLOCK_MONOTONIC, &t1);
    double secs = (double)(t1.tv_sec - t0.tv_sec) + 1e-9 * (double)(t1.tv_nsec - t0.tv_nsec);
    printf("cagd C ABI fuzz: %llu calls over %zu functions, seed %llu, %.1f s, %llu oracle "
           "violations\n",
           (unsigned long long)made, cagd_fuzz_n_functions(), (unsigned long long)seed, secs,
           (unsigned long long)fz_violations);
    return fz_violations == 0 ? 0 : 1;
}
