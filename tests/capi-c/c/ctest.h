/* Helpers of the C tests of cagd (STYLE §9.10): each test is `int cagd_ctest_<name>(void)`,
 * returns 0 on success and, on failure, prints the failing expression, the status name and
 * cagd_last_error_message() to stderr. Cleanup is by `goto cleanup` with NULL-safe frees. */
#ifndef CAGD_CTEST_H
#define CAGD_CTEST_H

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "cagd.h"

/* Fails the test (rc stays 1) when `expr` is false. */
#define CHECK(expr)                                                                  \
    do {                                                                             \
        if (!(expr)) {                                                               \
            fprintf(stderr, "%s:%d: CHECK failed: %s (last error: \"%s\")\n",        \
                    __FILE__, __LINE__, #expr, cagd_last_error_message());           \
            goto cleanup;                                                            \
        }                                                                            \
    } while (0)

/* Fails the test when `call` does not return `want`. */
#define CHECK_STATUS(call, want)                                                     \
    do {                                                                             \
        CagdStatus st_ = (call);                                                     \
        if (st_ != (want)) {                                                         \
            fprintf(stderr, "%s:%d: %s returned %s, expected %s (last error: \"%s\")\n", \
                    __FILE__, __LINE__, #call, cagd_status_name(st_),               \
                    cagd_status_name(want), cagd_last_error_message());              \
            goto cleanup;                                                            \
        }                                                                            \
    } while (0)

#define CHECK_OK(call) CHECK_STATUS(call, CAGD_OK)

/* Fails the test when |a - b| > tol. */
#define CHECK_NEAR(a, b, tol)                                                        \
    do {                                                                             \
        double a_ = (a), b_ = (b);                                                   \
        if (!(fabs(a_ - b_) <= (tol))) {                                             \
            fprintf(stderr, "%s:%d: %s = %.17g, expected %s = %.17g (tol %g)\n",     \
                    __FILE__, __LINE__, #a, a_, #b, b_, (double)(tol));              \
            goto cleanup;                                                            \
        }                                                                            \
    } while (0)

/* Fails the test when the last error message does not contain `needle`. */
#define CHECK_MESSAGE_HAS(needle) CHECK(strstr(cagd_last_error_message(), (needle)) != NULL)

#endif /* CAGD_CTEST_H */
