/* WSGB curves (seed 003, SPEC-reduce §9) through the C ABI: the paper's degree-7 example
 * r(u;7,1) (perturbation: middle point (615/2, 825/2), bound (11) = 17.8125, true max-abs
 * error 6*95*(3/14)^3/sqrt(7); uniform: (12) = 1140/2^13 = measured max-abs error),
 * evaluation against the Bézier form, elevation and degeneracy, and bad input. */
#include <stdbool.h>
#include <stdint.h>

#include "ctest.h"

static const double P7[16] = {220, 110, 160, 220, 180, 340, 260, 400,
                              355, 425, 470, 320, 490, 200, 420, 100};

int cagd_ctest_wsgb_paper_example(void) {
    int rc = 1;
    CagdWsgbCurve *c = NULL, *q = NULL, *u = NULL, *l2 = NULL, *e = NULL;
    CagdCurve *b = NULL;
    CagdReduceOptions o;
    CagdWsgbReport rep, urep, lrep;
    double pts[16] = {0}, x[2] = {0}, y[2] = {0}, lec[2] = {0};
    size_t needed = 0, n = 0, l = 0, dim = 0, k;
    bool degenerate = true;

    CHECK_OK(cagd_wsgb_new(P7, 8, 2, 1, &c));
    CHECK_OK(cagd_wsgb_shape(c, &n, &l, &dim));
    CHECK(n == 7 && l == 1 && dim == 2);
    CHECK_OK(cagd_wsgb_to_bezier(c, &b));
    for (k = 0; k <= 10; ++k) {
        double t = (double)k / 10.0;
        CHECK_OK(cagd_wsgb_eval(c, t, x, 2, &needed));
        CHECK_OK(cagd_curve_eval(b, t, y, 2, &needed));
        CHECK_NEAR(x[0], y[0], 1e-12);
        CHECK_NEAR(x[1], y[1], 1e-12);
    }
    CHECK_OK(cagd_wsgb_leading_coefficient(c, lec, 2, &needed, &degenerate));
    CHECK(lec[0] == -1140.0 && lec[1] == -300.0 && !degenerate);

    CHECK_OK(cagd_reduce_options_init(&o));
    o.target = 6;
    o.measure = true;
    rep.struct_size = sizeof rep;
    CHECK_OK(cagd_wsgb_reduce(c, CAGD_WSGB_PERTURBATION, &o, &q, &rep));
    CHECK_OK(cagd_wsgb_points(q, pts, 16, &needed));
    CHECK(needed == 14 && pts[6] == 307.5 && pts[7] == 412.5 && pts[0] == 220.0);
    CHECK(rep.degree_from == 7 && rep.degree_to == 6 && rep.order_to == 1);
    CHECK(rep.paper_bound_11 == 17.8125);
    CHECK_NEAR(rep.paper_true_error_inf, 570.0 * pow(3.0 / 14.0, 3) / sqrt(7.0), 1e-12);
    CHECK_NEAR(rep.max_error_inf, rep.paper_true_error_inf, 1e-11);
    CHECK(rep.max_error <= rep.error_bound);

    urep.struct_size = sizeof urep;
    CHECK_OK(cagd_wsgb_reduce(c, CAGD_WSGB_UNIFORM, &o, &u, &urep));
    CHECK(urep.uniform_error_12 == 1140.0 / 8192.0);
    CHECK_NEAR(urep.max_error_inf, 1140.0 / 8192.0, 1e-12);
    CHECK_OK(cagd_wsgb_points(u, pts, 16, &needed));
    CHECK(pts[0] == 450275.0 / 2048.0 && pts[6] == 307.5);

    o.method = CAGD_METHOD_L2;
    o.r = -1;
    o.p = -1;
    o.target = 4;
    o.measure = false;
    lrep.struct_size = sizeof lrep;
    CHECK_OK(cagd_wsgb_reduce(c, CAGD_WSGB_BEZIER, &o, &l2, &lrep));
    CHECK_OK(cagd_wsgb_shape(l2, &n, &l, &dim));
    CHECK(n == 4 && l == 1);
    CHECK(isnan(lrep.max_error) && isnan(lrep.paper_bound_11) && lrep.error_bound > 0);

    /* elevated curves are degenerate (odd target degree: exactly, after rounding) */
    CHECK_OK(cagd_wsgb_elevate(u, 1, &e));
    CHECK_OK(cagd_wsgb_leading_coefficient(e, lec, 2, &needed, &degenerate));
    CHECK(degenerate);
    rc = 0;
cleanup:
    cagd_wsgb_free(e);
    cagd_wsgb_free(l2);
    cagd_wsgb_free(u);
    cagd_wsgb_free(q);
    cagd_curve_free(b);
    cagd_wsgb_free(c);
    return rc;
}

int cagd_ctest_wsgb_bad_input(void) {
    int rc = 1;
    CagdWsgbCurve *c = NULL, *line = NULL, *out = NULL, *back = NULL;
    CagdCurve *rational = NULL, *b = NULL;
    CagdReduceOptions o;
    CagdWsgbReport rep;
    const double line_pts[2] = {0, 1}, w[3] = {1, 2, 1}, r_pts[3] = {0, 1, 0};
    double bad[16], x[2];
    size_t needed = 0, n = 0, l = 0, dim = 0;
    bool degenerate = false;

    /* L out of range: n = 7 allows L <= 2 */
    CHECK_STATUS(cagd_wsgb_new(P7, 8, 2, 3, &c), CAGD_ERR_INVALID_ARGUMENT);
    CHECK(c == NULL);
    memcpy(bad, P7, sizeof bad);
    bad[5] = NAN;
    CHECK_STATUS(cagd_wsgb_new(bad, 8, 2, 1, &c), CAGD_ERR_NON_FINITE);
    CHECK_STATUS(cagd_wsgb_new(NULL, 8, 2, 1, &c), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_wsgb_new(P7, 0, 2, 0, &c), CAGD_ERR_NOT_ENOUGH_POINTS);
    CHECK_STATUS(cagd_wsgb_new(P7, 8, 0, 0, &c), CAGD_ERR_INVALID_ARGUMENT);
    CHECK_OK(cagd_wsgb_new(P7, 8, 2, 1, &c));
    CHECK_STATUS(cagd_wsgb_eval(c, NAN, x, 2, &needed), CAGD_ERR_INVALID_ARGUMENT);
    CHECK_STATUS(cagd_wsgb_eval(c, 0.5, x, 1, &needed), CAGD_ERR_BUFFER_TOO_SMALL);
    CHECK(needed == 2);
    CHECK_STATUS(cagd_wsgb_points(c, NULL, 0, &needed), CAGD_ERR_BUFFER_TOO_SMALL);
    CHECK(needed == 16);
    CHECK_STATUS(cagd_wsgb_shape(c, &n, NULL, &dim), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_wsgb_leading_coefficient(c, x, 2, &needed, NULL), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_wsgb_elevate(c, 9, &out), CAGD_ERR_INVALID_ARGUMENT);

    CHECK_OK(cagd_reduce_options_init(&o));
    rep.struct_size = sizeof rep;
    o.target = 7; /* target not below the degree */
    CHECK_STATUS(cagd_wsgb_reduce(c, CAGD_WSGB_UNIFORM, &o, &out, &rep), CAGD_ERR_BAD_DEGREE_PAIR);
    o.target = 5;
    CHECK_STATUS(cagd_wsgb_reduce(c, 7, &o, &out, &rep), CAGD_ERR_INVALID_ARGUMENT);
    CHECK_STATUS(cagd_wsgb_reduce(c, CAGD_WSGB_UNIFORM, NULL, &out, &rep), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_wsgb_reduce(c, CAGD_WSGB_UNIFORM, &o, NULL, &rep), CAGD_ERR_NULL_POINTER);
    rep.struct_size = 0;
    CHECK_STATUS(cagd_wsgb_reduce(c, CAGD_WSGB_UNIFORM, &o, &out, &rep), CAGD_ERR_INVALID_ARGUMENT);
    o.struct_size = 4;
    CHECK_STATUS(cagd_wsgb_reduce(c, CAGD_WSGB_UNIFORM, &o, &out, NULL), CAGD_ERR_INVALID_ARGUMENT);
    CHECK(out == NULL);
    /* the report is optional */
    CHECK_OK(cagd_reduce_options_init(&o));
    o.target = 5;
    CHECK_OK(cagd_wsgb_reduce(c, CAGD_WSGB_UNIFORM, &o, &out, NULL));
    CHECK_OK(cagd_wsgb_shape(out, &n, &l, &dim));
    CHECK(n == 5 && l == 1 && dim == 2);

    /* perturbation needs n >= 2 at every step */
    CHECK_OK(cagd_wsgb_new(line_pts, 2, 1, 0, &line));
    o.target = 0;
    CHECK_STATUS(cagd_wsgb_reduce(line, CAGD_WSGB_PERTURBATION, &o, &back, NULL),
                 CAGD_ERR_BAD_DEGREE_PAIR);
    CHECK_OK(cagd_wsgb_leading_coefficient(line, x, 1, &needed, &degenerate));
    CHECK(x[0] == 1.0 && !degenerate);

    /* a rational Bézier curve has no WSGB form */
    CHECK_OK(cagd_curve_new_rational(r_pts, w, 3, 1, &rational));
    CHECK_STATUS(cagd_wsgb_from_bezier(rational, 0, &back), CAGD_ERR_CONDITION_NOT_MET);
    CHECK_STATUS(cagd_wsgb_to_bezier(NULL, &b), CAGD_ERR_NULL_POINTER);
    CHECK(back == NULL && b == NULL);
    rc = 0;
cleanup:
    cagd_curve_free(b);
    cagd_curve_free(rational);
    cagd_wsgb_free(back);
    cagd_wsgb_free(out);
    cagd_wsgb_free(line);
    cagd_wsgb_free(c);
    return rc;
}

int cagd_ctest_wsgb_reduce_to_tolerance(void) {
    int rc = 1;
    CagdWsgbCurve *c = NULL, *piece = NULL;
    CagdWsgbCurveList *list = NULL;
    CagdReduceOptions o;
    double start = -1, end = -1, bound = -1, prev_end = 0.0, x[2], y[2];
    size_t count = 0, i, k, needed = 0, n = 0, l = 0, dim = 0;

    CHECK_OK(cagd_wsgb_new(P7, 8, 2, 1, &c));
    CHECK_OK(cagd_reduce_options_init(&o));
    o.target = 4;
    o.tolerance = 0.5;
    CHECK_OK(cagd_wsgb_reduce_to_tolerance(c, CAGD_WSGB_PERTURBATION, &o, &list));
    CHECK_OK(cagd_wsgblist_count(list, &count));
    CHECK(count > 1);
    for (i = 0; i < count; ++i) {
        CHECK_OK(cagd_wsgblist_get(list, i, &piece, &start, &end, &bound));
        CHECK(start == prev_end && end > start && bound <= 0.5);
        CHECK_OK(cagd_wsgb_shape(piece, &n, &l, &dim));
        CHECK(n == 4 && l == 1 && dim == 2);
        /* independent check: the piece against the original at its own parameters */
        for (k = 0; k <= 20; ++k) {
            double s = (double)k / 20.0;
            CHECK_OK(cagd_wsgb_eval(piece, s, x, 2, &needed));
            CHECK_OK(cagd_wsgb_eval(c, start + s * (end - start), y, 2, &needed));
            CHECK(hypot(x[0] - y[0], x[1] - y[1]) <= bound + 1e-9);
        }
        prev_end = end;
        cagd_wsgb_free(piece);
        piece = NULL;
    }
    CHECK(prev_end == 1.0);
    CHECK_STATUS(cagd_wsgblist_get(list, count, &piece, &start, &end, &bound),
                 CAGD_ERR_INVALID_ARGUMENT);
    o.tolerance = 0.0;
    cagd_wsgblist_free(list);
    list = NULL;
    CHECK_STATUS(cagd_wsgb_reduce_to_tolerance(c, CAGD_WSGB_UNIFORM, &o, &list),
                 CAGD_ERR_INVALID_ARGUMENT);
    CHECK(list == NULL);
    rc = 0;
cleanup:
    cagd_wsgb_free(piece);
    cagd_wsgblist_free(list);
    cagd_wsgb_free(c);
    return rc;
}
