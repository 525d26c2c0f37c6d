/* The handle-free single-curve calls (cagd_bezier_reduce, cagd_bezier_elevate): equal bit
 * for bit to the handle API (cagd_curve_reduce / cagd_curve_elevate and their read-back),
 * report fields included; size queries, short buffers, NULLs, bad input. */
#include <stdint.h>

#include "ctest.h"

/* Degree 7, 2D (the points of ginv-n7-m3-free) and positive weights for a rational one. */
static const double P7[16] = {0, 0, 1, 3, 3, 4, 5, 1, 6, 5, 8, 2, 9, 6, 11, 0};
static const double W7[8] = {1, 0.5, 2, 1.5, 0.75, 1, 3, 1};

/* Bitwise equality of n doubles (the flat calls must give the handle API's bits). */
static int same_bits(const double *a, const double *b, size_t n) {
    return memcmp(a, b, n * sizeof(double)) == 0;
}

/* Equal, or both NaN (absent). */
static int same_or_both_nan(double a, double b) {
    return (isnan(a) && isnan(b)) || memcmp(&a, &b, sizeof a) == 0;
}

/* Reduces P7 (rational when `w` is not NULL) with `o` through the handle API and through
 * cagd_bezier_reduce (with and without a report) and compares everything. */
static int reduce_both_ways(const double *w, const CagdReduceOptions *o) {
    int rc = 1;
    CagdCurve *c = NULL, *q = NULL;
    CagdReport *rep = NULL;
    CagdBezierReport fr;
    double hp[16], hw[8], fp[16], fw[8], hb = NAN, he = NAN, hh = NAN;
    size_t needed = 0, fneeded = 0, from = 0, to = 0, n_out = o->target + 1;
    int32_t method = -1, space = -1;

    if (w) {
        CHECK_OK(cagd_curve_new_rational(P7, w, 8, 2, &c));
    } else {
        CHECK_OK(cagd_curve_new(P7, 8, 2, &c));
    }
    {
        /* a rational reduction may fail (a reduced weight <= 0): then both ways alike */
        CagdStatus st = cagd_curve_reduce(c, o, &q, &rep);
        if (st != CAGD_OK) {
            CHECK_STATUS(cagd_bezier_reduce(P7, 8, 2, w, o, fp, 16, &fneeded, fw, 8, NULL), st);
            rc = 0;
            goto cleanup;
        }
    }
    CHECK_OK(cagd_curve_points(q, hp, 16, &needed));
    CHECK(needed == n_out * 2);
    if (w) CHECK_OK(cagd_curve_weights(q, hw, 8, &needed));
    CHECK_OK(cagd_report_method(rep, &method, &from, &to));
    CHECK_OK(cagd_report_bound(rep, &hb));
    if (o->measure) CHECK_OK(cagd_report_max_error(rep, &he));
    CHECK_OK(cagd_report_space(rep, &space, &hh));

    memset(&fr, 0xAB, sizeof fr);
    fr.struct_size = sizeof fr;
    memset(fp, 0, sizeof fp);
    memset(fw, 0, sizeof fw);
    CHECK_OK(cagd_bezier_reduce(P7, 8, 2, w, o, fp, 16, &fneeded, fw, 8, &fr));
    CHECK(fneeded == n_out * 2);
    CHECK(same_bits(fp, hp, fneeded));
    if (w) CHECK(same_bits(fw, hw, n_out));
    CHECK(fr.struct_size == sizeof fr);
    CHECK(fr.method == method && fr.degree_from == from && fr.degree_to == to);
    CHECK(fr.space == space);
    CHECK(same_or_both_nan(fr.bound, hb));
    CHECK(same_or_both_nan(fr.homogeneous_bound, hh));
    CHECK(same_or_both_nan(fr.max_error, he));
    CHECK(o->measure || isnan(fr.max_error));

    /* no report: the same points (for a polynomial curve the bound is not computed) */
    memset(fp, 0, sizeof fp);
    CHECK_OK(cagd_bezier_reduce(P7, 8, 2, w, o, fp, 16, &fneeded, fw, 8, NULL));
    CHECK(same_bits(fp, hp, fneeded));
    if (w) CHECK(same_bits(fw, hw, n_out));
    rc = 0;
cleanup:
    if (rc) fprintf(stderr, "  (method %d, target %zu, rational %d)\n", (int)o->method, o->target, w != NULL);
    cagd_report_free(rep);
    cagd_curve_free(q);
    cagd_curve_free(c);
    return rc;
}

int cagd_ctest_flat_reduce_equals_handle(void) {
    int rc = 1;
    CagdReduceOptions o;
    int32_t m;

    CHECK_OK(cagd_reduce_options_init(&o));
    o.target = 4;
    for (m = CAGD_METHOD_FORREST; m <= CAGD_METHOD_L2; ++m) {
        o.method = m;
        o.l1 = m == CAGD_METHOD_PERTURB_G1 ? 0.25 : 0.0;
        o.l2 = m == CAGD_METHOD_PERTURB_G1 ? -0.5 : 0.0;
        CHECK(reduce_both_ways(NULL, &o) == 0);
        CHECK(reduce_both_ways(W7, &o) == 0);
    }
    /* measured error, L2 with C1 ends, and the homogeneous space of a rational curve */
    o.method = CAGD_METHOD_L2;
    o.r = 1;
    o.p = 1;
    o.target = 5;
    o.measure = true;
    CHECK(reduce_both_ways(NULL, &o) == 0);
    CHECK(reduce_both_ways(W7, &o) == 0);
    o.space = CAGD_SPACE_HOMOGENEOUS;
    CHECK(reduce_both_ways(W7, &o) == 0);
    rc = 0;
cleanup:
    return rc;
}

int cagd_ctest_flat_reduce_bad_input(void) {
    int rc = 1;
    CagdReduceOptions o;
    CagdBezierReport fr;
    double out[16], w_out[8], bad[16];
    size_t needed = 0, k;

    CHECK_OK(cagd_reduce_options_init(&o));
    o.target = 4;
    fr.struct_size = sizeof fr;
    /* size query: capacity 0, NULL buffer */
    CHECK_STATUS(cagd_bezier_reduce(P7, 8, 2, NULL, &o, NULL, 0, &needed, NULL, 0, NULL),
                 CAGD_ERR_BUFFER_TOO_SMALL);
    CHECK(needed == 10);
    /* short buffer: nothing written but the size */
    for (k = 0; k < 16; ++k) out[k] = -7.0;
    needed = 0;
    CHECK_STATUS(cagd_bezier_reduce(P7, 8, 2, NULL, &o, out, 9, &needed, NULL, 0, &fr),
                 CAGD_ERR_BUFFER_TOO_SMALL);
    CHECK(needed == 10 && out[0] == -7.0 && out[8] == -7.0);
    /* rational: weights buffer missing or short */
    CHECK_STATUS(cagd_bezier_reduce(P7, 8, 2, W7, &o, out, 16, &needed, NULL, 0, NULL),
                 CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_bezier_reduce(P7, 8, 2, W7, &o, out, 16, &needed, w_out, 4, NULL),
                 CAGD_ERR_BUFFER_TOO_SMALL);
    CHECK(needed == 10);
    CHECK_MESSAGE_HAS("weights_out_cap");
    /* out and weights_out overlap */
    CHECK_STATUS(cagd_bezier_reduce(P7, 8, 2, W7, &o, out, 16, &needed, out + 8, 5, NULL),
                 CAGD_ERR_INVALID_ARGUMENT);
    /* NULL arguments */
    CHECK_STATUS(cagd_bezier_reduce(NULL, 8, 2, NULL, &o, out, 16, &needed, NULL, 0, NULL),
                 CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_bezier_reduce(P7, 8, 2, NULL, NULL, out, 16, &needed, NULL, 0, NULL),
                 CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_bezier_reduce(P7, 8, 2, NULL, &o, out, 16, NULL, NULL, 0, NULL),
                 CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_bezier_reduce(P7, 8, 2, NULL, &o, NULL, 16, &needed, NULL, 0, NULL),
                 CAGD_ERR_NULL_POINTER);
    /* the report's struct_size */
    fr.struct_size = 8;
    CHECK_STATUS(cagd_bezier_reduce(P7, 8, 2, NULL, &o, out, 16, &needed, NULL, 0, &fr),
                 CAGD_ERR_INVALID_ARGUMENT);
    CHECK_MESSAGE_HAS("sizeof(CagdBezierReport)");
    fr.struct_size = sizeof fr;
    /* degree pair: answered before the size */
    o.target = 7;
    CHECK_STATUS(cagd_bezier_reduce(P7, 8, 2, NULL, &o, NULL, 0, &needed, NULL, 0, NULL),
                 CAGD_ERR_BAD_DEGREE_PAIR);
    o.target = 4;
    o.method = 12;
    CHECK_STATUS(cagd_bezier_reduce(P7, 8, 2, NULL, &o, out, 16, &needed, NULL, 0, NULL),
                 CAGD_ERR_INVALID_ARGUMENT);
    o.method = CAGD_METHOD_L2;
    /* points */
    CHECK_STATUS(cagd_bezier_reduce(P7, 0, 2, NULL, &o, out, 16, &needed, NULL, 0, NULL),
                 CAGD_ERR_NOT_ENOUGH_POINTS);
    CHECK_STATUS(cagd_bezier_reduce(P7, 8, 0, NULL, &o, out, 16, &needed, NULL, 0, NULL),
                 CAGD_ERR_INVALID_ARGUMENT);
    memcpy(bad, P7, sizeof bad);
    bad[5] = NAN;
    for (k = 0; k < 16; ++k) out[k] = -7.0;
    CHECK_STATUS(cagd_bezier_reduce(bad, 8, 2, NULL, &o, out, 16, &needed, NULL, 0, NULL),
                 CAGD_ERR_NON_FINITE);
    CHECK(out[0] == -7.0);
    {
        double wbad[8];
        memcpy(wbad, W7, sizeof wbad);
        wbad[3] = -1.0;
        CHECK_STATUS(cagd_bezier_reduce(P7, 8, 2, wbad, &o, out, 16, &needed, w_out, 8, NULL),
                     CAGD_ERR_NON_POSITIVE_WEIGHT);
    }
    rc = 0;
cleanup:
    return rc;
}

/* Elevates P7 (rational when `w` is not NULL) by r both ways and compares the bits. */
static int elevate_both_ways(const double *w, size_t r) {
    int rc = 1;
    CagdCurve *c = NULL, *e = NULL;
    double hp[2 * 12], hw[12], fp[2 * 12], fw[12];
    size_t needed = 0, fneeded = 0;

    if (w) {
        CHECK_OK(cagd_curve_new_rational(P7, w, 8, 2, &c));
    } else {
        CHECK_OK(cagd_curve_new(P7, 8, 2, &c));
    }
    CHECK_OK(cagd_curve_elevate(c, r, &e));
    CHECK_OK(cagd_curve_points(e, hp, 24, &needed));
    if (w) CHECK_OK(cagd_curve_weights(e, hw, 12, &needed));
    CHECK_OK(cagd_bezier_elevate(P7, 8, 2, w, r, fp, 24, &fneeded, fw, 12));
    CHECK(fneeded == (8 + r) * 2);
    CHECK(same_bits(fp, hp, fneeded));
    if (w) CHECK(same_bits(fw, hw, 8 + r));
    rc = 0;
cleanup:
    cagd_curve_free(e);
    cagd_curve_free(c);
    return rc;
}

int cagd_ctest_flat_elevate_equals_handle(void) {
    int rc = 1;
    size_t r;
    for (r = 0; r <= 4; ++r) {
        CHECK(elevate_both_ways(NULL, r) == 0);
        CHECK(elevate_both_ways(W7, r) == 0);
    }
    rc = 0;
cleanup:
    return rc;
}

int cagd_ctest_flat_elevate_bad_input(void) {
    int rc = 1;
    double out[24], w_out[12];
    size_t needed = 0;

    CHECK_STATUS(cagd_bezier_elevate(P7, 8, 2, NULL, 2, NULL, 0, &needed, NULL, 0),
                 CAGD_ERR_BUFFER_TOO_SMALL);
    CHECK(needed == 20);
    CHECK_STATUS(cagd_bezier_elevate(P7, 8, 2, NULL, 2, out, 19, &needed, NULL, 0),
                 CAGD_ERR_BUFFER_TOO_SMALL);
    CHECK_STATUS(cagd_bezier_elevate(P7, 8, 2, W7, 2, out, 24, &needed, w_out, 9),
                 CAGD_ERR_BUFFER_TOO_SMALL);
    CHECK_STATUS(cagd_bezier_elevate(P7, 8, 2, W7, 2, out, 24, &needed, NULL, 0),
                 CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_bezier_elevate(NULL, 8, 2, NULL, 2, out, 24, &needed, NULL, 0),
                 CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_bezier_elevate(P7, 8, 2, NULL, 2, out, 24, NULL, NULL, 0),
                 CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_bezier_elevate(P7, 8, 2, NULL, 58, out, 24, &needed, NULL, 0),
                 CAGD_ERR_DEGREE_OUT_OF_RANGE);
    CHECK_STATUS(cagd_bezier_elevate(P7, 8, 2, NULL, SIZE_MAX, out, 24, &needed, NULL, 0),
                 CAGD_ERR_DEGREE_OUT_OF_RANGE);
    {
        static const double big[66] = {0};
        CHECK_STATUS(cagd_bezier_elevate(big, 66, 1, NULL, 0, out, 24, &needed, NULL, 0),
                     CAGD_ERR_DEGREE_OUT_OF_RANGE);
    }
    CHECK_STATUS(cagd_bezier_elevate(P7, 0, 2, NULL, 1, out, 24, &needed, NULL, 0),
                 CAGD_ERR_NOT_ENOUGH_POINTS);
    rc = 0;
cleanup:
    return rc;
}
