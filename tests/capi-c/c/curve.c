/* CagdCurve: new -> operate -> read back -> free, checked against closed forms.
 * The quadratic P = (0,0), (1,2), (2,0) is C(t) = (2t, 4t(1 - t)); its values at dyadic t
 * and its elevation / subdivision points are exact in binary floating point up to a few
 * ulp, so the tolerance EXACT = 1e-15 (relative to the curve's size 2) is ample. */
#include "ctest.h"

#define EXACT 1e-15

static const double QUAD[6] = {0.0, 0.0, 1.0, 2.0, 2.0, 0.0};

int cagd_ctest_curve_roundtrip(void) {
    int rc = 1;
    CagdCurve *c = NULL;
    size_t degree = 0, dim = 0, needed = 0;
    bool rational = true;
    double pts[6] = {0}, w[3] = {0}, p[2] = {0};

    CHECK_OK(cagd_curve_new(QUAD, 3, 2, &c));
    CHECK(c != NULL);
    CHECK_OK(cagd_curve_degree(c, &degree));
    CHECK_OK(cagd_curve_dim(c, &dim));
    CHECK_OK(cagd_curve_is_rational(c, &rational));
    CHECK(degree == 2 && dim == 2 && !rational);

    /* size query, then read back */
    CHECK_STATUS(cagd_curve_points(c, NULL, 0, &needed), CAGD_ERR_BUFFER_TOO_SMALL);
    CHECK(needed == 6);
    CHECK_OK(cagd_curve_points(c, pts, 6, &needed));
    CHECK(memcmp(pts, QUAD, sizeof QUAD) == 0);
    CHECK_OK(cagd_curve_weights(c, w, 3, &needed));
    CHECK(needed == 3 && w[0] == 1.0 && w[1] == 1.0 && w[2] == 1.0);

    CHECK_OK(cagd_curve_eval(c, 0.5, p, 2, &needed));
    CHECK(needed == 2);
    CHECK_NEAR(p[0], 1.0, EXACT);
    CHECK_NEAR(p[1], 1.0, EXACT);
    CHECK_OK(cagd_curve_eval(c, 0.25, p, 2, &needed));
    CHECK_NEAR(p[0], 0.5, EXACT);
    CHECK_NEAR(p[1], 0.75, EXACT);
    rc = 0;
cleanup:
    cagd_curve_free(c);
    return rc;
}

int cagd_ctest_curve_eval_many(void) {
    int rc = 1;
    CagdCurve *c = NULL;
    const double ts[5] = {0.0, 0.25, 0.5, 0.75, 1.0};
    double out[10] = {0};
    size_t needed = 0;
    int j;

    CHECK_OK(cagd_curve_new(QUAD, 3, 2, &c));
    CHECK_STATUS(cagd_curve_eval_many(c, ts, 5, NULL, 0, &needed), CAGD_ERR_BUFFER_TOO_SMALL);
    CHECK(needed == 10);
    CHECK_OK(cagd_curve_eval_many(c, ts, 5, out, 10, &needed));
    for (j = 0; j < 5; ++j) {
        CHECK_NEAR(out[2 * j], 2.0 * ts[j], EXACT);
        CHECK_NEAR(out[2 * j + 1], 4.0 * ts[j] * (1.0 - ts[j]), EXACT);
    }
    /* zero parameters: nothing to write, needed = 0 */
    CHECK_OK(cagd_curve_eval_many(c, ts, 0, NULL, 0, &needed));
    CHECK(needed == 0);
    rc = 0;
cleanup:
    cagd_curve_free(c);
    return rc;
}

int cagd_ctest_curve_rational_circle(void) {
    int rc = 1;
    CagdCurve *c = NULL, *e = NULL;
    /* quarter circle: (1,0), (1,1), (0,1) with weights 1, sqrt(2)/2, 1 */
    const double pts[6] = {1.0, 0.0, 1.0, 1.0, 0.0, 1.0};
    const double w[3] = {1.0, sqrt(0.5), 1.0};
    double out[2 * 9] = {0}, ts[9], wout[4] = {0};
    size_t needed = 0, degree = 0;
    bool rational = false;
    int j;

    CHECK_OK(cagd_curve_new_rational(pts, w, 3, 2, &c));
    CHECK_OK(cagd_curve_is_rational(c, &rational));
    CHECK(rational);
    CHECK_OK(cagd_curve_weights(c, wout, 4, &needed));
    CHECK(needed == 3 && wout[1] == w[1] && wout[3] == 0.0);
    for (j = 0; j < 9; ++j) ts[j] = j / 8.0;
    CHECK_OK(cagd_curve_eval_many(c, ts, 9, out, 18, &needed));
    for (j = 0; j < 9; ++j) {
        /* on the unit circle; de Casteljau in homogeneous space: a few ulp */
        CHECK_NEAR(hypot(out[2 * j], out[2 * j + 1]), 1.0, 1e-15);
    }
    CHECK_NEAR(out[8], sqrt(0.5), 1e-15);
    CHECK_NEAR(out[9], sqrt(0.5), 1e-15);

    /* elevation of a rational curve keeps it on the circle */
    CHECK_OK(cagd_curve_elevate(c, 2, &e));
    CHECK_OK(cagd_curve_degree(e, &degree));
    CHECK(degree == 4);
    CHECK_OK(cagd_curve_eval(e, 0.3, out, 2, &needed));
    CHECK_NEAR(hypot(out[0], out[1]), 1.0, 1e-15);
    rc = 0;
cleanup:
    cagd_curve_free(e);
    cagd_curve_free(c);
    return rc;
}

int cagd_ctest_curve_elevate_subdivide_segment(void) {
    int rc = 1;
    CagdCurve *c = NULL, *e = NULL, *l = NULL, *r = NULL, *s = NULL;
    /* elevation by one: Q_i = i/3 P_{i-1} + (1 - i/3) P_i */
    const double elevated[8] = {0.0, 0.0, 2.0 / 3.0, 4.0 / 3.0, 4.0 / 3.0, 4.0 / 3.0, 2.0, 0.0};
    const double left[6] = {0.0, 0.0, 0.5, 1.0, 1.0, 1.0};
    const double right[6] = {1.0, 1.0, 1.5, 1.0, 2.0, 0.0};
    double buf[8] = {0};
    size_t needed = 0, k;

    CHECK_OK(cagd_curve_new(QUAD, 3, 2, &c));
    CHECK_OK(cagd_curve_elevate(c, 1, &e));
    CHECK_OK(cagd_curve_points(e, buf, 8, &needed));
    CHECK(needed == 8);
    for (k = 0; k < 8; ++k) CHECK_NEAR(buf[k], elevated[k], EXACT);

    CHECK_OK(cagd_curve_subdivide(c, 0.5, &l, &r));
    CHECK_OK(cagd_curve_points(l, buf, 8, &needed));
    CHECK(needed == 6);
    for (k = 0; k < 6; ++k) CHECK_NEAR(buf[k], left[k], EXACT);
    CHECK_OK(cagd_curve_points(r, buf, 8, &needed));
    for (k = 0; k < 6; ++k) CHECK_NEAR(buf[k], right[k], EXACT);

    /* the piece on [0.25, 0.75] runs from C(0.25) = (0.5, 0.75) to C(0.75) = (1.5, 0.75) */
    CHECK_OK(cagd_curve_segment(c, 0.25, 0.75, &s));
    CHECK_OK(cagd_curve_points(s, buf, 8, &needed));
    CHECK_NEAR(buf[0], 0.5, EXACT);
    CHECK_NEAR(buf[1], 0.75, EXACT);
    CHECK_NEAR(buf[4], 1.5, EXACT);
    CHECK_NEAR(buf[5], 0.75, EXACT);
    rc = 0;
cleanup:
    cagd_curve_free(s);
    cagd_curve_free(r);
    cagd_curve_free(l);
    cagd_curve_free(e);
    cagd_curve_free(c);
    return rc;
}
