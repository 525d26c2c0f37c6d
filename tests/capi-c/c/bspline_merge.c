/* cagd_bspline_from_beziers: the exact merge of Bézier segments into one B-spline (seed 001
 * §4.1).
 *
 * - The public vector 001-exact-merge-c0 (SPEC-reduce §8, vectors-reduce.json): three
 *   cubic segments given as exact fractions, merged C0 (interior knots of multiplicity 3,
 *   each joint point stored once). Its segments are C1 as well (checked by hand: the end
 *   derivatives 3 (P3 - P2) and 3 (Q1 - Q0) agree, (3/2, -5/4) and (3/2, 5/12)) but not
 *   C2, so the C1 merge is the segment points without the joint points, knots of
 *   multiplicity 2.
 * - A C1 cubic spline (double interior knot) split by cagd_bspline_to_beziers and merged
 *   back with continuity 1 is the same spline; also as a NURBS.
 * - Bad input: each status with a message. */
#include "ctest.h"

/* 001-exact-merge-c0, input.segments_exact (the fractions rounded once by the division). */
static const double SEG[3][8] = {
    {167.0 / 60, 23.0 / 10, 197.0 / 60, 389.0 / 180, 223.0 / 60, 33.0 / 20, 253.0 / 60,
     37.0 / 30},
    {253.0 / 60, 37.0 / 30, 283.0 / 60, 49.0 / 60, 317.0 / 60, 101.0 / 180, 347.0 / 60,
     7.0 / 10},
    {347.0 / 60, 7.0 / 10, 377.0 / 60, 151.0 / 180, 403.0 / 60, 27.0 / 20, 433.0 / 60,
     53.0 / 30},
};
/* expected.knots and expected.ctrl_exact. */
static const double C0_KNOTS[14] = {0, 0, 0, 0, 1, 1, 1, 2, 2, 2, 3, 3, 3, 3};
static const double C0_CTRL[20] = {
    167.0 / 60, 23.0 / 10,  197.0 / 60, 389.0 / 180, 223.0 / 60, 33.0 / 20,  253.0 / 60,
    37.0 / 30,  283.0 / 60, 49.0 / 60,  317.0 / 60, 101.0 / 180, 347.0 / 60, 7.0 / 10,
    377.0 / 60, 151.0 / 180, 403.0 / 60, 27.0 / 20, 433.0 / 60, 53.0 / 30,
};
/* The C1 merge of the same segments: the joint points P3 and P6 removed. */
static const double C1_KNOTS[12] = {0, 0, 0, 0, 1, 1, 2, 2, 3, 3, 3, 3};
static const double C1_CTRL[16] = {
    167.0 / 60, 23.0 / 10,  197.0 / 60, 389.0 / 180, 223.0 / 60, 33.0 / 20,
    283.0 / 60, 49.0 / 60,  317.0 / 60, 101.0 / 180, 377.0 / 60, 151.0 / 180,
    403.0 / 60, 27.0 / 20,  433.0 / 60, 53.0 / 30,
};

/* Makes the three segments of the vector; `*segs` entries are NULL on failure. */
static CagdStatus vector_segments(CagdCurve *segs[3]) {
    size_t i;
    for (i = 0; i < 3; ++i) {
        CagdStatus st = cagd_curve_new(SEG[i], 4, 2, &segs[i]);
        if (st != CAGD_OK) return st;
    }
    return CAGD_OK;
}

int cagd_ctest_bspline_merge_001_exact(void) {
    int rc = 1;
    CagdCurve *segs[3] = {NULL, NULL, NULL};
    CagdBSpline *c0 = NULL, *c1 = NULL, *c2 = NULL;
    const double breaks[4] = {0, 1, 2, 3};
    double knots[14] = {0}, pts[20] = {0};
    size_t needed = 0, degree = 0, i;
    bool rational = true;

    CHECK_OK(vector_segments(segs));
    /* C0 with the breaks given: the vector exactly (1e-15 allowed, 0 observed) */
    CHECK_OK(cagd_bspline_from_beziers((const CagdCurve *const *)segs, 3, breaks, 0, 1e-12,
                                       &c0));
    CHECK_OK(cagd_bspline_degree(c0, &degree));
    CHECK_OK(cagd_bspline_is_rational(c0, &rational));
    CHECK(degree == 3 && !rational);
    CHECK_OK(cagd_bspline_knots(c0, knots, 14, &needed));
    CHECK(needed == 14 && memcmp(knots, C0_KNOTS, sizeof C0_KNOTS) == 0);
    CHECK_OK(cagd_bspline_points(c0, pts, 20, &needed));
    CHECK(needed == 20);
    for (i = 0; i < 20; ++i) CHECK_NEAR(pts[i], C0_CTRL[i], 1e-15);
    /* C1 with the default breaks 0, 1, 2, 3 (NULL) */
    CHECK_OK(cagd_bspline_from_beziers((const CagdCurve *const *)segs, 3, NULL, 1, 1e-12, &c1));
    CHECK_OK(cagd_bspline_knots(c1, knots, 14, &needed));
    CHECK(needed == 12 && memcmp(knots, C1_KNOTS, sizeof C1_KNOTS) == 0);
    CHECK_OK(cagd_bspline_points(c1, pts, 20, &needed));
    CHECK(needed == 16);
    for (i = 0; i < 16; ++i) CHECK_NEAR(pts[i], C1_CTRL[i], 1e-14);
    /* not C2: the second derivatives differ by 2/5 at both joints */
    CHECK_STATUS(cagd_bspline_from_beziers((const CagdCurve *const *)segs, 3, NULL, 2, 1e-6, &c2),
                 CAGD_ERR_CONDITION_NOT_MET);
    CHECK(c2 == NULL && strlen(cagd_last_error_message()) > 0);
    rc = 0;
cleanup:
    cagd_bspline_free(c2);
    cagd_bspline_free(c1);
    cagd_bspline_free(c0);
    for (i = 0; i < 3; ++i) cagd_curve_free(segs[i]);
    return rc;
}

/* A cubic with a double knot at 1 (C1 there), 6 points, 2 spans. */
static const double U_C1[10] = {0, 0, 0, 0, 1, 1, 2, 2, 2, 2};
static const double P_C1[12] = {0, 0, 1, 2, 2, 3, 3, 1, 4, -1, 5, 2};
static const double W_C1[6] = {1, 2, 1, 0.5, 1, 1.5};

/* Splits `s` into its Bézier pieces and merges them back with continuity `k`; checks that
 * the result has the knots, points and weights of `s` (1e-12). Returns 0 on success. */
static int split_and_merge(const CagdBSpline *s, size_t k) {
    int rc = 1;
    CagdCurveList *list = NULL;
    CagdCurve *pieces[2] = {NULL, NULL};
    CagdBSpline *m = NULL;
    double breaks[3] = {0}, a = 0, b = 0;
    double knots[10] = {0}, want_knots[10] = {0}, pts[12] = {0}, want_pts[12] = {0};
    double w[6] = {0}, want_w[6] = {0};
    size_t count = 0, needed = 0, i;

    CHECK_OK(cagd_bspline_to_beziers(s, &list));
    CHECK_OK(cagd_curvelist_count(list, &count));
    CHECK(count == 2);
    for (i = 0; i < 2; ++i) {
        CHECK_OK(cagd_curvelist_get(list, i, &pieces[i]));
        CHECK_OK(cagd_curvelist_interval(list, i, &a, &b));
        breaks[i] = a;
        breaks[i + 1] = b;
    }
    CHECK_OK(cagd_bspline_from_beziers((const CagdCurve *const *)pieces, 2, breaks, k, 1e-9, &m));
    CHECK_OK(cagd_bspline_knots(s, want_knots, 10, &needed));
    CHECK_OK(cagd_bspline_knots(m, knots, 10, &needed));
    CHECK(needed == 10 && memcmp(knots, want_knots, sizeof knots) == 0);
    CHECK_OK(cagd_bspline_points(s, want_pts, 12, &needed));
    CHECK_OK(cagd_bspline_points(m, pts, 12, &needed));
    CHECK(needed == 12);
    for (i = 0; i < 12; ++i) CHECK_NEAR(pts[i], want_pts[i], 1e-12);
    CHECK_OK(cagd_bspline_weights(s, want_w, 6, &needed));
    CHECK_OK(cagd_bspline_weights(m, w, 6, &needed));
    CHECK(needed == 6);
    for (i = 0; i < 6; ++i) CHECK_NEAR(w[i], want_w[i], 1e-12);
    rc = 0;
cleanup:
    cagd_bspline_free(m);
    for (i = 0; i < 2; ++i) cagd_curve_free(pieces[i]);
    cagd_curvelist_free(list);
    return rc;
}

int cagd_ctest_bspline_merge_c1_round_trip(void) {
    int rc = 1;
    CagdBSpline *s = NULL, *nurbs = NULL;

    CHECK_OK(cagd_bspline_new(3, U_C1, 10, P_C1, 6, 2, &s));
    CHECK(split_and_merge(s, 1) == 0);
    CHECK_OK(cagd_bspline_new_rational(3, U_C1, 10, P_C1, W_C1, 6, 2, &nurbs));
    CHECK(split_and_merge(nurbs, 1) == 0);
    rc = 0;
cleanup:
    cagd_bspline_free(nurbs);
    cagd_bspline_free(s);
    return rc;
}

/* Fails the test unless the last call's message is non-empty. */
#define CHECK_HAS_MESSAGE() CHECK(strlen(cagd_last_error_message()) > 0)

int cagd_ctest_bspline_merge_bad_input(void) {
    int rc = 1;
    CagdCurve *segs[3] = {NULL, NULL, NULL}, *apart = NULL, *quad = NULL;
    const CagdCurve *list[3] = {NULL, NULL, NULL};
    CagdBSpline *out = NULL;
    const double decreasing[4] = {0, 2, 1, 3};
    const double nan_break[4] = {0, 1, NAN, 3};
    double shifted[8];
    const double quad_pts[6] = {0, 0, 1, 1, 2, 0};
    size_t i;

    CHECK_OK(vector_segments(segs));
    memcpy(shifted, SEG[1], sizeof shifted);
    shifted[0] += 1e-3; /* starts 1e-3 away from the end of segment 0 */
    CHECK_OK(cagd_curve_new(shifted, 4, 2, &apart));
    CHECK_OK(cagd_curve_new(quad_pts, 3, 2, &quad));
    list[0] = segs[0];
    list[2] = segs[2];

    /* NULL pointers: the array, an element (named in the message), the output */
    CHECK_STATUS(cagd_bspline_from_beziers(NULL, 3, NULL, 0, 1e-9, &out), CAGD_ERR_NULL_POINTER);
    CHECK_MESSAGE_HAS("segments");
    CHECK_STATUS(cagd_bspline_from_beziers(list, 3, NULL, 0, 1e-9, &out), CAGD_ERR_NULL_POINTER);
    CHECK_MESSAGE_HAS("segments[1]");
    list[1] = segs[1];
    CHECK_STATUS(cagd_bspline_from_beziers(list, 3, NULL, 0, 1e-9, NULL), CAGD_ERR_NULL_POINTER);
    CHECK_MESSAGE_HAS("spline_out");
    /* no segment */
    CHECK_STATUS(cagd_bspline_from_beziers(list, 0, NULL, 0, 1e-9, &out),
                 CAGD_ERR_NOT_ENOUGH_POINTS);
    CHECK_HAS_MESSAGE();
    /* breaks not increasing, not finite */
    CHECK_STATUS(cagd_bspline_from_beziers(list, 3, decreasing, 0, 1e-9, &out),
                 CAGD_ERR_INVALID_ARGUMENT);
    CHECK_MESSAGE_HAS("breaks");
    CHECK_STATUS(cagd_bspline_from_beziers(list, 3, nan_break, 0, 1e-9, &out),
                 CAGD_ERR_INVALID_ARGUMENT);
    CHECK_MESSAGE_HAS("breaks");
    /* continuity >= degree */
    CHECK_STATUS(cagd_bspline_from_beziers(list, 3, NULL, 3, 1e-9, &out),
                 CAGD_ERR_INVALID_ARGUMENT);
    CHECK_MESSAGE_HAS("continuity");
    /* tolerance not > 0 */
    CHECK_STATUS(cagd_bspline_from_beziers(list, 3, NULL, 0, 0.0, &out),
                 CAGD_ERR_INVALID_ARGUMENT);
    CHECK_HAS_MESSAGE();
    /* a quadratic among cubics */
    list[1] = quad;
    CHECK_STATUS(cagd_bspline_from_beziers(list, 3, NULL, 0, 1e-9, &out),
                 CAGD_ERR_DIMENSION_MISMATCH);
    CHECK_HAS_MESSAGE();
    /* segments that do not meet: a gap of 1e-3, refused at 1e-9, accepted at 1e-2 */
    list[1] = apart;
    CHECK_STATUS(cagd_bspline_from_beziers(list, 3, NULL, 0, 1e-9, &out),
                 CAGD_ERR_CONDITION_NOT_MET);
    CHECK_MESSAGE_HAS("4.1");
    CHECK(out == NULL); /* never written on failure */
    CHECK_OK(cagd_bspline_from_beziers(list, 3, NULL, 0, 1e-2, &out));
    CHECK(strlen(cagd_last_error_message()) == 0); /* cleared on success */
    rc = 0;
cleanup:
    cagd_bspline_free(out);
    cagd_curve_free(quad);
    cagd_curve_free(apart);
    for (i = 0; i < 3; ++i) cagd_curve_free(segs[i]);
    return rc;
}
