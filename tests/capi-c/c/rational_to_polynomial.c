/* cagd_bspline_to_polynomial / cagd_bsplinesurface_to_polynomial: NURBS to polynomial
 * within a tolerance. The half circle (two rational quadratic quarter arcs, double knot at
 * 1/2) becomes cubic; the certified bound must be <= the tolerance and >= the radial error
 * | |S(t)| - 1 | sampled here (the parametric distance is at least the radial one); the
 * double knot (C^0 in the input) is reported with order 0; equal weights come back as the
 * same control points with bound 0; bad input gives the documented statuses. */
#include "ctest.h"

static const double HALF_U[8] = {0, 0, 0, 0.5, 0.5, 1, 1, 1};
static const double HALF_P[10] = {1, 0, 1, 1, 0, 1, -1, 1, -1, 0};
#define H 0.70710678118654752440

int cagd_ctest_rational_to_polynomial_half_circle(void) {
    int rc = 1;
    CagdBSpline *s = NULL, *out = NULL;
    CagdReport *rep = NULL;
    const double w[5] = {1, H, 1, H, 1};
    double bound = -1, measured = -1, seg = -1, p[2], knots[1] = {0};
    int32_t orders[1] = {-1};
    size_t pieces = 0, spans_in = 0, spans_out = 0, needed = 0, degree = 0, k;
    bool rational = true;
    double worst = 0;

    CHECK_OK(cagd_bspline_new_rational(2, HALF_U, 8, HALF_P, w, 5, 2, &s));
    CHECK_OK(cagd_bspline_to_polynomial(s, 3, 1e-5, &out, &rep));
    CHECK_OK(cagd_bspline_is_rational(out, &rational));
    CHECK_OK(cagd_bspline_degree(out, &degree));
    CHECK(!rational && degree == 3);
    CHECK_OK(cagd_report_bound(rep, &bound));
    CHECK_OK(cagd_report_max_error(rep, &measured));
    CHECK(bound <= 1e-5 && measured <= bound && measured > 0);
    for (k = 0; k <= 4000; ++k) {
        double t = (double)k / 4000.0, r;
        CHECK_OK(cagd_bspline_eval(out, t, p, 2, &needed));
        r = fabs(sqrt(p[0] * p[0] + p[1] * p[1]) - 1.0);
        if (r > worst) worst = r;
    }
    CHECK(worst <= bound);
    CHECK_OK(cagd_report_spline(rep, &seg, &pieces, &spans_in, &spans_out));
    CHECK(spans_in == 2 && spans_out >= 2 && pieces >= spans_out && seg <= bound);
    CHECK_OK(cagd_report_spline_continuity(rep, knots, orders, 1, &needed));
    CHECK(needed == 1 && knots[0] == 0.5 && orders[0] == 0);
    rc = 0;
cleanup:
    cagd_report_free(rep);
    cagd_bspline_free(out);
    cagd_bspline_free(s);
    return rc;
}

int cagd_ctest_rational_to_polynomial_equal_weights_and_errors(void) {
    int rc = 1;
    CagdBSpline *s = NULL, *out = NULL, *half = NULL;
    CagdReport *rep = NULL;
    CagdBSplineSurface *surf = NULL, *sout = NULL;
    const double w[5] = {3, 3, 3, 3, 3};
    const double hw[5] = {1, H, 1, H, 1};
    const double u1[4] = {0, 0, 1, 1};
    const double bad_u[9] = {0, 0, 0, 0.5, 0.5, 0.5, 1, 1, 1};
    const double bad_p[12] = {0, 0, 1, 1, 2, 0, 3, 1, 4, 0, 5, 1};
    const double bad_w[6] = {1, 2, 1, 1, 3, 1};
    double pts[10] = {0}, bound = -1, sp[30], sw[10];
    size_t needed = 0, shape[5] = {0}, i;
    bool rational = true;

    /* Equal weights: the same points, a bound at rounding level (the evaluation rounding of
     * the rational form, so that it is never below a measurement). */
    CHECK_OK(cagd_bspline_new_rational(2, HALF_U, 8, HALF_P, w, 5, 2, &s));
    CHECK_OK(cagd_bspline_to_polynomial(s, 0, 1e-9, &out, &rep));
    CHECK_OK(cagd_bspline_points(out, pts, 10, &needed));
    CHECK(needed == 10 && memcmp(pts, HALF_P, sizeof pts) == 0);
    CHECK_OK(cagd_report_bound(rep, &bound));
    CHECK(bound >= 0.0 && bound < 1e-13);
    cagd_report_free(rep);
    rep = NULL;
    cagd_bspline_free(out);
    out = NULL;

    /* Bad input: statuses as documented; outputs untouched. */
    CHECK_OK(cagd_bspline_new_rational(2, HALF_U, 8, HALF_P, hw, 5, 2, &half));
    CHECK_STATUS(cagd_bspline_to_polynomial(half, 3, 0.0, &out, &rep), CAGD_ERR_INVALID_ARGUMENT);
    CHECK_STATUS(cagd_bspline_to_polynomial(half, 3, NAN, &out, &rep), CAGD_ERR_INVALID_ARGUMENT);
    CHECK_STATUS(cagd_bspline_to_polynomial(half, 65, 1e-3, &out, &rep), CAGD_ERR_BAD_DEGREE_PAIR);
    CHECK_STATUS(cagd_bspline_to_polynomial(half, 3, 1e-300, &out, &rep),
                 CAGD_ERR_CONDITION_NOT_MET);
    CHECK_STATUS(cagd_bspline_to_polynomial(NULL, 3, 1e-3, &out, &rep), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_bspline_to_polynomial(half, 3, 1e-3, NULL, &rep), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_bspline_to_polynomial(half, 3, 1e-3, &out, NULL), CAGD_ERR_NULL_POINTER);
    CHECK(out == NULL && rep == NULL);
    cagd_bspline_free(s);
    s = NULL;
    CHECK_OK(cagd_bspline_new_rational(2, bad_u, 9, bad_p, bad_w, 6, 2, &s));
    CHECK_STATUS(cagd_bspline_to_polynomial(s, 2, 1e-3, &out, &rep), CAGD_ERR_BAD_KNOTS);

    /* Surface: a half cylinder (the half circle in u, linear in v) to bicubic x linear. */
    for (i = 0; i < 5; ++i) {
        sp[6 * i] = HALF_P[2 * i];
        sp[6 * i + 1] = HALF_P[2 * i + 1];
        sp[6 * i + 2] = 0.0;
        sp[6 * i + 3] = HALF_P[2 * i];
        sp[6 * i + 4] = HALF_P[2 * i + 1];
        sp[6 * i + 5] = 2.0;
        sw[2 * i] = sw[2 * i + 1] = hw[i];
    }
    CHECK_OK(cagd_bsplinesurface_new(2, 1, HALF_U, 8, u1, 4, sp, sw, 5, 2, 3, &surf));
    CHECK_OK(cagd_bsplinesurface_to_polynomial(surf, 3, 0, 1e-4, &sout, &rep));
    CHECK_OK(cagd_bsplinesurface_shape(sout, shape, &rational));
    CHECK(shape[0] == 3 && shape[1] == 1 && shape[4] == 3 && !rational);
    CHECK_OK(cagd_report_bound(rep, &bound));
    CHECK(bound > 0 && bound <= 1e-4);
    CHECK_STATUS(cagd_bsplinesurface_to_polynomial(surf, 3, 1, -1.0, &sout, &rep),
                 CAGD_ERR_INVALID_ARGUMENT);
    rc = 0;
cleanup:
    cagd_report_free(rep);
    cagd_bsplinesurface_free(sout);
    cagd_bsplinesurface_free(surf);
    cagd_bspline_free(out);
    cagd_bspline_free(half);
    cagd_bspline_free(s);
    return rc;
}
