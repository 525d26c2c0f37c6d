/* Degree reduction: new -> reduce -> read back -> free, checked against the spec vectors
 * of shared/spec/vectors-reduce.json (numbers copied with their vector id). The spec's
 * tolerance rule: max |got - expected| <= tol * max(1, max |expected|), tol = 1e-12. */
#include "ctest.h"

/* The spec tolerance rule over n doubles. */
static int spec_close(const double *got, const double *expected, size_t n, double tol) {
    double scale = 1.0, worst = 0.0;
    size_t i;
    for (i = 0; i < n; ++i) {
        if (fabs(expected[i]) > scale) scale = fabs(expected[i]);
    }
    for (i = 0; i < n; ++i) {
        double d = fabs(got[i] - expected[i]);
        if (!(d <= worst)) worst = d; /* NaN becomes the worst */
    }
    if (!(worst <= tol * scale)) {
        fprintf(stderr, "deviation %.3g exceeds %.3g\n", worst, tol * scale);
        return 0;
    }
    return 1;
}

/* Control points P of forrest-1 (degree 5) and of ginv-n7-m3-free / hermite-n7-m3
 * (degree 7), 2D. */
static const double P5[12] = {0, 0, 1, 3, 3, 4, 5, 1, 6, 5, 8, 2};
static const double P7[16] = {0, 0, 1, 3, 3, 4, 5, 1, 6, 5, 8, 2, 9, 6, 11, 0};

/* Reduces `pts` and compares the result with `expected` ((target + 1) * 2 doubles). */
static int reduce_and_compare(const double *pts, size_t n_points, const CagdReduceOptions *o,
                              const double *expected, double *bound, double *measured) {
    int rc = 1;
    CagdCurve *c = NULL, *q = NULL;
    CagdReport *rep = NULL;
    double out[16] = {0};
    size_t needed = 0, degree = 0, from = 0, to = 0;
    int32_t method = -1;

    CHECK_OK(cagd_curve_new(pts, n_points, 2, &c));
    CHECK_OK(cagd_curve_reduce(c, o, &q, &rep));
    CHECK_OK(cagd_curve_degree(q, &degree));
    CHECK(degree == o->target);
    CHECK_OK(cagd_curve_points(q, out, 16, &needed));
    CHECK(needed == (o->target + 1) * 2);
    CHECK(spec_close(out, expected, needed, 1e-12));
    CHECK_OK(cagd_report_method(rep, &method, &from, &to));
    CHECK(method == o->method && from == n_points - 1 && to == o->target);
    CHECK_OK(cagd_report_bound(rep, bound));
    if (o->measure) {
        CHECK_OK(cagd_report_max_error(rep, measured));
    } else {
        CHECK_STATUS(cagd_report_max_error(rep, measured), CAGD_ERR_NOT_AVAILABLE);
    }
    rc = 0;
cleanup:
    cagd_report_free(rep);
    cagd_curve_free(q);
    cagd_curve_free(c);
    return rc;
}

int cagd_ctest_reduce_forrest_1(void) {
    int rc = 1;
    CagdReduceOptions o;
    /* forrest-1: Q exact = (0,0) (5/4,15/4) (53/12,1) (11/2,23/4) (8,2) */
    const double q[10] = {0.0, 0.0, 1.25, 3.75, 4.416666666666667, 1.0, 5.5, 5.75, 8.0, 2.0};
    double bound = -1.0, measured = -1.0;

    CHECK_OK(cagd_reduce_options_init(&o));
    o.method = CAGD_METHOD_FORREST;
    o.target = 4;
    CHECK(reduce_and_compare(P5, 6, &o, q, &bound, &measured) == 0);
    CHECK(bound > 0.0 && isfinite(bound));
    rc = 0;
cleanup:
    return rc;
}

int cagd_ctest_reduce_ginv_n7_m3_free(void) {
    int rc = 1;
    CagdReduceOptions o;
    /* ginv-n7-m3-free: Q exact starts (-2/11, 53/66) */
    const double q[8] = {-0.18181818181818182, 0.803030303030303, 3.48989898989899,
                         3.0353535353535355, 7.343434343434343, 5.4646464646464645,
                         10.848484848484848, 1.196969696969697};
    double bound = -1.0, measured = -1.0;

    CHECK_OK(cagd_reduce_options_init(&o));
    o.method = CAGD_METHOD_GENERALIZED_INVERSE;
    o.target = 3;
    o.measure = true;
    CHECK(reduce_and_compare(P7, 8, &o, q, &bound, &measured) == 0);
    /* certified: measured <= bound; and the bound is no worse than the spec's eq. 14.4.3
     * value 2.994122288160019 (ginv-n7-m3-free, bound_14.4.3) plus rounding */
    CHECK(measured > 0.0 && measured <= bound);
    CHECK(bound <= 2.994122288160019 * (1.0 + 1e-12));
    rc = 0;
cleanup:
    return rc;
}

int cagd_ctest_reduce_hermite_n7_m3(void) {
    int rc = 1;
    CagdReduceOptions o;
    /* hermite-n7-m3 (r = p = 1, m = 3): Q = (0,0) (7/3,7) (19/3,14) (11,0) */
    const double q[8] = {0.0, 0.0, 2.3333333333333335, 7.0, 6.333333333333333, 14.0, 11.0, 0.0};
    double bound = -1.0, measured = -1.0;

    CHECK_OK(cagd_reduce_options_init(&o));
    o.method = CAGD_METHOD_CONSTRAINED_CHEBYSHEV;
    o.target = 3;
    o.r = 1;
    o.p = 1;
    o.measure = true;
    CHECK(reduce_and_compare(P7, 8, &o, q, &bound, &measured) == 0);
    CHECK(measured <= bound);
    rc = 0;
cleanup:
    return rc;
}

int cagd_ctest_reduce_batch(void) {
    int rc = 1;
    CagdReduceOptions o;
    double in[3 * 16], out[3 * 8];
    size_t needed = 0, c;
    /* ginv-n7-m3-free, as above */
    const double q[8] = {-0.18181818181818182, 0.803030303030303, 3.48989898989899,
                         3.0353535353535355, 7.343434343434343, 5.4646464646464645,
                         10.848484848484848, 1.196969696969697};

    for (c = 0; c < 3; ++c) memcpy(in + 16 * c, P7, sizeof P7);
    CHECK_OK(cagd_reduce_options_init(&o));
    o.method = CAGD_METHOD_GENERALIZED_INVERSE;
    o.target = 3;
    CHECK_STATUS(cagd_curve_reduce_batch(in, 3, 7, 2, &o, NULL, 0, &needed),
                 CAGD_ERR_BUFFER_TOO_SMALL);
    CHECK(needed == 24);
    CHECK_OK(cagd_curve_reduce_batch(in, 3, 7, 2, &o, out, 24, &needed));
    for (c = 0; c < 3; ++c) CHECK(spec_close(out + 8 * c, q, 8, 1e-12));
    CHECK_OK(cagd_curve_reduce_batch(in, 0, 7, 2, &o, NULL, 0, &needed));
    CHECK(needed == 0);
    rc = 0;
cleanup:
    return rc;
}

/* Per-curve certified bounds from the batch call: every bound is at least the error that
 * cagd_curve_reduce measures for that curve, the tight ones (batch and per-curve call)
 * within 1.1x of it, and the report names the level. */
int cagd_ctest_reduce_batch_bounds(void) {
    int rc = 1;
    CagdCurve *c = NULL, *q = NULL;
    CagdReport *rep = NULL;
    CagdReduceOptions o;
    double in[2 * 16], out[2 * 10], fast[2] = {-1, -1}, tight[2] = {-1, -1};
    double bound = -1.0, measured = -1.0;
    size_t needed = 0, k;
    int32_t level = -1;

    memcpy(in, P7, sizeof P7);
    for (k = 0; k < 16; ++k) in[16 + k] = P7[k] * (k % 2 ? 0.5 : -2.0);
    CHECK_OK(cagd_reduce_options_init(&o));
    CHECK(o.bound_level == CAGD_BOUND_TIGHT);
    o.method = CAGD_METHOD_L2;
    o.target = 4;
    o.bound_level = CAGD_BOUND_FAST;
    CHECK_OK(cagd_curve_reduce_batch_bounded(in, 2, 7, 2, &o, out, 20, &needed, fast));
    o.bound_level = CAGD_BOUND_TIGHT;
    CHECK_OK(cagd_curve_reduce_batch_bounded(in, 2, 7, 2, &o, out, 20, &needed, tight));
    o.measure = true;
    for (k = 0; k < 2; ++k) {
        CHECK_OK(cagd_curve_new(in + 16 * k, 8, 2, &c));
        CHECK_OK(cagd_curve_reduce(c, &o, &q, &rep));
        CHECK_OK(cagd_report_bound(rep, &bound));
        CHECK_OK(cagd_report_max_error(rep, &measured));
        CHECK_OK(cagd_report_bound_level(rep, &level));
        CHECK(level == CAGD_BOUND_TIGHT);
        CHECK(measured <= bound && bound <= 1.1 * measured);
        CHECK(measured <= tight[k] && tight[k] <= 1.1 * measured);
        CHECK(measured <= fast[k] && tight[k] <= fast[k]);
        cagd_report_free(rep);
        rep = NULL;
        cagd_curve_free(q);
        q = NULL;
        cagd_curve_free(c);
        c = NULL;
    }
    /* No bound asked for: the report says so, and the bound is not available. */
    o.bound_level = CAGD_BOUND_NONE;
    CHECK_OK(cagd_curve_new(P7, 8, 2, &c));
    CHECK_OK(cagd_curve_reduce(c, &o, &q, &rep));
    CHECK_OK(cagd_report_bound_level(rep, &level));
    CHECK(level == CAGD_BOUND_NONE);
    CHECK_STATUS(cagd_report_bound(rep, &bound), CAGD_ERR_NOT_AVAILABLE);
    /* bounds_out with CAGD_BOUND_NONE, an unknown level, or overlapping out: rejected. */
    CHECK_STATUS(cagd_curve_reduce_batch_bounded(in, 2, 7, 2, &o, out, 20, &needed, fast),
                 CAGD_ERR_INVALID_ARGUMENT);
    o.bound_level = 7;
    CHECK_STATUS(cagd_curve_reduce_batch_bounded(in, 2, 7, 2, &o, out, 20, &needed, fast),
                 CAGD_ERR_INVALID_ARGUMENT);
    CHECK_STATUS(cagd_curve_reduce(c, &o, &q, &rep), CAGD_ERR_INVALID_ARGUMENT);
    o.bound_level = CAGD_BOUND_FAST;
    CHECK_STATUS(cagd_curve_reduce_batch_bounded(in, 2, 7, 2, &o, out, 20, &needed, out + 3),
                 CAGD_ERR_INVALID_ARGUMENT);
    rc = 0;
cleanup:
    cagd_report_free(rep);
    cagd_curve_free(q);
    cagd_curve_free(c);
    return rc;
}

int cagd_ctest_reduce_rational_roundtrip(void) {
    int rc = 1;
    CagdCurve *c = NULL, *e = NULL, *q = NULL;
    CagdReport *rep = NULL;
    CagdReduceOptions o;
    const double pts[6] = {1.0, 0.0, 1.0, 1.0, 0.0, 1.0};
    const double w[3] = {1.0, sqrt(0.5), 1.0};
    double back[6] = {0}, wb[3] = {0}, bound = -1.0, hb = -1.0;
    size_t needed = 0, k;
    bool rational = false;
    int32_t space = -1;

    /* elevate the quarter circle by 3, reduce back to 2: the same curve */
    CHECK_OK(cagd_curve_new_rational(pts, w, 3, 2, &c));
    CHECK_OK(cagd_curve_elevate(c, 3, &e));
    CHECK_OK(cagd_reduce_options_init(&o));
    o.method = CAGD_METHOD_L2;
    o.target = 2;
    o.r = -1;
    o.p = -1;
    CHECK_OK(cagd_curve_reduce(e, &o, &q, &rep));
    CHECK_OK(cagd_curve_is_rational(q, &rational));
    CHECK(rational);
    CHECK_OK(cagd_curve_points(q, back, 6, &needed));
    CHECK_OK(cagd_curve_weights(q, wb, 3, &needed));
    /* operator entries rounded once, applied to size-1 data: 1e-13 is ample */
    for (k = 0; k < 6; ++k) CHECK_NEAR(back[k], pts[k], 1e-13);
    for (k = 0; k < 3; ++k) CHECK_NEAR(wb[k], w[k], 1e-13);
    CHECK_OK(cagd_report_bound(rep, &bound));
    CHECK(bound >= 0.0 && bound < 1e-12);
    CHECK_OK(cagd_report_space(rep, &space, &hb));
    CHECK(space == CAGD_SPACE_EUCLIDEAN && hb >= 0.0 && hb < 1e-12);
    rc = 0;
cleanup:
    cagd_report_free(rep);
    cagd_curve_free(q);
    cagd_curve_free(e);
    cagd_curve_free(c);
    return rc;
}
