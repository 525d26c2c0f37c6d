/* CagdBSplineSurface: new -> eval / read back -> reduce -> free, against closed forms.
 * - Bernstein coefficients: on one bicubic span, P_ij = (i/3, j/3, i(i-1)/6 * j/3) is
 *   S(u, v) = (u, v, u^2 v) (coefficients of u: i/3; of u^2: i(i-1)/6; of v: j/3), whose
 *   true degrees are (2, 1): the reduction to (2, 1) is exact.
 * - A NURBS cylinder: the rational quarter circle (weights 1, 1/sqrt 2, 1) in u times a
 *   line in v: x^2 + y^2 = 1 and z = v everywhere. */
#include <stdint.h>

#include "ctest.h"

static const double K3[8] = {0, 0, 0, 0, 1, 1, 1, 1};
static const double K1[4] = {0, 0, 1, 1};
static const double K2[6] = {0, 0, 0, 1, 1, 1};

static void bicubic_u2v(double *pts) {
    size_t i, j;
    for (i = 0; i < 4; ++i) {
        for (j = 0; j < 4; ++j) {
            double *x = pts + (i * 4 + j) * 3;
            x[0] = i / 3.0;
            x[1] = j / 3.0;
            x[2] = (double)(i * (i - (i > 0))) / 6.0 * (j / 3.0);
        }
    }
}

int cagd_ctest_bsplinesurface_roundtrip(void) {
    int rc = 1;
    CagdBSplineSurface *s = NULL, *cyl = NULL;
    double pts[48], back[48] = {0}, w[6], cp[18], q[3] = {0};
    size_t shape[5] = {0}, needed = 0, i, j;
    bool rational = true;
    const double r2 = sqrt(0.5);
    const double quarter[6] = {1, 0, 1, 1, 0, 1};

    bicubic_u2v(pts);
    CHECK_OK(cagd_bsplinesurface_new(3, 3, K3, 8, K3, 8, pts, NULL, 4, 4, 3, &s));
    CHECK_OK(cagd_bsplinesurface_shape(s, shape, &rational));
    CHECK(shape[0] == 3 && shape[1] == 3 && shape[2] == 4 && shape[3] == 4 && shape[4] == 3);
    CHECK(!rational);
    CHECK_STATUS(cagd_bsplinesurface_array(s, 2, NULL, 0, &needed), CAGD_ERR_BUFFER_TOO_SMALL);
    CHECK(needed == 48);
    CHECK_OK(cagd_bsplinesurface_array(s, 2, back, 48, &needed));
    CHECK(memcmp(back, pts, sizeof pts) == 0);
    CHECK_OK(cagd_bsplinesurface_array(s, 0, back, 48, &needed));
    CHECK(needed == 8 && memcmp(back, K3, sizeof K3) == 0);
    CHECK_OK(cagd_bsplinesurface_array(s, 1, back, 48, &needed));
    CHECK(needed == 8 && memcmp(back, K3, sizeof K3) == 0);
    CHECK_OK(cagd_bsplinesurface_array(s, 3, back, 48, &needed));
    CHECK(needed == 16 && back[0] == 1.0 && back[15] == 1.0);
    for (i = 0; i <= 4; ++i) {
        for (j = 0; j <= 4; ++j) {
            double u = i / 4.0, v = j / 4.0;
            CHECK_OK(cagd_bsplinesurface_eval(s, u, v, q, 3, &needed));
            CHECK_NEAR(q[0], u, 1e-15);
            CHECK_NEAR(q[1], v, 1e-15);
            CHECK_NEAR(q[2], u * u * v, 1e-15);
        }
    }
    /* the NURBS cylinder: 3 x 2 net, weights (1, r2, 1) along u */
    for (i = 0; i < 3; ++i) {
        for (j = 0; j < 2; ++j) {
            cp[(i * 2 + j) * 3] = quarter[2 * i];
            cp[(i * 2 + j) * 3 + 1] = quarter[2 * i + 1];
            cp[(i * 2 + j) * 3 + 2] = (double)j;
            w[i * 2 + j] = (i == 1) ? r2 : 1.0;
        }
    }
    CHECK_OK(cagd_bsplinesurface_new(2, 1, K2, 6, K1, 4, cp, w, 3, 2, 3, &cyl));
    CHECK_OK(cagd_bsplinesurface_shape(cyl, shape, &rational));
    CHECK(rational);
    for (i = 0; i <= 8; ++i) {
        double u = i / 8.0, v = 1.0 - i / 8.0;
        CHECK_OK(cagd_bsplinesurface_eval(cyl, u, v, q, 3, &needed));
        CHECK_NEAR(hypot(q[0], q[1]), 1.0, 1e-15);
        CHECK_NEAR(q[2], v, 1e-15);
    }
    rc = 0;
cleanup:
    cagd_bsplinesurface_free(cyl);
    cagd_bsplinesurface_free(s);
    return rc;
}

int cagd_ctest_bsplinesurface_reduce(void) {
    int rc = 1;
    CagdBSplineSurface *s = NULL, *r = NULL;
    CagdReport *rep = NULL;
    CagdReduceOptions o;
    double pts[48], q[3] = {0}, bound = -1, measured = -1;
    size_t shape[5] = {0}, needed = 0, deg[4] = {0}, pieces = 0, i, j;
    bool rational = true;
    int32_t pm = 0;

    bicubic_u2v(pts);
    CHECK_OK(cagd_bsplinesurface_new(3, 3, K3, 8, K3, 8, pts, NULL, 4, 4, 3, &s));
    CHECK_OK(cagd_reduce_options_init(&o));
    o.target = 2;
    o.target_v = 1;
    o.measure = true;
    CHECK_OK(cagd_bsplinesurface_reduce(s, &o, &r, &rep));
    CHECK_OK(cagd_bsplinesurface_shape(r, shape, &rational));
    CHECK(shape[0] == 2 && shape[1] == 1 && shape[2] == 3 && shape[3] == 2);
    CHECK_OK(cagd_report_patch(rep, &pm, deg, &pieces));
    CHECK(pm == -1 && deg[0] == 3 && deg[1] == 3 && deg[2] == 2 && deg[3] == 1 && pieces == 1);
    CHECK_OK(cagd_report_bound(rep, &bound));
    CHECK_OK(cagd_report_max_error(rep, &measured));
    CHECK(measured <= bound && bound < 1e-12); /* exact: rounding allowance only */
    for (i = 0; i <= 4; ++i) {
        for (j = 0; j <= 4; ++j) {
            double u = i / 4.0, v = j / 4.0;
            CHECK_OK(cagd_bsplinesurface_eval(r, u, v, q, 3, &needed));
            CHECK_NEAR(q[0], u, 1e-14);
            CHECK_NEAR(q[1], v, 1e-14);
            CHECK_NEAR(q[2], u * u * v, 1e-14);
        }
    }
    rc = 0;
cleanup:
    cagd_report_free(rep);
    cagd_bsplinesurface_free(r);
    cagd_bsplinesurface_free(s);
    return rc;
}

int cagd_ctest_bsplinesurface_bad_input(void) {
    int rc = 1;
    CagdBSplineSurface *s = NULL, *r = NULL;
    CagdReport *rep = NULL;
    CagdReduceOptions o;
    double pts[48], w[16], buf[8] = {-7}, bad_k[8], q[3];
    size_t shape[5], needed = 0, i;
    bool rat = false;

    bicubic_u2v(pts);
    for (i = 0; i < 16; ++i) w[i] = 1.0;
    memcpy(bad_k, K3, sizeof bad_k);
    CHECK_STATUS(cagd_bsplinesurface_new(3, 3, NULL, 8, K3, 8, pts, NULL, 4, 4, 3, &s),
                 CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_bsplinesurface_new(3, 3, K3, 8, NULL, 8, pts, NULL, 4, 4, 3, &s),
                 CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_bsplinesurface_new(3, 3, K3, 8, K3, 8, NULL, NULL, 4, 4, 3, &s),
                 CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_bsplinesurface_new(3, 3, K3, 8, K3, 8, pts, NULL, 4, 4, 3, NULL),
                 CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_bsplinesurface_new(3, 3, K3, 8, K3, 7, pts, NULL, 4, 4, 3, &s),
                 CAGD_ERR_BAD_KNOTS);
    bad_k[4] = 0.5; /* 0 0 0 0 0.5 1 1 1 is fine; make it decrease */
    bad_k[3] = 0.7;
    CHECK_STATUS(cagd_bsplinesurface_new(3, 3, bad_k, 8, K3, 8, pts, NULL, 4, 4, 3, &s),
                 CAGD_ERR_BAD_KNOTS);
    memcpy(bad_k, K3, sizeof bad_k);
    bad_k[2] = NAN;
    CHECK_STATUS(cagd_bsplinesurface_new(3, 3, K3, 8, bad_k, 8, pts, NULL, 4, 4, 3, &s),
                 CAGD_ERR_NON_FINITE);
    CHECK_STATUS(cagd_bsplinesurface_new(1, 3, K3, 8, K3, 8, pts, NULL, 6, 4, 2, &s),
                 CAGD_ERR_MULTIPLICITY); /* 0 four times > degree 1 + 1 */
    CHECK_STATUS(cagd_bsplinesurface_new(3, 3, K3, 8, K3, 8, pts, NULL, 4, 4, 0, &s),
                 CAGD_ERR_INVALID_ARGUMENT);
    CHECK_STATUS(cagd_bsplinesurface_new(3, 3, K3, 8, K3, 8, pts, NULL, SIZE_MAX, 4, 3, &s),
                 CAGD_ERR_INVALID_ARGUMENT);
    w[5] = -1.0;
    CHECK_STATUS(cagd_bsplinesurface_new(3, 3, K3, 8, K3, 8, pts, w, 4, 4, 3, &s),
                 CAGD_ERR_NON_POSITIVE_WEIGHT);
    pts[7] = INFINITY;
    CHECK_STATUS(cagd_bsplinesurface_new(3, 3, K3, 8, K3, 8, pts, NULL, 4, 4, 3, &s),
                 CAGD_ERR_NON_FINITE);
    CHECK(s == NULL);
    bicubic_u2v(pts);
    CHECK_OK(cagd_bsplinesurface_new(3, 3, K3, 8, K3, 8, pts, NULL, 4, 4, 3, &s));
    CHECK_STATUS(cagd_bsplinesurface_shape(NULL, shape, &rat), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_bsplinesurface_shape(s, NULL, &rat), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_bsplinesurface_shape(s, shape, NULL), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_bsplinesurface_array(NULL, 0, buf, 8, &needed), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_bsplinesurface_array(s, 0, NULL, 8, &needed), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_bsplinesurface_array(s, 0, buf, 8, NULL), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_bsplinesurface_array(s, 4, buf, 8, &needed), CAGD_ERR_INVALID_ARGUMENT);
    CHECK_STATUS(cagd_bsplinesurface_array(s, -1, buf, 8, &needed), CAGD_ERR_INVALID_ARGUMENT);
    buf[0] = -7.0;
    CHECK_STATUS(cagd_bsplinesurface_array(s, 2, buf, 8, &needed), CAGD_ERR_BUFFER_TOO_SMALL);
    CHECK(needed == 48 && buf[0] == -7.0);
    CHECK_STATUS(cagd_bsplinesurface_eval(NULL, 0.5, 0.5, q, 3, &needed), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_bsplinesurface_eval(s, 0.5, 0.5, NULL, 3, &needed), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_bsplinesurface_eval(s, 0.5, 0.5, q, 3, NULL), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_bsplinesurface_eval(s, NAN, 0.5, q, 3, &needed), CAGD_ERR_INVALID_ARGUMENT);
    CHECK_STATUS(cagd_bsplinesurface_eval(s, 0.5, 0.5, q, 2, &needed), CAGD_ERR_BUFFER_TOO_SMALL);
    /* reduction */
    CHECK_OK(cagd_reduce_options_init(&o));
    o.target = 2;
    o.target_v = 2;
    CHECK_STATUS(cagd_bsplinesurface_reduce(NULL, &o, &r, &rep), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_bsplinesurface_reduce(s, NULL, &r, &rep), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_bsplinesurface_reduce(s, &o, NULL, &rep), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_bsplinesurface_reduce(s, &o, &r, NULL), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_bsplinesurface_reduce(s, &o, (CagdBSplineSurface **)(void *)&rep, &rep),
                 CAGD_ERR_INVALID_ARGUMENT);
    o.struct_size = 4;
    CHECK_STATUS(cagd_bsplinesurface_reduce(s, &o, &r, &rep), CAGD_ERR_INVALID_ARGUMENT);
    o.struct_size = sizeof o;
    o.target = o.target_v = 3; /* no reduction at all */
    CHECK_STATUS(cagd_bsplinesurface_reduce(s, &o, &r, &rep), CAGD_ERR_BAD_DEGREE_PAIR);
    o.target = 0;
    CHECK_STATUS(cagd_bsplinesurface_reduce(s, &o, &r, &rep), CAGD_ERR_BAD_DEGREE_PAIR);
    o.target = 2;
    o.continuity = 1; /* floor((2 - 1) / 2) = 0 */
    CHECK_STATUS(cagd_bsplinesurface_reduce(s, &o, &r, &rep), CAGD_ERR_TOO_MANY_CONSTRAINTS);
    o.continuity = 0;
    o.method = CAGD_METHOD_FORREST;
    CHECK_STATUS(cagd_bsplinesurface_reduce(s, &o, &r, &rep), CAGD_ERR_INVALID_ARGUMENT);
    CHECK(r == NULL && rep == NULL);
    cagd_bsplinesurface_free(NULL);
    cagd_bsplinesurface_free(NULL);
    rc = 0;
cleanup:
    cagd_report_free(rep);
    cagd_bsplinesurface_free(r);
    cagd_bsplinesurface_free(s);
    return rc;
}

/* To a tolerance: a bicubic with a genuine cubic term (z = u^3 v on one span, Bernstein
 * coefficients of u^3: 0, 0, 0, 1) reduced to degrees (2, 1): every tolerance is met by the
 * certified bound, the bound is not below the error sampled here, and a smaller tolerance
 * needs at least as many patches. */
int cagd_ctest_bsplinesurface_reduce_to_tolerance(void) {
    int rc = 1;
    CagdBSplineSurface *s = NULL, *r = NULL;
    CagdReport *rep = NULL;
    CagdReduceOptions o;
    double pts[48], q[3] = {0}, bound = -1;
    size_t needed = 0, deg[4] = {0}, pieces = 0, last_pieces = 0, i, j, k, st;
    size_t fit_pieces[3] = {0, 0, 0};
    int32_t pm = 0;
    const double tols[3] = {1e-2, 1e-3, 1e-4};

    for (i = 0; i < 4; ++i) {
        for (j = 0; j < 4; ++j) {
            double *x = pts + (i * 4 + j) * 3;
            x[0] = i / 3.0;
            x[1] = j / 3.0;
            x[2] = (i == 3 ? 1.0 : 0.0) * (j / 3.0);
        }
    }
    CHECK_OK(cagd_bsplinesurface_new(3, 3, K3, 8, K3, 8, pts, NULL, 4, 4, 3, &s));
    CHECK_OK(cagd_reduce_options_init(&o));
    o.target = 2;
    o.target_v = 1;
    /* both strategies: the global fit (default) and patch-wise uniform refinement */
    for (st = 0; st < 2; ++st) {
        o.spline_strategy = st == 0 ? CAGD_SPLINE_FIT : CAGD_SPLINE_SEGMENTS;
        last_pieces = 0;
        for (k = 0; k < 3; ++k) {
            double worst = 0.0;
            o.tolerance = tols[k];
            CHECK_OK(cagd_bsplinesurface_reduce_to_tolerance(s, &o, &r, &rep));
            CHECK_OK(cagd_report_bound(rep, &bound));
            CHECK(bound <= tols[k]);
            CHECK_OK(cagd_report_patch(rep, &pm, deg, &pieces));
            CHECK(deg[2] == 2 && deg[3] == 1 && pieces >= last_pieces);
            last_pieces = pieces;
            if (st == 0) fit_pieces[k] = pieces;
            else CHECK(fit_pieces[k] <= pieces); /* the fit needs no more patches */
            for (i = 0; i <= 20; ++i) {
                for (j = 0; j <= 20; ++j) {
                    double u = i / 20.0, v = j / 20.0, d;
                    CHECK_OK(cagd_bsplinesurface_eval(r, u, v, q, 3, &needed));
                    d = fabs(q[2] - u * u * u * v) + fabs(q[0] - u) + fabs(q[1] - v);
                    worst = d > worst ? d : worst;
                }
            }
            CHECK(worst <= bound);
            cagd_report_free(rep);
            rep = NULL;
            cagd_bsplinesurface_free(r);
            r = NULL;
        }
    }
    o.tolerance = 0.0;
    CHECK_STATUS(cagd_bsplinesurface_reduce_to_tolerance(s, &o, &r, &rep), CAGD_ERR_INVALID_ARGUMENT);
    CHECK(r == NULL && rep == NULL);
    o.tolerance = 1e-300;
    CHECK_STATUS(cagd_bsplinesurface_reduce_to_tolerance(s, &o, &r, &rep), CAGD_ERR_NO_CONVERGENCE);
    o.spline_strategy = CAGD_SPLINE_FIT;
    CHECK_STATUS(cagd_bsplinesurface_reduce_to_tolerance(s, &o, &r, &rep),
                 CAGD_ERR_CONDITION_NOT_MET);
    o.tolerance = 1e-3;
    o.spline_strategy = CAGD_SPLINE_PIEGL_TILLER_1995; /* curves only */
    CHECK_STATUS(cagd_bsplinesurface_reduce_to_tolerance(s, &o, &r, &rep), CAGD_ERR_INVALID_ARGUMENT);
    o.spline_strategy = 7;
    CHECK_STATUS(cagd_bsplinesurface_reduce_to_tolerance(s, &o, &r, &rep), CAGD_ERR_INVALID_ARGUMENT);
    o.spline_strategy = CAGD_SPLINE_FIT;
    o.spline_continuity = -2;
    CHECK_STATUS(cagd_bsplinesurface_reduce_to_tolerance(s, &o, &r, &rep), CAGD_ERR_INVALID_ARGUMENT);
    o.spline_continuity = 1; /* target_v = 1: at most C0 across v knot lines */
    CHECK_STATUS(cagd_bsplinesurface_reduce_to_tolerance(s, &o, &r, &rep),
                 CAGD_ERR_TOO_MANY_CONSTRAINTS);
    CHECK(r == NULL && rep == NULL);
    o.spline_continuity = -1;
    o.tolerance = 1e-3;
    CHECK_STATUS(cagd_bsplinesurface_reduce_to_tolerance(NULL, &o, &r, &rep), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_bsplinesurface_reduce_to_tolerance(s, NULL, &r, &rep), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_bsplinesurface_reduce_to_tolerance(s, &o, NULL, &rep), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_bsplinesurface_reduce_to_tolerance(s, &o, &r, NULL), CAGD_ERR_NULL_POINTER);
    rc = 0;
cleanup:
    cagd_report_free(rep);
    cagd_bsplinesurface_free(r);
    cagd_bsplinesurface_free(s);
    return rc;
}
