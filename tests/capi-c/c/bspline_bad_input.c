/* CagdBSpline and CagdCurveList: bad knots, NULL for every pointer, NaN, bad weights,
 * short buffers, size queries, free(NULL). */
#include <stdint.h>

#include "ctest.h"

/* A valid clamped quadratic with 5 points (8 knots). */
static const double U[8] = {0, 0, 0, 0.4, 0.6, 1, 1, 1};
static const double P[10] = {0, 0, 1, 2, 2, 3, 3, 1, 4, 0};
static const double W[5] = {1, 2, 1, 0.5, 1};

int cagd_ctest_bspline_new_bad_knots(void) {
    int rc = 1;
    CagdBSpline *s = NULL;
    const double decreasing[8] = {0, 0, 0, 0.6, 0.4, 1, 1, 1};
    const double nan_knot[8] = {0, 0, 0, NAN, 0.6, 1, 1, 1};
    const double inf_knot[8] = {0, 0, 0, 0.4, 0.6, 1, 1, INFINITY};
    /* degree 2, 7 points: 0.5 four times (> degree + 1 = 3) */
    const double too_many[10] = {0, 0, 0, 0.5, 0.5, 0.5, 0.5, 1, 1, 1};
    const double P7[14] = {0, 0, 1, 1, 2, 2, 3, 3, 4, 4, 5, 5, 6, 6};
    const double W7[7] = {1, 1, 1, 1, 1, 1, 1};
    /* degree 1, 2 points: domain [knots[1], knots[2]] = [0.5, 0.5] is empty */
    const double empty[4] = {0, 0.5, 0.5, 1};

    CHECK_STATUS(cagd_bspline_new(2, decreasing, 8, P, 5, 2, &s), CAGD_ERR_BAD_KNOTS);
    CHECK_MESSAGE_HAS("4"); /* the first decreasing index */
    CHECK_STATUS(cagd_bspline_new(2, U, 7, P, 5, 2, &s), CAGD_ERR_BAD_KNOTS);
    CHECK_STATUS(cagd_bspline_new(2, U, 9, P, 5, 2, &s), CAGD_ERR_BAD_KNOTS);
    CHECK_STATUS(cagd_bspline_new(3, U, 8, P, 5, 2, &s), CAGD_ERR_BAD_KNOTS); /* needs 9 */
    CHECK_STATUS(cagd_bspline_new(2, too_many, 10, P7, 7, 2, &s), CAGD_ERR_MULTIPLICITY);
    CHECK_STATUS(cagd_bspline_new(2, nan_knot, 8, P, 5, 2, &s), CAGD_ERR_NON_FINITE);
    CHECK_STATUS(cagd_bspline_new(2, inf_knot, 8, P, 5, 2, &s), CAGD_ERR_NON_FINITE);
    CHECK_STATUS(cagd_bspline_new(1, empty, 4, P, 2, 2, &s), CAGD_ERR_BAD_KNOTS);
    CHECK_STATUS(cagd_bspline_new_rational(2, decreasing, 8, P, W, 5, 2, &s),
                 CAGD_ERR_BAD_KNOTS);
    CHECK_STATUS(cagd_bspline_new_rational(2, too_many, 10, P7, W7, 7, 2, &s),
                 CAGD_ERR_MULTIPLICITY);
    CHECK_STATUS(cagd_bspline_new_rational(2, nan_knot, 8, P, W, 5, 2, &s),
                 CAGD_ERR_NON_FINITE);
    CHECK(s == NULL); /* never written on failure */
    rc = 0;
cleanup:
    cagd_bspline_free(s);
    return rc;
}

int cagd_ctest_bspline_new_bad_input(void) {
    int rc = 1;
    CagdBSpline *s = NULL;
    double nan_pts[10], w[5];
    const double U65[131] = {0};

    memcpy(nan_pts, P, sizeof nan_pts);
    nan_pts[5] = NAN;
    memcpy(w, W, sizeof w);
    CHECK_STATUS(cagd_bspline_new(2, NULL, 8, P, 5, 2, &s), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_bspline_new(2, U, 8, NULL, 5, 2, &s), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_bspline_new(2, U, 8, P, 5, 2, NULL), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_bspline_new_rational(2, NULL, 8, P, W, 5, 2, &s), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_bspline_new_rational(2, U, 8, NULL, W, 5, 2, &s), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_bspline_new_rational(2, U, 8, P, NULL, 5, 2, &s), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_bspline_new_rational(2, U, 8, P, W, 5, 2, NULL), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_bspline_new(2, U, 8, P, 5, 0, &s), CAGD_ERR_INVALID_ARGUMENT);
    CHECK_STATUS(cagd_bspline_new(2, U, 8, P, SIZE_MAX, 2, &s), CAGD_ERR_INVALID_ARGUMENT);
    CHECK_STATUS(cagd_bspline_new(2, U, 8, P, 0, 2, &s), CAGD_ERR_NOT_ENOUGH_POINTS);
    CHECK_STATUS(cagd_bspline_new(5, U, 8, P, 5, 2, &s), CAGD_ERR_NOT_ENOUGH_POINTS);
    CHECK_STATUS(cagd_bspline_new(65, U65, 131, U65, 65, 1, &s),
                 CAGD_ERR_DEGREE_OUT_OF_RANGE);
    CHECK_STATUS(cagd_bspline_new(2, U, 8, nan_pts, 5, 2, &s), CAGD_ERR_NON_FINITE);
    CHECK_STATUS(cagd_bspline_new_rational(2, U, 8, nan_pts, W, 5, 2, &s), CAGD_ERR_NON_FINITE);
    w[3] = -0.5;
    CHECK_STATUS(cagd_bspline_new_rational(2, U, 8, P, w, 5, 2, &s),
                 CAGD_ERR_NON_POSITIVE_WEIGHT);
    CHECK_MESSAGE_HAS("-0.5");
    w[3] = 0.0;
    CHECK_STATUS(cagd_bspline_new_rational(2, U, 8, P, w, 5, 2, &s),
                 CAGD_ERR_NON_POSITIVE_WEIGHT);
    w[3] = NAN;
    CHECK_STATUS(cagd_bspline_new_rational(2, U, 8, P, w, 5, 2, &s),
                 CAGD_ERR_NON_POSITIVE_WEIGHT);
    CHECK(s == NULL);
    cagd_bspline_free(NULL);
    cagd_bspline_free(NULL);
    rc = 0;
cleanup:
    cagd_bspline_free(s);
    return rc;
}

int cagd_ctest_bspline_ops_bad_input(void) {
    int rc = 1;
    CagdBSpline *s = NULL, *r = NULL;
    CagdCurveList *list = NULL;
    double buf[16] = {0}, a = 0, b = 0;
    size_t needed = 0, n = 0;
    bool rat = false;

    CHECK_OK(cagd_bspline_new(2, U, 8, P, 5, 2, &s));
    /* scalar accessors */
    CHECK_STATUS(cagd_bspline_degree(NULL, &n), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_bspline_degree(s, NULL), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_bspline_dim(NULL, &n), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_bspline_dim(s, NULL), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_bspline_n_points(NULL, &n), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_bspline_n_points(s, NULL), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_bspline_is_rational(NULL, &rat), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_bspline_is_rational(s, NULL), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_bspline_domain(NULL, &a, &b), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_bspline_domain(s, NULL, &b), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_bspline_domain(s, &a, NULL), CAGD_ERR_NULL_POINTER);
    /* array accessors: NULL, short buffer (nothing written), size query */
    CHECK_STATUS(cagd_bspline_knots(NULL, buf, 16, &needed), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_bspline_knots(s, NULL, 16, &needed), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_bspline_knots(s, buf, 16, NULL), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_bspline_points(NULL, buf, 16, &needed), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_bspline_points(s, NULL, 16, &needed), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_bspline_points(s, buf, 16, NULL), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_bspline_weights(NULL, buf, 16, &needed), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_bspline_weights(s, NULL, 16, &needed), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_bspline_weights(s, buf, 16, NULL), CAGD_ERR_NULL_POINTER);
    buf[0] = -7.0;
    CHECK_STATUS(cagd_bspline_knots(s, buf, 7, &needed), CAGD_ERR_BUFFER_TOO_SMALL);
    CHECK(needed == 8 && buf[0] == -7.0);
    CHECK_STATUS(cagd_bspline_points(s, buf, 9, &needed), CAGD_ERR_BUFFER_TOO_SMALL);
    CHECK(needed == 10 && buf[0] == -7.0);
    CHECK_STATUS(cagd_bspline_weights(s, NULL, 0, &needed), CAGD_ERR_BUFFER_TOO_SMALL);
    CHECK(needed == 5);
    /* eval / derivatives */
    CHECK_STATUS(cagd_bspline_eval(NULL, 0.5, buf, 2, &needed), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_bspline_eval(s, 0.5, NULL, 2, &needed), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_bspline_eval(s, 0.5, buf, 2, NULL), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_bspline_eval(s, NAN, buf, 2, &needed), CAGD_ERR_INVALID_ARGUMENT);
    CHECK_STATUS(cagd_bspline_eval(s, INFINITY, buf, 2, &needed), CAGD_ERR_INVALID_ARGUMENT);
    CHECK_STATUS(cagd_bspline_eval(s, 0.5, buf, 1, &needed), CAGD_ERR_BUFFER_TOO_SMALL);
    CHECK(needed == 2 && buf[0] == -7.0);
    CHECK_STATUS(cagd_bspline_derivatives(NULL, 0.5, 2, buf, 6, &needed), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_bspline_derivatives(s, 0.5, 2, NULL, 6, &needed), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_bspline_derivatives(s, 0.5, 2, buf, 6, NULL), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_bspline_derivatives(s, NAN, 2, buf, 6, &needed),
                 CAGD_ERR_INVALID_ARGUMENT);
    CHECK_STATUS(cagd_bspline_derivatives(s, 0.5, 131, buf, 16, &needed),
                 CAGD_ERR_INVALID_ARGUMENT);
    CHECK_STATUS(cagd_bspline_derivatives(s, 0.5, 2, buf, 5, &needed),
                 CAGD_ERR_BUFFER_TOO_SMALL);
    CHECK(needed == 6 && buf[0] == -7.0);
    /* knot insertion */
    CHECK_STATUS(cagd_bspline_insert_knot(NULL, 0.5, 1, &r), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_bspline_insert_knot(s, 0.5, 1, NULL), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_bspline_insert_knot(s, NAN, 1, &r), CAGD_ERR_INVALID_ARGUMENT);
    CHECK_STATUS(cagd_bspline_insert_knot(s, 1.5, 1, &r), CAGD_ERR_INVALID_ARGUMENT);
    CHECK_STATUS(cagd_bspline_insert_knot(s, 0.4, 3, &r), CAGD_ERR_MULTIPLICITY); /* 1+3 > 3 */
    CHECK_STATUS(cagd_bspline_insert_knot(s, 0.5, SIZE_MAX, &r), CAGD_ERR_MULTIPLICITY);
    CHECK(r == NULL);
    CHECK_OK(cagd_bspline_insert_knot(s, 0.4, 2, &r)); /* multiplicity 3 = degree + 1 */
    /* Bézier extraction and the list */
    CHECK_STATUS(cagd_bspline_to_beziers(NULL, &list), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_bspline_to_beziers(s, NULL), CAGD_ERR_NULL_POINTER);
    CHECK_OK(cagd_bspline_to_beziers(s, &list));
    {
        CagdCurve *c = NULL;
        size_t count = 0;
        double bound = 0;
        CHECK_STATUS(cagd_curvelist_count(NULL, &count), CAGD_ERR_NULL_POINTER);
        CHECK_STATUS(cagd_curvelist_count(list, NULL), CAGD_ERR_NULL_POINTER);
        CHECK_OK(cagd_curvelist_count(list, &count));
        CHECK(count == 3);
        CHECK_STATUS(cagd_curvelist_get(NULL, 0, &c), CAGD_ERR_NULL_POINTER);
        CHECK_STATUS(cagd_curvelist_get(list, 0, NULL), CAGD_ERR_NULL_POINTER);
        CHECK_STATUS(cagd_curvelist_get(list, 3, &c), CAGD_ERR_INVALID_ARGUMENT);
        CHECK(c == NULL);
        CHECK_STATUS(cagd_curvelist_interval(NULL, 0, &a, &b), CAGD_ERR_NULL_POINTER);
        CHECK_STATUS(cagd_curvelist_interval(list, 0, NULL, &b), CAGD_ERR_NULL_POINTER);
        CHECK_STATUS(cagd_curvelist_interval(list, 0, &a, NULL), CAGD_ERR_NULL_POINTER);
        CHECK_STATUS(cagd_curvelist_interval(list, SIZE_MAX, &a, &b), CAGD_ERR_INVALID_ARGUMENT);
        CHECK_STATUS(cagd_curvelist_bound(NULL, 0, &bound), CAGD_ERR_NULL_POINTER);
        CHECK_STATUS(cagd_curvelist_bound(list, 0, NULL), CAGD_ERR_NULL_POINTER);
        CHECK_STATUS(cagd_curvelist_bound(list, 9, &bound), CAGD_ERR_INVALID_ARGUMENT);
        CHECK_STATUS(cagd_curvelist_bound(list, 0, &bound), CAGD_ERR_NOT_AVAILABLE);
    }
    cagd_curvelist_free(NULL);
    cagd_curvelist_free(NULL);
    rc = 0;
cleanup:
    cagd_curvelist_free(list);
    cagd_bspline_free(r);
    cagd_bspline_free(s);
    return rc;
}
