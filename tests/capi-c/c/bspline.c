/* CagdBSpline and CagdCurveList: new -> operate -> read back -> free, against closed forms.
 *
 * Polynomial case: by Marsden's identity (blossoming), the cubic spline with control
 * points P_i = (xi_i, eta_i), xi_i = (u_{i+1} + u_{i+2} + u_{i+3}) / 3 (Greville
 * abscissae) and eta_i = u_{i+1} u_{i+2} u_{i+3} (the blossom of t^3) is exactly
 * C(t) = (t, t^3), so C' = (1, 3t^2), C'' = (0, 6t), C''' = (0, 6), C'''' = 0.
 * Rational case: the 9-point NURBS circle (quadratic, knots 0 0 0 1/4 1/4 1/2 1/2 3/4 3/4
 * 1 1 1, weights 1, 1/sqrt 2, ...) lies on the unit circle for every t. */
#include "ctest.h"

/* Nonuniform clamped cubic knots, 6 control points. */
static const double U3[10] = {0, 0, 0, 0, 0.3, 0.6, 1, 1, 1, 1};

/* Fills the control points of (t, t^3) for the cubic knot vector u of n points. */
static void marsden_t3(const double *u, size_t n, double *pts) {
    size_t i;
    for (i = 0; i < n; ++i) {
        pts[2 * i] = (u[i + 1] + u[i + 2] + u[i + 3]) / 3.0;
        pts[2 * i + 1] = u[i + 1] * u[i + 2] * u[i + 3];
    }
}

static const double CIRCLE_U[12] = {0, 0, 0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1, 1, 1};
static const double CIRCLE_P[18] = {1, 0, 1, 1, 0, 1, -1, 1, -1, 0, -1, -1, 0, -1, 1, -1, 1, 0};

/* Exact relations evaluated by de Boor on values of size <= 1: 1e-14 is ~50 ulp. */
#define TOL 1e-14

int cagd_ctest_bspline_polynomial_closed_form(void) {
    int rc = 1;
    CagdBSpline *s = NULL, *r = NULL;
    double pts[12], back[12] = {0}, knots[10] = {0}, w[6] = {0}, p[2] = {0}, d[10] = {0};
    double rpts[16], rknots[12] = {0}, a = -1, b = -1;
    const double ts[6] = {0.0, 0.2, 0.3, 0.45, 0.99, 1.0};
    size_t needed = 0, degree = 0, dim = 0, n = 0, i, k;
    bool rational = true;

    marsden_t3(U3, 6, pts);
    CHECK_OK(cagd_bspline_new(3, U3, 10, pts, 6, 2, &s));
    CHECK_OK(cagd_bspline_degree(s, &degree));
    CHECK_OK(cagd_bspline_dim(s, &dim));
    CHECK_OK(cagd_bspline_n_points(s, &n));
    CHECK_OK(cagd_bspline_is_rational(s, &rational));
    CHECK(degree == 3 && dim == 2 && n == 6 && !rational);
    CHECK_OK(cagd_bspline_domain(s, &a, &b));
    CHECK(a == 0.0 && b == 1.0);
    /* read back: size queries, then exact copies */
    CHECK_STATUS(cagd_bspline_knots(s, NULL, 0, &needed), CAGD_ERR_BUFFER_TOO_SMALL);
    CHECK(needed == 10);
    CHECK_OK(cagd_bspline_knots(s, knots, 10, &needed));
    CHECK(memcmp(knots, U3, sizeof U3) == 0);
    CHECK_STATUS(cagd_bspline_points(s, NULL, 0, &needed), CAGD_ERR_BUFFER_TOO_SMALL);
    CHECK(needed == 12);
    CHECK_OK(cagd_bspline_points(s, back, 12, &needed));
    CHECK(memcmp(back, pts, sizeof pts) == 0);
    CHECK_OK(cagd_bspline_weights(s, w, 6, &needed));
    CHECK(needed == 6);
    for (i = 0; i < 6; ++i) CHECK(w[i] == 1.0);
    /* C(t) = (t, t^3) and its derivatives */
    for (k = 0; k < 6; ++k) {
        double t = ts[k];
        CHECK_OK(cagd_bspline_eval(s, t, p, 2, &needed));
        CHECK(needed == 2);
        CHECK_NEAR(p[0], t, TOL);
        CHECK_NEAR(p[1], t * t * t, TOL);
        CHECK_STATUS(cagd_bspline_derivatives(s, t, 4, NULL, 0, &needed),
                     CAGD_ERR_BUFFER_TOO_SMALL);
        CHECK(needed == 10); /* (order + 1) * dim */
        CHECK_OK(cagd_bspline_derivatives(s, t, 4, d, 10, &needed));
        CHECK_NEAR(d[0], t, TOL);
        CHECK_NEAR(d[1], t * t * t, TOL);
        CHECK_NEAR(d[2], 1.0, 1e-13); /* differences of knots amplify by ~1/0.3 */
        CHECK_NEAR(d[3], 3 * t * t, 1e-13);
        CHECK_NEAR(d[4], 0.0, 1e-12);
        CHECK_NEAR(d[5], 6 * t, 1e-12);
        CHECK_NEAR(d[6], 0.0, 1e-11);
        CHECK_NEAR(d[7], 6.0, 1e-11);
        CHECK(d[8] == 0.0 && d[9] == 0.0); /* above the degree */
    }
    /* knot insertion: 0.45 twice; the new points are again Marsden's points */
    CHECK_OK(cagd_bspline_insert_knot(s, 0.45, 2, &r));
    CHECK_OK(cagd_bspline_n_points(r, &n));
    CHECK(n == 8);
    CHECK_OK(cagd_bspline_knots(r, rknots, 12, &needed));
    CHECK(needed == 12 && rknots[5] == 0.45 && rknots[6] == 0.45 && rknots[7] == 0.6);
    {
        double expect[16];
        marsden_t3(rknots, 8, expect);
        CHECK_OK(cagd_bspline_points(r, rpts, 16, &needed));
        CHECK(needed == 16);
        for (i = 0; i < 16; ++i) CHECK_NEAR(rpts[i], expect[i], TOL);
    }
    rc = 0;
cleanup:
    cagd_bspline_free(r);
    cagd_bspline_free(s);
    return rc;
}

int cagd_ctest_bspline_nurbs_circle(void) {
    int rc = 1;
    CagdBSpline *s = NULL, *r = NULL;
    double w[9], wb[9] = {0}, p[2] = {0}, d[4] = {0};
    size_t needed = 0, i;
    bool rational = false;

    for (i = 0; i < 9; ++i) w[i] = (i % 2) ? sqrt(0.5) : 1.0;
    CHECK_OK(cagd_bspline_new_rational(2, CIRCLE_U, 12, CIRCLE_P, w, 9, 2, &s));
    CHECK_OK(cagd_bspline_is_rational(s, &rational));
    CHECK(rational);
    CHECK_OK(cagd_bspline_weights(s, wb, 9, &needed));
    CHECK(needed == 9 && memcmp(wb, w, sizeof w) == 0);
    /* quarter points are control points: exact */
    CHECK_OK(cagd_bspline_eval(s, 0.25, p, 2, &needed));
    CHECK_NEAR(p[0], 0.0, 1e-15);
    CHECK_NEAR(p[1], 1.0, 1e-15);
    for (i = 0; i <= 40; ++i) {
        double t = i / 40.0;
        CHECK_OK(cagd_bspline_eval(s, t, p, 2, &needed));
        CHECK_NEAR(hypot(p[0], p[1]), 1.0, TOL);
        /* the tangent of a circle is orthogonal to the radius */
        CHECK_OK(cagd_bspline_derivatives(s, t, 1, d, 4, &needed));
        CHECK_NEAR(d[0] * d[2] + d[1] * d[3], 0.0, 1e-13);
        CHECK(hypot(d[2], d[3]) > 1.0);
    }
    /* insertion keeps the circle */
    CHECK_OK(cagd_bspline_insert_knot(s, 0.1, 1, &r));
    for (i = 0; i <= 40; ++i) {
        CHECK_OK(cagd_bspline_eval(r, i / 40.0, p, 2, &needed));
        CHECK_NEAR(hypot(p[0], p[1]), 1.0, TOL);
    }
    rc = 0;
cleanup:
    cagd_bspline_free(r);
    cagd_bspline_free(s);
    return rc;
}

int cagd_ctest_bspline_to_beziers(void) {
    int rc = 1;
    CagdBSpline *s = NULL, *circle = NULL;
    CagdCurveList *list = NULL, *clist = NULL;
    CagdCurve *piece = NULL;
    double pts[12], w[9], p[2] = {0}, a = -1, b = -1, bound = -1;
    const double breaks[4] = {0.0, 0.3, 0.6, 1.0};
    size_t count = 0, needed = 0, degree = 0, i, k;
    bool rational = false;

    marsden_t3(U3, 6, pts);
    CHECK_OK(cagd_bspline_new(3, U3, 10, pts, 6, 2, &s));
    CHECK_OK(cagd_bspline_to_beziers(s, &list));
    CHECK_OK(cagd_curvelist_count(list, &count));
    CHECK(count == 3);
    for (i = 0; i < 3; ++i) {
        CHECK_OK(cagd_curvelist_interval(list, i, &a, &b));
        CHECK(a == breaks[i] && b == breaks[i + 1]);
        CHECK_STATUS(cagd_curvelist_bound(list, i, &bound), CAGD_ERR_NOT_AVAILABLE);
        CHECK_OK(cagd_curvelist_get(list, i, &piece));
        CHECK_OK(cagd_curve_degree(piece, &degree));
        CHECK(degree == 3);
        for (k = 0; k <= 8; ++k) {
            double sp = k / 8.0, t = a + sp * (b - a);
            CHECK_OK(cagd_curve_eval(piece, sp, p, 2, &needed));
            CHECK_NEAR(p[0], t, TOL);
            CHECK_NEAR(p[1], t * t * t, TOL);
        }
        cagd_curve_free(piece);
        piece = NULL;
    }
    /* the NURBS circle: 4 rational quadratic quarters on the unit circle */
    for (i = 0; i < 9; ++i) w[i] = (i % 2) ? sqrt(0.5) : 1.0;
    CHECK_OK(cagd_bspline_new_rational(2, CIRCLE_U, 12, CIRCLE_P, w, 9, 2, &circle));
    CHECK_OK(cagd_bspline_to_beziers(circle, &clist));
    CHECK_OK(cagd_curvelist_count(clist, &count));
    CHECK(count == 4);
    for (i = 0; i < 4; ++i) {
        CHECK_OK(cagd_curvelist_interval(clist, i, &a, &b));
        CHECK(a == 0.25 * i && b == 0.25 * (i + 1));
        CHECK_OK(cagd_curvelist_get(clist, i, &piece));
        CHECK_OK(cagd_curve_is_rational(piece, &rational));
        CHECK(rational);
        CHECK_OK(cagd_curve_eval(piece, 0.5, p, 2, &needed));
        CHECK_NEAR(hypot(p[0], p[1]), 1.0, TOL);
        cagd_curve_free(piece);
        piece = NULL;
    }
    /* a piece outlives its list */
    CHECK_OK(cagd_curvelist_get(clist, 3, &piece));
    cagd_curvelist_free(clist);
    clist = NULL;
    CHECK_OK(cagd_curve_eval(piece, 1.0, p, 2, &needed));
    CHECK_NEAR(p[0], 1.0, 1e-15);
    CHECK_NEAR(p[1], 0.0, 1e-15);
    rc = 0;
cleanup:
    cagd_curve_free(piece);
    cagd_curvelist_free(clist);
    cagd_curvelist_free(list);
    cagd_bspline_free(circle);
    cagd_bspline_free(s);
    return rc;
}
