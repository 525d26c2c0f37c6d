/* The strategies of cagd_bspline_reduce (CagdReduceOptions.spline_strategy and
 * spline_continuity) and the report accessors cagd_report_spline_strategy and
 * cagd_report_spline_continuity:
 * - the default fit keeps C2 at the knots of a degree-5 spline reduced to a cubic (checked
 *   through the derivatives on both sides of every kept knot);
 * - the continuity limits of each strategy (TOO_MANY_CONSTRAINTS above them);
 * - Piegl-Tiller 1995 recovers a cubic spline elevated to degree 5 (built here by
 *   blossoming) with its knots, and refuses a generic degree-7 spline;
 * - bad codes, NULL and short buffers. */
#include <stdint.h>

#include "ctest.h"

/* A degree-5 spline with simple interior knots (no lower-degree structure). */
static const double Q5_KNOTS[15] = {0, 0, 0, 0, 0, 0, 0.25, 0.5, 0.75, 1, 1, 1, 1, 1, 1};
static const double Q5_P[18] = {0, 0, 1, 2, 2, -1, 3, 3, 4, 0, 5, 2, 6, -2, 7, 1, 8, 0};

/* A generic cubic spline with simple knots 0.3 and 0.6. */
static const double C3_KNOTS[10] = {0, 0, 0, 0, 0.3, 0.6, 1, 1, 1, 1};
static const double C3_P[12] = {0, 0, 1, 2, 2, -1, 4, 3, 5, 0, 6, 1};

/* The blossom b(x[0], x[1], x[2]) of the piece on span [U[j], U[j+1]) of the cubic spline
 * (U, P) in 2D: de Boor's algorithm with a different argument at each level. */
static void cubic_blossom(const double *U, const double *P, size_t j, const double x[3],
                          double out[2]) {
    double d[4][2];
    size_t r, i, k;
    for (i = 0; i < 4; ++i) {
        d[i][0] = P[2 * (j - 3 + i)];
        d[i][1] = P[2 * (j - 3 + i) + 1];
    }
    for (r = 1; r <= 3; ++r) {
        for (i = 3; i >= r; --i) {
            size_t g = j - 3 + i;
            double a = (x[r - 1] - U[g]) / (U[g + 4 - r] - U[g]);
            for (k = 0; k < 2; ++k) d[i][k] = (1.0 - a) * d[i - 1][k] + a * d[i][k];
        }
    }
    out[0] = d[3][0];
    out[1] = d[3][1];
}

/* The cubic spline (U = C3_KNOTS-like: 0^4 a b 1^4, P: 6 points) elevated to degree 5:
 * knots 0^6 a^3 b^3 1^6, point i the degree-5 blossom (the mean of the cubic blossom over
 * the 10 triples) at V[i+1..i+5], taken on a span of V inside its support. */
static CagdStatus elevate_cubic(const double *U, const double *P, CagdBSpline **out) {
    double V[18], pts[24], y[5], x[3], b[2];
    size_t i, k, j, a, c, e;
    for (i = 0; i < 6; ++i) {
        V[i] = 0.0;
        V[12 + i] = 1.0;
    }
    for (i = 0; i < 3; ++i) {
        V[6 + i] = U[4];
        V[9 + i] = U[5];
    }
    for (i = 0; i < 12; ++i) {
        double t;
        for (k = 0; k < 5; ++k) y[k] = V[i + 1 + k];
        k = i; /* the first non-empty span of V in the support of point i */
        while (!(V[k] < V[k + 1])) ++k;
        t = 0.5 * (V[k] + V[k + 1]);
        j = 3; /* the span of U holding it */
        while (!(t < U[j + 1])) ++j;
        pts[2 * i] = pts[2 * i + 1] = 0.0;
        for (a = 0; a < 5; ++a) {
            for (c = a + 1; c < 5; ++c) {
                for (e = c + 1; e < 5; ++e) {
                    x[0] = y[a];
                    x[1] = y[c];
                    x[2] = y[e];
                    cubic_blossom(U, P, j, x, b);
                    pts[2 * i] += b[0] / 10.0;
                    pts[2 * i + 1] += b[1] / 10.0;
                }
            }
        }
    }
    return cagd_bspline_new(5, V, 18, pts, 12, 2, out);
}

int cagd_ctest_bspline_reduce_fit_c2(void) {
    int rc = 1;
    CagdBSpline *s = NULL, *q = NULL;
    CagdReport *rep = NULL;
    CagdReduceOptions o;
    double bound = -1, measured = -1, kn[8], qk[512], left[6], right[6];
    int32_t orders[8], strategy = -1, method = -1;
    size_t needed = 0, nk = 0, nq = 0, degree = 0, from = 0, to = 0, i, j, d;

    CHECK_OK(cagd_bspline_new(5, Q5_KNOTS, 15, Q5_P, 9, 2, &s));
    CHECK_OK(cagd_reduce_options_init(&o));
    CHECK(o.target == 3 && o.spline_strategy == CAGD_SPLINE_FIT && o.spline_continuity == -1);
    o.tolerance = 1e-4;
    o.measure = true;
    CHECK_OK(cagd_bspline_reduce(s, &o, &q, &rep));
    CHECK_OK(cagd_bspline_degree(q, &degree));
    CHECK(degree == 3);
    CHECK_OK(cagd_report_bound(rep, &bound));
    CHECK_OK(cagd_report_max_error(rep, &measured));
    CHECK(bound <= 1e-4 && measured <= bound);
    CHECK_OK(cagd_report_spline_strategy(rep, &strategy));
    CHECK(strategy == CAGD_SPLINE_FIT);
    CHECK_OK(cagd_report_method(rep, &method, &from, &to));
    CHECK(method == CAGD_METHOD_L2 && from == 5 && to == 3);
    CHECK_OK(cagd_report_spline_continuity(rep, kn, orders, 8, &nk));
    CHECK(nk >= 1 && nk <= 3); /* some of 0.25, 0.5, 0.75 stay: a quintic is no cubic */
    CHECK_OK(cagd_bspline_knots(q, qk, 512, &nq));
    for (i = 0; i < nk; ++i) {
        /* h: far above the rounding of t (1e-16), and the change 2 h |D3| of D2 across
         * [t - h, t + h] far below the 1e-6 allowed (measured: relative jumps <= 2.1e-8
         * here; a C1-only knot, e.g. of the segment strategy, jumps by 0.24) */
        const double h = 1e-10;
        size_t mult = 0;
        CHECK(orders[i] == 2);
        CHECK(i == 0 || kn[i] > kn[i - 1]);
        for (j = 0; j < nq; ++j) mult += qk[j] == kn[i];
        CHECK(mult == 1); /* a cubic is C2 at a simple knot only */
        CHECK_OK(cagd_bspline_derivatives(q, kn[i] - h, 2, left, 6, &needed));
        CHECK_OK(cagd_bspline_derivatives(q, kn[i] + h, 2, right, 6, &needed));
        for (d = 0; d <= 2; ++d) {
            /* jump of the derivative of order d relative to 1 + its size (the curve's
             * scale is ~10) */
            double jump = hypot(right[2 * d] - left[2 * d], right[2 * d + 1] - left[2 * d + 1]);
            double size = 1.0 + hypot(left[2 * d], left[2 * d + 1]);
            if (!(jump <= 1e-6 * size)) {
                fprintf(stderr, "knot %g: jump of D%zu = %g (|D%zu| = %g)\n", kn[i], d, jump,
                        d, size - 1.0);
                goto cleanup;
            }
        }
    }
    rc = 0;
cleanup:
    cagd_report_free(rep);
    cagd_bspline_free(q);
    cagd_bspline_free(s);
    return rc;
}

int cagd_ctest_bspline_reduce_continuity_limits(void) {
    int rc = 1;
    CagdBSpline *s = NULL, *q = NULL;
    CagdReport *rep = NULL;
    CagdReduceOptions o;
    double bound = -1, kn[64];
    int32_t orders[64], strategy = -1, method = -1;
    size_t nk = 0, from = 0, to = 0, i;

    CHECK_OK(cagd_bspline_new(5, Q5_KNOTS, 15, Q5_P, 9, 2, &s));
    CHECK_OK(cagd_reduce_options_init(&o));
    o.tolerance = 1e-3;
    /* segments: C1 is the most a cubic keeps (2k + 1 <= 3) */
    o.spline_strategy = CAGD_SPLINE_SEGMENTS;
    o.method = CAGD_METHOD_CONSTRAINED_CHEBYSHEV;
    o.spline_continuity = 1;
    CHECK_OK(cagd_bspline_reduce(s, &o, &q, &rep));
    CHECK_OK(cagd_report_bound(rep, &bound));
    CHECK(bound <= 1e-3);
    CHECK_OK(cagd_report_spline_strategy(rep, &strategy));
    CHECK_OK(cagd_report_method(rep, &method, &from, &to));
    CHECK(strategy == CAGD_SPLINE_SEGMENTS && method == CAGD_METHOD_CONSTRAINED_CHEBYSHEV);
    CHECK_OK(cagd_report_spline_continuity(rep, kn, orders, 64, &nk));
    CHECK(nk >= 1);
    for (i = 0; i < nk; ++i) CHECK(orders[i] == 1);
    cagd_report_free(rep);
    cagd_bspline_free(q);
    rep = NULL;
    q = NULL;
    o.spline_continuity = 2;
    CHECK_STATUS(cagd_bspline_reduce(s, &o, &q, &rep), CAGD_ERR_TOO_MANY_CONSTRAINTS);
    /* the fit keeps up to C^(target - 1) = C2; less on request */
    o.spline_strategy = CAGD_SPLINE_FIT;
    o.spline_continuity = 3;
    CHECK_STATUS(cagd_bspline_reduce(s, &o, &q, &rep), CAGD_ERR_TOO_MANY_CONSTRAINTS);
    o.spline_strategy = CAGD_SPLINE_PIEGL_TILLER_1995;
    CHECK_STATUS(cagd_bspline_reduce(s, &o, &q, &rep), CAGD_ERR_TOO_MANY_CONSTRAINTS);
    CHECK(q == NULL && rep == NULL);
    o.spline_strategy = CAGD_SPLINE_FIT;
    o.spline_continuity = 1;
    CHECK_OK(cagd_bspline_reduce(s, &o, &q, &rep));
    CHECK_OK(cagd_report_method(rep, &method, &from, &to));
    CHECK(method == CAGD_METHOD_L2); /* what the fit minimises, whatever opts.method is */
    CHECK_OK(cagd_report_spline_continuity(rep, kn, orders, 64, &nk));
    CHECK(nk >= 1);
    for (i = 0; i < nk; ++i) CHECK(orders[i] == 1);
    rc = 0;
cleanup:
    cagd_report_free(rep);
    cagd_bspline_free(q);
    cagd_bspline_free(s);
    return rc;
}

int cagd_ctest_bspline_reduce_piegl_tiller(void) {
    int rc = 1;
    CagdBSpline *s = NULL, *q = NULL, *g = NULL, *gq = NULL;
    CagdReport *rep = NULL, *grep = NULL;
    CagdReduceOptions o;
    /* a generic degree-7 spline with one simple interior knot */
    const double g_knots[17] = {0, 0, 0, 0, 0, 0, 0, 0, 0.5, 1, 1, 1, 1, 1, 1, 1, 1};
    const double g_pts[18] = {3, 3, 5, 9.5, 7, 2, 8, 9, 10, 3, 11, 8, 13, 5, 14, 6, 16, 4};
    double bound = -1, measured = -1, sb = -1, kn[4], out[16];
    int32_t orders[4], strategy = -1, method = -1;
    size_t pieces = 0, si = 0, so = 0, nk = 0, needed = 0, from = 0, to = 0, i;

    CHECK_OK(elevate_cubic(C3_KNOTS, C3_P, &s));
    CHECK_OK(cagd_reduce_options_init(&o));
    o.spline_strategy = CAGD_SPLINE_PIEGL_TILLER_1995;
    o.tolerance = 1e-9;
    o.measure = true;
    CHECK_OK(cagd_bspline_reduce(s, &o, &q, &rep));
    CHECK_OK(cagd_report_spline(rep, &sb, &pieces, &si, &so));
    CHECK(si == 3 && so == si); /* never subdivides; here no span merges either */
    CHECK_OK(cagd_report_bound(rep, &bound));
    CHECK_OK(cagd_report_max_error(rep, &measured));
    CHECK(measured <= bound && bound <= 1e-9);
    CHECK_OK(cagd_report_spline_strategy(rep, &strategy));
    CHECK_OK(cagd_report_method(rep, &method, &from, &to));
    CHECK(strategy == CAGD_SPLINE_PIEGL_TILLER_1995 && method == CAGD_METHOD_PIEGL_TILLER);
    CHECK(from == 5 && to == 3);
    /* the cubic comes back: its knots and points; C2 (= 5 - 3, the input's) at 0.3, 0.6 */
    CHECK_OK(cagd_bspline_knots(q, out, 16, &needed));
    CHECK(needed == 10 && memcmp(out, C3_KNOTS, sizeof C3_KNOTS) == 0);
    CHECK_OK(cagd_bspline_points(q, out, 16, &needed));
    CHECK(needed == 12);
    for (i = 0; i < 12; ++i) CHECK_NEAR(out[i], C3_P[i], 1e-10 * 6.0);
    CHECK_OK(cagd_report_spline_continuity(rep, kn, orders, 4, &nk));
    CHECK(nk == 2 && kn[0] == 0.3 && kn[1] == 0.6 && orders[0] == 2 && orders[1] == 2);
    /* a generic degree-7 spline is not within 1e-6 of a cubic spline on its two spans */
    CHECK_OK(cagd_bspline_new(7, g_knots, 17, g_pts, 9, 2, &g));
    o.tolerance = 1e-6;
    o.measure = false;
    CHECK_STATUS(cagd_bspline_reduce(g, &o, &gq, &grep), CAGD_ERR_CONDITION_NOT_MET);
    CHECK(gq == NULL && grep == NULL);
    /* the default fit subdivides and succeeds */
    o.spline_strategy = CAGD_SPLINE_FIT;
    CHECK_OK(cagd_bspline_reduce(g, &o, &gq, &grep));
    CHECK_OK(cagd_report_bound(grep, &bound));
    CHECK_OK(cagd_report_spline(grep, &sb, &pieces, &si, &so));
    CHECK(bound <= 1e-6 && si == 2 && so > 2);
    rc = 0;
cleanup:
    cagd_report_free(grep);
    cagd_report_free(rep);
    cagd_bspline_free(gq);
    cagd_bspline_free(g);
    cagd_bspline_free(q);
    cagd_bspline_free(s);
    return rc;
}

int cagd_ctest_bspline_reduce_strategy_bad_input(void) {
    int rc = 1;
    CagdBSpline *s = NULL, *q = NULL;
    CagdReport *rep = NULL;
    CagdReduceOptions o;

    CHECK_OK(cagd_bspline_new(5, Q5_KNOTS, 15, Q5_P, 9, 2, &s));
    CHECK_OK(cagd_reduce_options_init(&o));
    o.tolerance = 1e-3;
    o.spline_strategy = 3;
    CHECK_STATUS(cagd_bspline_reduce(s, &o, &q, &rep), CAGD_ERR_INVALID_ARGUMENT);
    CHECK_MESSAGE_HAS("spline_strategy = 3");
    o.spline_strategy = -1;
    CHECK_STATUS(cagd_bspline_reduce(s, &o, &q, &rep), CAGD_ERR_INVALID_ARGUMENT);
    o.spline_strategy = CAGD_SPLINE_FIT;
    o.spline_continuity = -2;
    CHECK_STATUS(cagd_bspline_reduce(s, &o, &q, &rep), CAGD_ERR_INVALID_ARGUMENT);
    CHECK_MESSAGE_HAS("spline_continuity = -2");
    o.spline_continuity = INT32_MIN;
    CHECK_STATUS(cagd_bspline_reduce(s, &o, &q, &rep), CAGD_ERR_INVALID_ARGUMENT);
    o.spline_continuity = -1;
    /* the method matters for the segment strategy only */
    o.method = 42;
    o.spline_strategy = CAGD_SPLINE_SEGMENTS;
    CHECK_STATUS(cagd_bspline_reduce(s, &o, &q, &rep), CAGD_ERR_INVALID_ARGUMENT);
    CHECK(q == NULL && rep == NULL);
    o.spline_strategy = CAGD_SPLINE_FIT;
    CHECK_OK(cagd_bspline_reduce(s, &o, &q, &rep));
    rc = 0;
cleanup:
    cagd_report_free(rep);
    cagd_bspline_free(q);
    cagd_bspline_free(s);
    return rc;
}

int cagd_ctest_report_spline_accessors(void) {
    int rc = 1;
    CagdBSpline *s = NULL, *q = NULL, *u = NULL, *uq = NULL, *poly = NULL, *pq = NULL;
    CagdReport *rep = NULL, *urep = NULL, *prep = NULL, *single = NULL;
    CagdCurve *c = NULL, *cq = NULL;
    CagdReduceOptions o;
    double kn[4] = {-1, -1, -1, -1}, knots[17], mp[12];
    int32_t orders[4] = {-7, -7, -7, -7}, strategy = -1;
    size_t needed = 0, i;

    CHECK_OK(elevate_cubic(C3_KNOTS, C3_P, &s));
    CHECK_OK(cagd_reduce_options_init(&o));
    o.tolerance = 1e-9;
    CHECK_OK(cagd_bspline_reduce(s, &o, &q, &rep));
    /* cagd_report_spline_strategy */
    CHECK_STATUS(cagd_report_spline_strategy(NULL, &strategy), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_report_spline_strategy(rep, NULL), CAGD_ERR_NULL_POINTER);
    CHECK(strategy == -1);
    CHECK_OK(cagd_report_spline_strategy(rep, &strategy));
    CHECK(strategy == CAGD_SPLINE_FIT);
    /* cagd_report_spline_continuity: NULLs, size query, short buffer, overlap */
    CHECK_STATUS(cagd_report_spline_continuity(NULL, kn, orders, 4, &needed),
                 CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_report_spline_continuity(rep, kn, orders, 4, NULL),
                 CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_report_spline_continuity(rep, NULL, orders, 4, &needed),
                 CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_report_spline_continuity(rep, kn, NULL, 4, &needed),
                 CAGD_ERR_NULL_POINTER);
    CHECK(needed == 0);
    CHECK_STATUS(cagd_report_spline_continuity(rep, NULL, NULL, 0, &needed),
                 CAGD_ERR_BUFFER_TOO_SMALL);
    CHECK(needed == 2); /* the fit recovers the cubic: both knots stay */
    needed = 0;
    CHECK_STATUS(cagd_report_spline_continuity(rep, kn, orders, 1, &needed),
                 CAGD_ERR_BUFFER_TOO_SMALL);
    CHECK(needed == 2 && kn[0] == -1 && orders[0] == -7);
    CHECK_STATUS(cagd_report_spline_continuity(rep, kn, (int32_t *)(void *)kn, 4, &needed),
                 CAGD_ERR_INVALID_ARGUMENT);
    CHECK(kn[0] == -1);
    CHECK_OK(cagd_report_spline_continuity(rep, kn, orders, 4, &needed));
    CHECK(needed == 2 && kn[0] == 0.3 && kn[1] == 0.6 && orders[0] == 2 && orders[1] == 2);
    CHECK(kn[2] == -1 && orders[2] == -7); /* nothing past the count */
    /* an empty list: (t, t^3) elevated is one cubic, the fit removes both knots */
    for (i = 0; i < 6; ++i) {
        const double *v = C3_KNOTS + i + 1; /* Marsden: mean and product of 3 knots */
        mp[2 * i] = (v[0] + v[1] + v[2]) / 3.0;
        mp[2 * i + 1] = v[0] * v[1] * v[2];
    }
    CHECK_OK(elevate_cubic(C3_KNOTS, mp, &poly));
    CHECK_OK(cagd_bspline_reduce(poly, &o, &pq, &prep));
    CHECK_OK(cagd_report_spline_continuity(prep, NULL, NULL, 0, &needed));
    CHECK(needed == 0);
    /* reports without a strategy */
    for (i = 0; i < 17; ++i) knots[i] = (double)i;
    CHECK_OK(cagd_bspline_new(7, knots, 17, Q5_P, 9, 2, &u));
    CHECK_OK(cagd_bspline_reduce_uniform(u, &o, &uq, &urep));
    CHECK_STATUS(cagd_report_spline_strategy(urep, &strategy), CAGD_ERR_NOT_AVAILABLE);
    CHECK_STATUS(cagd_report_spline_continuity(urep, kn, orders, 4, &needed),
                 CAGD_ERR_NOT_AVAILABLE);
    CHECK_OK(cagd_curve_new(Q5_P, 9, 2, &c));
    CHECK_OK(cagd_curve_reduce(c, &o, &cq, &single));
    CHECK_STATUS(cagd_report_spline_strategy(single, &strategy), CAGD_ERR_NOT_AVAILABLE);
    CHECK_STATUS(cagd_report_spline_continuity(single, NULL, NULL, 0, &needed),
                 CAGD_ERR_NOT_AVAILABLE);
    rc = 0;
cleanup:
    cagd_report_free(single);
    cagd_curve_free(cq);
    cagd_curve_free(c);
    cagd_report_free(urep);
    cagd_bspline_free(uq);
    cagd_bspline_free(u);
    cagd_report_free(prep);
    cagd_bspline_free(pq);
    cagd_bspline_free(poly);
    cagd_report_free(rep);
    cagd_bspline_free(q);
    cagd_bspline_free(s);
    return rc;
}
