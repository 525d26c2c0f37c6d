/* The batch calls cagd_bezier_reduce_batch and cagd_bezier_elevate_batch: both layouts and
 * 0..3 threads give the bits of cagd_curve_reduce_batch, of the single-curve flat calls and
 * of the handle API (point-major reduction: up to rounding, its sums run in another order
 * than the GEMM kernel's); size queries, short buffers, NULLs, bad input. */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>

#include "ctest.h"

enum { K = 3000, N1 = 10, DIM = 3 }; /* 3000 curves of degree 9 in 3D: several blocks */

/* Deterministic coordinates in [-1, 1). */
static void fill(double *x, size_t n) {
    uint64_t s = 0x9E3779B97F4A7C15u;
    size_t i;
    for (i = 0; i < n; ++i) {
        s = s * 6364136223846793005u + 1442695040888963407u;
        x[i] = (double)(s >> 11) / 4503599627370496.0 - 1.0;
    }
}

/* Curve-major -> point-major of `k` curves of `n1` points (and back with `back`). */
static void transpose(const double *in, double *out, size_t k, size_t n1, int back) {
    size_t c, j, d;
    for (c = 0; c < k; ++c)
        for (j = 0; j < n1; ++j)
            for (d = 0; d < DIM; ++d) {
                size_t cm = (c * n1 + j) * DIM + d, pm = (j * k + c) * DIM + d;
                if (back) out[cm] = in[pm];
                else out[pm] = in[cm];
            }
}

int cagd_ctest_flat_batch_reduce_layouts(void) {
    int rc = 1;
    const size_t m1 = 6, out_len = (size_t)K * 6 * DIM;
    double *cm = malloc(sizeof(double) * K * N1 * DIM), *pm = malloc(sizeof(double) * K * N1 * DIM);
    double *ref = malloc(sizeof(double) * out_len), *out = malloc(sizeof(double) * out_len);
    double *back = malloc(sizeof(double) * out_len), one[6 * DIM];
    CagdReduceOptions o;
    size_t needed = 0, t, c;

    CHECK(cm && pm && ref && out && back);
    fill(cm, (size_t)K * N1 * DIM);
    transpose(cm, pm, K, N1, 0);
    CHECK_OK(cagd_reduce_options_init(&o));
    o.target = 5;
    o.r = 1;
    o.p = 1;
    CHECK_OK(cagd_curve_reduce_batch(cm, K, 9, DIM, &o, ref, out_len, &needed));
    CHECK(needed == out_len);
    for (t = 0; t <= 3; ++t) {
        memset(out, 0, sizeof(double) * out_len);
        CHECK_OK(cagd_bezier_reduce_batch(cm, K, 9, DIM, CAGD_LAYOUT_CURVE_MAJOR, &o, t, out,
                                          out_len, &needed));
        CHECK(needed == out_len);
        CHECK(memcmp(out, ref, sizeof(double) * out_len) == 0);
        memset(out, 0, sizeof(double) * out_len);
        CHECK_OK(cagd_bezier_reduce_batch(pm, K, 9, DIM, CAGD_LAYOUT_POINT_MAJOR, &o, t, out,
                                          out_len, &needed));
        transpose(out, back, K, m1, 1);
        /* point-major sums in another order than the GEMM kernel: equal up to rounding */
        for (c = 0; c < out_len; ++c) CHECK(fabs(back[c] - ref[c]) <= 1e-13);
    }
    /* every curve as the single-curve call gives it (no report: points only) */
    for (c = 0; c < K; c += 7) {
        CHECK_OK(cagd_bezier_reduce(cm + c * N1 * DIM, N1, DIM, NULL, &o, one, 6 * DIM, &needed,
                                    NULL, 0, NULL));
        /* the batch sums in the GEMM kernel's order: equal up to rounding */
        for (t = 0; t < m1 * DIM; ++t) CHECK(fabs(one[t] - ref[c * m1 * DIM + t]) <= 1e-13);
    }
    rc = 0;
cleanup:
    free(cm);
    free(pm);
    free(ref);
    free(out);
    free(back);
    return rc;
}

int cagd_ctest_flat_batch_elevate_layouts(void) {
    int rc = 1;
    const size_t r = 3, m1 = N1 + 3, out_len = (size_t)K * (N1 + 3) * DIM;
    double *cm = malloc(sizeof(double) * K * N1 * DIM), *pm = malloc(sizeof(double) * K * N1 * DIM);
    double *ref = malloc(sizeof(double) * out_len), *out = malloc(sizeof(double) * out_len);
    double *back = malloc(sizeof(double) * out_len), hp[(N1 + 3) * DIM];
    CagdCurve *curve = NULL, *e = NULL;
    size_t needed = 0, t, c;

    CHECK(cm && pm && ref && out && back);
    fill(cm, (size_t)K * N1 * DIM);
    transpose(cm, pm, K, N1, 0);
    /* reference: every curve by the single-curve flat call */
    for (c = 0; c < K; ++c) {
        CHECK_OK(cagd_bezier_elevate(cm + c * N1 * DIM, N1, DIM, NULL, r, ref + c * m1 * DIM,
                                     m1 * DIM, &needed, NULL, 0));
    }
    /* ... which is the handle API's (checked on a few curves) */
    for (c = 0; c < K; c += 997) {
        CHECK_OK(cagd_curve_new(cm + c * N1 * DIM, N1, DIM, &curve));
        CHECK_OK(cagd_curve_elevate(curve, r, &e));
        CHECK_OK(cagd_curve_points(e, hp, m1 * DIM, &needed));
        CHECK(memcmp(hp, ref + c * m1 * DIM, sizeof hp) == 0);
        cagd_curve_free(e);
        cagd_curve_free(curve);
        e = NULL;
        curve = NULL;
    }
    for (t = 0; t <= 3; ++t) {
        memset(out, 0, sizeof(double) * out_len);
        CHECK_OK(cagd_bezier_elevate_batch(cm, K, 9, DIM, CAGD_LAYOUT_CURVE_MAJOR, r, t, out,
                                           out_len, &needed));
        CHECK(needed == out_len);
        CHECK(memcmp(out, ref, sizeof(double) * out_len) == 0);
        memset(out, 0, sizeof(double) * out_len);
        CHECK_OK(cagd_bezier_elevate_batch(pm, K, 9, DIM, CAGD_LAYOUT_POINT_MAJOR, r, t, out,
                                           out_len, &needed));
        transpose(out, back, K, m1, 1);
        CHECK(memcmp(back, ref, sizeof(double) * out_len) == 0);
    }
    rc = 0;
cleanup:
    cagd_curve_free(e);
    cagd_curve_free(curve);
    free(cm);
    free(pm);
    free(ref);
    free(out);
    free(back);
    return rc;
}

int cagd_ctest_flat_batch_bad_input(void) {
    int rc = 1;
    double in[3 * 4 * 2], out[3 * 6 * 2];
    CagdReduceOptions o;
    size_t needed = 0, k;

    fill(in, 24);
    CHECK_OK(cagd_reduce_options_init(&o));
    o.target = 2;
    /* size queries and short buffers (3 curves of degree 3 in 2D) */
    CHECK_STATUS(cagd_bezier_reduce_batch(in, 3, 3, 2, CAGD_LAYOUT_CURVE_MAJOR, &o, 0, NULL, 0,
                                          &needed),
                 CAGD_ERR_BUFFER_TOO_SMALL);
    CHECK(needed == 18);
    CHECK_STATUS(cagd_bezier_elevate_batch(in, 3, 3, 2, CAGD_LAYOUT_POINT_MAJOR, 2, 2, NULL, 0,
                                           &needed),
                 CAGD_ERR_BUFFER_TOO_SMALL);
    CHECK(needed == 36);
    for (k = 0; k < 36; ++k) out[k % 36] = -7.0;
    CHECK_STATUS(cagd_bezier_elevate_batch(in, 3, 3, 2, CAGD_LAYOUT_CURVE_MAJOR, 2, 0, out, 35,
                                           &needed),
                 CAGD_ERR_BUFFER_TOO_SMALL);
    CHECK(out[0] == -7.0);
    /* no curves: nothing to do, size 0 */
    CHECK_OK(cagd_bezier_reduce_batch(in, 0, 3, 2, CAGD_LAYOUT_POINT_MAJOR, &o, 2, NULL, 0,
                                      &needed));
    CHECK(needed == 0);
    /* bad codes and sizes */
    CHECK_STATUS(cagd_bezier_reduce_batch(in, 3, 3, 2, 2, &o, 0, out, 36, &needed),
                 CAGD_ERR_INVALID_ARGUMENT);
    CHECK_MESSAGE_HAS("CagdBatchLayout");
    CHECK_STATUS(cagd_bezier_elevate_batch(in, 3, 3, 2, -1, 1, 0, out, 36, &needed),
                 CAGD_ERR_INVALID_ARGUMENT);
    CHECK_STATUS(cagd_bezier_reduce_batch(in, 3, 3, 0, 0, &o, 0, out, 36, &needed),
                 CAGD_ERR_INVALID_ARGUMENT);
    CHECK_STATUS(cagd_bezier_reduce_batch(in, 1, 65, 0, 0, &o, 0, out, 36, &needed),
                 CAGD_ERR_DEGREE_OUT_OF_RANGE);
    CHECK_STATUS(cagd_bezier_reduce_batch(in, SIZE_MAX, 3, 2, 0, &o, 0, out, 36, &needed),
                 CAGD_ERR_INVALID_ARGUMENT);
    CHECK_STATUS(cagd_bezier_elevate_batch(in, 3, 3, 2, 0, 62, 0, out, 36, &needed),
                 CAGD_ERR_DEGREE_OUT_OF_RANGE);
    o.target = 3;
    CHECK_STATUS(cagd_bezier_reduce_batch(in, 3, 3, 2, 0, &o, 0, NULL, 0, &needed),
                 CAGD_ERR_BAD_DEGREE_PAIR);
    o.target = 2;
    /* NULLs */
    CHECK_STATUS(cagd_bezier_reduce_batch(NULL, 3, 3, 2, 0, &o, 0, out, 36, &needed),
                 CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_bezier_reduce_batch(in, 3, 3, 2, 0, NULL, 0, out, 36, &needed),
                 CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_bezier_reduce_batch(in, 3, 3, 2, 0, &o, 0, out, 36, NULL),
                 CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_bezier_elevate_batch(in, 3, 3, 2, 0, 1, 0, NULL, 36, &needed),
                 CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_bezier_elevate_batch(NULL, 3, 3, 2, 0, 1, 0, out, 36, &needed),
                 CAGD_ERR_NULL_POINTER);
    /* a NaN: named by curve, point and coordinate in either layout (the contents of out
     * are unspecified on CAGD_ERR_NON_FINITE: the input is not scanned before the kernel
     * writes); *out_needed is written */
    in[(2 * 4 + 1) * 2 + 1] = NAN; /* curve-major: curve 2, point 1, coordinate 1 */
    needed = 0;
    CHECK_STATUS(cagd_bezier_reduce_batch(in, 3, 3, 2, CAGD_LAYOUT_CURVE_MAJOR, &o, 2, out, 36,
                                          &needed),
                 CAGD_ERR_NON_FINITE);
    CHECK_MESSAGE_HAS("curve 2, point 1, coordinate 1");
    CHECK(needed == 3 * 3 * 2);
    /* the same double read point-major: row 3 (point 3) of curve 0, coordinate 1 */
    CHECK_STATUS(cagd_bezier_elevate_batch(in, 3, 3, 2, CAGD_LAYOUT_POINT_MAJOR, 1, 0, out, 36,
                                           &needed),
                 CAGD_ERR_NON_FINITE);
    CHECK_MESSAGE_HAS("curve 0, point 3, coordinate 1");
    rc = 0;
cleanup:
    return rc;
}
