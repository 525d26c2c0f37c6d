/* B-spline / NURBS reduction: new -> reduce -> read back -> free.
 * - seed 001's uniform pipeline against the spec vector 001-example (degree 7, 9 points,
 *   knots 0..16 -> degree 3 by the C1 Hermite reduction, i.e. constrained Chebyshev with
 *   r = p = 1): the lossy merge gives merged_ctrl; the exact merge (C1 joint: interior
 *   knot of multiplicity 2) gives the reduced_segments' points without the shared joint
 *   point; its measured error is SPEC-reduce §8's 1.30e-2.
 * - general reduction to a tolerance: (t, t^3) written as a degree-4 spline (Marsden's
 *   identity: points are the blossoms) comes back as the cubic (t, t^3) by the C1 segment
 *   strategy; the NURBS circle reduced to a polyline within 1e-2 by the default fit stays
 *   within its bound of the unit circle. The strategies themselves are tested in
 *   bspline_reduce_strategy.c. */
#include <stdint.h>

#include "ctest.h"

/* 001-example: input P (degree 7, 2D) and uniform knots 0..16 */
static const double E001_P[18] = {3, 3, 5, 9.5, 7, 2, 8, 9, 10, 3, 11, 8, 13, 5, 14, 6, 16, 4};
/* 001-example: expected merged_ctrl (lossy merge) */
static const double E001_LOSSY[10] = {
    6.787433862433862, 4.882407407407407, 8.20978835978836, 6.409986772486772,
    9.790343915343914, 5.288558201058201, 11.20978835978836, 6.186375661375662,
    12.790476190476191, 6.141931216931217};
/* 001-example: reduced_segments[0][0..3] then reduced_segments[1][1..4] (exact merge) */
static const double E001_EXACT[12] = {
    8.236309523809524, 5.914087301587301, 8.736772486772487, 5.989550264550265,
    9.263492063492064, 5.662367724867725, 10.263492063492064, 5.587830687830688,
    10.736507936507936, 5.9337301587301585, 11.236507936507936, 6.083730158730159};

/* The spec rule with tol 1e-12: |got - expected| <= 1e-12 * max(1, max |expected|). */
static int close_1e12(const double *got, const double *expected, size_t n) {
    double scale = 1.0;
    size_t i;
    for (i = 0; i < n; ++i) if (fabs(expected[i]) > scale) scale = fabs(expected[i]);
    for (i = 0; i < n; ++i) {
        if (!(fabs(got[i] - expected[i]) <= 1e-12 * scale)) {
            fprintf(stderr, "[%zu] = %.17g, expected %.17g\n", i, got[i], expected[i]);
            return 0;
        }
    }
    return 1;
}

int cagd_ctest_bspline_reduce_uniform_001(void) {
    int rc = 1;
    CagdBSpline *s = NULL, *lossy = NULL, *exact = NULL;
    CagdReport *rl = NULL, *re = NULL;
    CagdReduceOptions o;
    double knots[17], out[16] = {0}, ok[16] = {0}, bound = -1, measured = -1, sb = -1;
    const double exact_knots[10] = {7, 7, 7, 7, 8, 8, 9, 9, 9, 9};
    size_t needed = 0, pieces = 0, si = 0, so = 0, i;

    for (i = 0; i < 17; ++i) knots[i] = (double)i;
    CHECK_OK(cagd_bspline_new(7, knots, 17, E001_P, 9, 2, &s));
    CHECK_OK(cagd_reduce_options_init(&o));
    o.method = CAGD_METHOD_CONSTRAINED_CHEBYSHEV;
    o.r = o.p = 1;
    o.target = 3;
    o.merge = CAGD_MERGE_LOSSY;
    CHECK_OK(cagd_bspline_reduce_uniform(s, &o, &lossy, &rl));
    CHECK_OK(cagd_bspline_points(lossy, out, 16, &needed));
    CHECK(needed == 10 && close_1e12(out, E001_LOSSY, 10));
    /* the paper numbers the knots from 0; here they sit on the input's domain [7, 9] */
    CHECK_OK(cagd_bspline_knots(lossy, ok, 16, &needed));
    CHECK(needed == 9);
    for (i = 0; i < 9; ++i) CHECK(ok[i] == 4.0 + i);
    CHECK_OK(cagd_report_spline(rl, &sb, &pieces, &si, &so));
    CHECK(pieces == 2 && si == 2 && so == 2);
    CHECK_OK(cagd_report_bound(rl, &bound));
    CHECK(sb <= bound);
    /* exact merge, measured */
    o.merge = CAGD_MERGE_EXACT;
    o.measure = true;
    CHECK_OK(cagd_bspline_reduce_uniform(s, &o, &exact, &re));
    CHECK_OK(cagd_bspline_points(exact, out, 16, &needed));
    CHECK(needed == 12 && close_1e12(out, E001_EXACT, 12));
    CHECK_OK(cagd_bspline_knots(exact, ok, 16, &needed));
    CHECK(needed == 10 && memcmp(ok, exact_knots, sizeof exact_knots) == 0);
    CHECK_OK(cagd_report_bound(re, &bound));
    CHECK_OK(cagd_report_max_error(re, &measured));
    CHECK_NEAR(measured, 0.0130, 1e-4); /* SPEC-reduce §8: 1.30e-2 */
    CHECK(measured <= bound);
    rc = 0;
cleanup:
    cagd_report_free(re);
    cagd_report_free(rl);
    cagd_bspline_free(exact);
    cagd_bspline_free(lossy);
    cagd_bspline_free(s);
    return rc;
}

int cagd_ctest_bspline_reduce_tolerance(void) {
    int rc = 1;
    CagdBSpline *s = NULL, *q = NULL, *circle = NULL, *poly = NULL;
    CagdReport *rep = NULL, *crep = NULL;
    CagdReduceOptions o;
    /* (t, t^3) on the cubic knots 0^4 .3 .6 1^4, elevated: every multiplicity + 1 */
    const double u4[14] = {0, 0, 0, 0, 0, 0.3, 0.3, 0.6, 0.6, 1, 1, 1, 1, 1};
    const double cu[12] = {0, 0, 0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1, 1, 1};
    const double cp[18] = {1, 0, 1, 1, 0, 1, -1, 1, -1, 0, -1, -1, 0, -1, 1, -1, 1, 0};
    double pts[18], w[9], p[2], bound = -1, measured = -1, sb = -1;
    size_t degree = 0, pieces = 0, si = 0, so = 0, needed = 0, i;
    int32_t method = -1;
    size_t from = 0, to = 0;

    /* Marsden: point i of degree 4 is (mean of u_{i+1..i+4}, e3(u_{i+1..i+4}) / 4) */
    for (i = 0; i < 9; ++i) {
        const double *u = u4 + i + 1;
        pts[2 * i] = (u[0] + u[1] + u[2] + u[3]) / 4.0;
        pts[2 * i + 1] = (u[0] * u[1] * u[2] + u[0] * u[1] * u[3] + u[0] * u[2] * u[3] +
                          u[1] * u[2] * u[3]) / 4.0;
    }
    CHECK_OK(cagd_bspline_new(4, u4, 14, pts, 9, 2, &s));
    CHECK_OK(cagd_reduce_options_init(&o));
    o.target = 3;
    o.tolerance = 1e-9;
    o.spline_strategy = CAGD_SPLINE_SEGMENTS; /* with the default CAGD_METHOD_L2 */
    o.spline_continuity = 1;
    o.measure = true;
    CHECK_OK(cagd_bspline_reduce(s, &o, &q, &rep));
    CHECK_OK(cagd_bspline_degree(q, &degree));
    CHECK(degree == 3);
    CHECK_OK(cagd_report_method(rep, &method, &from, &to));
    CHECK(method == CAGD_METHOD_L2 && from == 4 && to == 3);
    CHECK_OK(cagd_report_bound(rep, &bound));
    CHECK_OK(cagd_report_max_error(rep, &measured));
    CHECK(measured <= bound && bound <= 1e-9);
    CHECK_OK(cagd_report_spline(rep, &sb, &pieces, &si, &so));
    CHECK(si == 3 && so <= pieces && sb <= bound);
    for (i = 0; i <= 20; ++i) {
        double t = i / 20.0;
        CHECK_OK(cagd_bspline_eval(q, t, p, 2, &needed));
        CHECK_NEAR(p[0], t, 1e-12);
        CHECK_NEAR(p[1], t * t * t, 1e-12);
    }
    /* the NURBS circle to a polyline within 1e-2 */
    for (i = 0; i < 9; ++i) w[i] = (i % 2) ? sqrt(0.5) : 1.0;
    CHECK_OK(cagd_bspline_new_rational(2, cu, 12, cp, w, 9, 2, &circle));
    o.target = 1;
    o.tolerance = 1e-2;
    o.spline_strategy = CAGD_SPLINE_FIT;
    o.spline_continuity = -1; /* C0: all a polyline can keep */
    o.measure = false;
    CHECK_OK(cagd_bspline_reduce(circle, &o, &poly, &crep));
    CHECK_OK(cagd_report_bound(crep, &bound));
    CHECK(bound <= 1e-2);
    CHECK_OK(cagd_report_spline(crep, &sb, &pieces, &si, &so));
    CHECK(si == 4 && so >= 8); /* a polygon within 1e-2 of a circle needs >= 23 sides */
    for (i = 0; i <= 400; ++i) {
        CHECK_OK(cagd_bspline_eval(poly, i / 400.0, p, 2, &needed));
        CHECK(fabs(hypot(p[0], p[1]) - 1.0) <= bound);
    }
    rc = 0;
cleanup:
    cagd_report_free(crep);
    cagd_report_free(rep);
    cagd_bspline_free(poly);
    cagd_bspline_free(circle);
    cagd_bspline_free(q);
    cagd_bspline_free(s);
    return rc;
}

int cagd_ctest_bspline_reduce_bad_input(void) {
    int rc = 1;
    CagdBSpline *s = NULL, *q = NULL, *nonuni = NULL;
    CagdReport *rep = NULL, *single = NULL;
    CagdCurve *c = NULL, *cq = NULL;
    CagdReduceOptions o;
    double knots[17], x = 0;
    double nu[17];
    size_t n = 0, i;

    for (i = 0; i < 17; ++i) knots[i] = nu[i] = (double)i;
    nu[16] = 17.0; /* one gap of 2: not uniform */
    CHECK_OK(cagd_bspline_new(7, knots, 17, E001_P, 9, 2, &s));
    CHECK_OK(cagd_reduce_options_init(&o));
    o.tolerance = 1e-3;
    CHECK_STATUS(cagd_bspline_reduce(NULL, &o, &q, &rep), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_bspline_reduce(s, NULL, &q, &rep), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_bspline_reduce(s, &o, NULL, &rep), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_bspline_reduce(s, &o, &q, NULL), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_bspline_reduce(s, &o, (CagdBSpline **)(void *)&rep, &rep),
                 CAGD_ERR_INVALID_ARGUMENT);
    CHECK_STATUS(cagd_bspline_reduce_uniform(NULL, &o, &q, &rep), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_bspline_reduce_uniform(s, NULL, &q, &rep), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_bspline_reduce_uniform(s, &o, NULL, &rep), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_bspline_reduce_uniform(s, &o, &q, NULL), CAGD_ERR_NULL_POINTER);
    o.struct_size = 0;
    CHECK_STATUS(cagd_bspline_reduce(s, &o, &q, &rep), CAGD_ERR_INVALID_ARGUMENT);
    CHECK_STATUS(cagd_bspline_reduce_uniform(s, &o, &q, &rep), CAGD_ERR_INVALID_ARGUMENT);
    o.struct_size = sizeof o;
    o.tolerance = 0.0;
    CHECK_STATUS(cagd_bspline_reduce(s, &o, &q, &rep), CAGD_ERR_INVALID_ARGUMENT);
    o.tolerance = INFINITY;
    CHECK_STATUS(cagd_bspline_reduce(s, &o, &q, &rep), CAGD_ERR_INVALID_ARGUMENT);
    o.tolerance = 1e-3;
    o.target = 7;
    CHECK_STATUS(cagd_bspline_reduce(s, &o, &q, &rep), CAGD_ERR_BAD_DEGREE_PAIR);
    o.target = 0;
    CHECK_STATUS(cagd_bspline_reduce(s, &o, &q, &rep), CAGD_ERR_BAD_DEGREE_PAIR);
    o.target = 3;
    o.spline_strategy = CAGD_SPLINE_SEGMENTS;
    o.spline_continuity = 2; /* > floor((3 - 1) / 2) */
    CHECK_STATUS(cagd_bspline_reduce(s, &o, &q, &rep), CAGD_ERR_TOO_MANY_CONSTRAINTS);
    o.spline_continuity = -1;
    o.method = CAGD_METHOD_ECK; /* only constrained Chebyshev or L2 */
    CHECK_STATUS(cagd_bspline_reduce(s, &o, &q, &rep), CAGD_ERR_INVALID_ARGUMENT);
    o.method = 42;
    CHECK_STATUS(cagd_bspline_reduce(s, &o, &q, &rep), CAGD_ERR_INVALID_ARGUMENT);
    /* the uniform pipeline */
    o.method = CAGD_METHOD_ECK; /* exact merge needs interpolated ends */
    CHECK_STATUS(cagd_bspline_reduce_uniform(s, &o, &q, &rep), CAGD_ERR_INVALID_ARGUMENT);
    o.method = CAGD_METHOD_L2;
    o.merge = 2;
    CHECK_STATUS(cagd_bspline_reduce_uniform(s, &o, &q, &rep), CAGD_ERR_INVALID_ARGUMENT);
    o.merge = CAGD_MERGE_EXACT;
    CHECK_OK(cagd_bspline_new(7, nu, 17, E001_P, 9, 2, &nonuni));
    CHECK_STATUS(cagd_bspline_reduce_uniform(nonuni, &o, &q, &rep), CAGD_ERR_BAD_KNOTS);
    o.target = 7;
    CHECK_STATUS(cagd_bspline_reduce_uniform(s, &o, &q, &rep), CAGD_ERR_BAD_DEGREE_PAIR);
    CHECK(q == NULL && rep == NULL);
    /* cagd_report_spline */
    o.target = 3;
    CHECK_OK(cagd_bspline_reduce(s, &o, &q, &rep));
    CHECK_STATUS(cagd_report_spline(NULL, &x, &n, &n, &n), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_report_spline(rep, NULL, &n, &n, &n), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_report_spline(rep, &x, NULL, &n, &n), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_report_spline(rep, &x, &n, NULL, &n), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_report_spline(rep, &x, &n, &n, NULL), CAGD_ERR_NULL_POINTER);
    CHECK_OK(cagd_curve_new(E001_P, 9, 2, &c));
    CHECK_OK(cagd_curve_reduce(c, &o, &cq, &single));
    CHECK_STATUS(cagd_report_spline(single, &x, &n, &n, &n), CAGD_ERR_NOT_AVAILABLE);
    rc = 0;
cleanup:
    cagd_report_free(single);
    cagd_curve_free(cq);
    cagd_curve_free(c);
    cagd_report_free(rep);
    cagd_bspline_free(nonuni);
    cagd_bspline_free(q);
    cagd_bspline_free(s);
    return rc;
}
