/* NURBS <-> rational Bezier (SPEC-convert §15.1-15.3): the closed forms of one span both
 * ways (the public vectors conv-15.1-a and conv-15.3-b-b0-d0, the condition failure
 * conv-15.3-inv-condition-fails), the biquadratic patch both ways (conv-15.2-a, a weight
 * matrix that is not rank 1), a NURBS curve to pieces and back (same knots and points),
 * the standard form, and bad input (each status with a message). */
#include "ctest.h"

int cagd_ctest_convert_span_closed_forms(void) {
    int rc = 1;
    CagdCurve *b2 = NULL, *b3 = NULL, *bad = NULL;
    CagdBSpline *span = NULL, *none = NULL;
    /* conv-15.1-a: knots (0,1,3,4), w = (1,2,1), r = ((0,0),(1,2),(3,0)) ->
     * W = (4/3, 2, 4/3), R = ((1/2,1),(1,2),(2,1)). */
    const double k2[4] = {0, 1, 3, 4};
    const double p2[6] = {0, 0, 1, 2, 3, 0};
    const double w2[3] = {1, 2, 1};
    /* conv-15.3-b-b0-d0: knots (0,2,2,5,5,6), w = (2,1,1/2,1) -> W = (8/5, 1, 1/2, 7/8),
     * R = ((1/4,3/4),(1,3),(4,3),(40/7,3/7)). */
    const double k3[6] = {0, 2, 2, 5, 5, 6};
    const double p3[8] = {0, 0, 1, 3, 4, 3, 6, 0};
    const double w3[4] = {2, 1, 0.5, 1};
    const double want3[8] = {0.25, 0.75, 1, 3, 4, 3, 40.0 / 7, 3.0 / 7};
    const double wantw3[4] = {1.6, 1, 0.5, 0.875};
    double pts[8] = {0}, w[4] = {0}, extra = 0, knots[8] = {0};
    size_t needed = 0, i;

    CHECK_OK(cagd_nurbs_span_to_bezier(2, k2, p2, w2, 2, &b2));
    CHECK_OK(cagd_curve_weights(b2, w, 4, &needed));
    CHECK(needed == 3);
    CHECK_NEAR(w[0], 4.0 / 3, 1e-15);
    CHECK_NEAR(w[1], 2.0, 1e-15);
    CHECK_OK(cagd_curve_points(b2, pts, 8, &needed));
    CHECK(needed == 6);
    CHECK_NEAR(pts[0], 0.5, 1e-15);
    CHECK_NEAR(pts[5], 1.0, 1e-15);
    /* and back: the span, with the extrapolation factor 1 + max(k1, k2) = 2 here
     * (k1 = b W1 / (c w_{n-2}) = 1 * 2 / (2 * 1)). */
    CHECK_OK(cagd_bezier_to_nurbs_span(b2, k2, &span, &extra));
    CHECK_NEAR(extra, 2.0, 1e-14);
    CHECK_OK(cagd_bspline_points(span, pts, 8, &needed));
    CHECK(needed == 6);
    for (i = 0; i < 6; ++i) CHECK_NEAR(pts[i], p2[i], 1e-14);
    CHECK_OK(cagd_bspline_knots(span, knots, 8, &needed));
    CHECK(needed == 6 && knots[0] == 0 && knots[1] == 0 && knots[4] == 4 && knots[5] == 4);
    cagd_bspline_free(span);
    span = NULL;

    CHECK_OK(cagd_nurbs_span_to_bezier(3, k3, p3, w3, 2, &b3));
    CHECK_OK(cagd_curve_points(b3, pts, 8, &needed));
    for (i = 0; i < 8; ++i) CHECK_NEAR(pts[i], want3[i], 1e-14);
    CHECK_OK(cagd_curve_weights(b3, w, 4, &needed));
    for (i = 0; i < 4; ++i) CHECK_NEAR(w[i], wantw3[i], 1e-15);
    CHECK_OK(cagd_bezier_to_nurbs_span(b3, k3, &span, NULL));
    CHECK_OK(cagd_bspline_weights(span, w, 4, &needed));
    for (i = 0; i < 4; ++i) CHECK_NEAR(w[i], w3[i], 1e-14);

    /* conv-15.3-inv-condition-fails: a=b=d=e=1, c=1/2, W=(1,2,1,1): w_{n-3} = -21. */
    {
        const double kb[6] = {0, 1, 2, 2.5, 3.5, 4.5};
        const double pb[4] = {0, 1, 2, 3};
        const double wb[4] = {1, 2, 1, 1};
        CHECK_OK(cagd_curve_new_rational(pb, wb, 4, 1, &bad));
        CHECK_STATUS(cagd_bezier_to_nurbs_span(bad, kb, &none, &extra),
                     CAGD_ERR_CONVERSION_CONDITION);
        CHECK(none == NULL);
        CHECK_MESSAGE_HAS("15.3.14");
        CHECK_MESSAGE_HAS("-21");
    }
    /* degree 4 has no closed form; a zero-length span; a decreasing knot; NULLs */
    {
        const double k4[8] = {0, 1, 2, 3, 4, 5, 6, 7};
        const double p4[5] = {0, 1, 2, 3, 4};
        const double kz[4] = {0, 1, 1, 2};
        const double kd[4] = {0, 2, 1, 3};
        const double wneg[3] = {1, -1, 1};
        CagdCurve *c = NULL;
        CHECK_STATUS(cagd_nurbs_span_to_bezier(4, k4, p4, NULL, 1, &c), CAGD_ERR_BAD_DEGREE_PAIR);
        CHECK_STATUS(cagd_nurbs_span_to_bezier(2, kz, p2, w2, 2, &c), CAGD_ERR_INVALID_ARGUMENT);
        CHECK_MESSAGE_HAS("span");
        CHECK_STATUS(cagd_nurbs_span_to_bezier(2, kd, p2, w2, 2, &c), CAGD_ERR_BAD_KNOTS);
        CHECK_STATUS(cagd_nurbs_span_to_bezier(2, k2, p2, wneg, 2, &c),
                     CAGD_ERR_NON_POSITIVE_WEIGHT);
        CHECK_STATUS(cagd_nurbs_span_to_bezier(2, NULL, p2, w2, 2, &c), CAGD_ERR_NULL_POINTER);
        CHECK_STATUS(cagd_nurbs_span_to_bezier(2, k2, p2, w2, 0, &c), CAGD_ERR_INVALID_ARGUMENT);
        CHECK_STATUS(cagd_bezier_to_nurbs_span(NULL, k2, &none, NULL), CAGD_ERR_NULL_POINTER);
        CHECK(c == NULL);
    }
    rc = 0;
cleanup:
    cagd_curve_free(b2);
    cagd_curve_free(b3);
    cagd_curve_free(bad);
    cagd_bspline_free(span);
    cagd_bspline_free(none);
    return rc;
}

int cagd_ctest_convert_biquadratic(void) {
    int rc = 1;
    /* conv-15.2-a: g = (1,2,1), h = (1/2,1,3), u knots (0,1,3,4), v knots (0,0,2,5). */
    const double uk[4] = {0, 1, 3, 4}, vk[4] = {0, 0, 2, 5};
    const double g[3] = {1, 2, 1}, h[3] = {0.5, 1, 3};
    const double r[27] = {0, 0, 0, 0, 1, 0, 0, 2, 0, 1, 0, 0, 1, 1, 1,
                          1, 2, 2, 2, 0, 0, 2, 1, 2, 2, 2, 1};
    const double want[27] = {0.5, 0, 0,   0.5, 1, 0.5, 0.5, 5.0 / 3, 5.0 / 6,
                             1,   0, 0,   1,   1, 1,   1,   5.0 / 3, 5.0 / 3,
                             1.5, 0, 0,   1.5, 1, 1.5, 1.5, 5.0 / 3, 1.5};
    const double bigg[3] = {4.0 / 3, 2, 4.0 / 3}, bigh[3] = {0.5, 1, 1.8};
    double w[9], bp[27], bw[9], np[27], nw[9], extra = 0;
    size_t i;
    for (i = 0; i < 9; ++i) w[i] = g[i / 3] * h[i % 3];
    CHECK_OK(cagd_nurbs22_span_to_bezier(uk, vk, r, w, 3, bp, bw));
    for (i = 0; i < 27; ++i) CHECK_NEAR(bp[i], want[i], 1e-14);
    for (i = 0; i < 9; ++i) CHECK_NEAR(bw[i], bigg[i / 3] * bigh[i % 3], 1e-14);
    CHECK_OK(cagd_bezier22_to_nurbs22_span(uk, vk, bp, bw, 3, np, nw, &extra));
    for (i = 0; i < 27; ++i) CHECK_NEAR(np[i], r[i], 1e-13);
    for (i = 0; i < 9; ++i) CHECK_NEAR(nw[i], w[i], 1e-13);
    CHECK(extra >= 1.0);
    /* Bezier weights that are not rank 1: the closed form does not apply. */
    bw[4] *= 1.5;
    CHECK_STATUS(cagd_bezier22_to_nurbs22_span(uk, vk, bp, bw, 3, np, nw, NULL),
                 CAGD_ERR_CONVERSION_CONDITION);
    CHECK_MESSAGE_HAS("separable");
    /* overlapping outputs */
    CHECK_STATUS(cagd_nurbs22_span_to_bezier(uk, vk, r, w, 3, bp, bp + 20),
                 CAGD_ERR_INVALID_ARGUMENT);
    CHECK_STATUS(cagd_nurbs22_span_to_bezier(uk, NULL, r, w, 3, bp, bw), CAGD_ERR_NULL_POINTER);
    rc = 0;
cleanup:
    return rc;
}

int cagd_ctest_convert_curve_round_trip(void) {
    int rc = 1;
    /* A cubic NURBS with a double knot (C1) and a simple one (C2), 2-D. */
    const double knots[11] = {0, 0, 0, 0, 0.3, 0.3, 0.8, 1, 1, 1, 1};
    const double pts[14] = {0, 0, 1, 2, 2, -1, 3, 2, 4, 0, 5, 1, 6, 0};
    const double wts[7] = {1, 2, 0.5, 1, 3, 1, 0.7};
    CagdBSpline *c = NULL, *back = NULL, *bad = NULL;
    CagdCurveList *list = NULL;
    CagdCurve *piece = NULL, *sf = NULL;
    double k[11] = {0}, p[14] = {0}, w[7] = {0}, a = 0, b = 0, rho = 0;
    size_t needed = 0, count = 0, i;

    CHECK_OK(cagd_bspline_new_rational(3, knots, 11, pts, wts, 7, 2, &c));
    CHECK_OK(cagd_bspline_to_bezier_pieces(c, &list));
    CHECK_OK(cagd_curvelist_count(list, &count));
    CHECK(count == 3);
    CHECK_OK(cagd_curvelist_interval(list, 1, &a, &b));
    CHECK(a == 0.3 && b == 0.8);
    CHECK_OK(cagd_curvelist_to_bspline(list, 0.0, &back));
    CHECK_OK(cagd_bspline_knots(back, k, 11, &needed));
    CHECK(needed == 11 && memcmp(k, knots, sizeof knots) == 0);
    CHECK_OK(cagd_bspline_points(back, p, 14, &needed));
    for (i = 0; i < 14; ++i) CHECK_NEAR(p[i], pts[i], 1e-13);
    CHECK_OK(cagd_bspline_weights(back, w, 7, &needed));
    for (i = 0; i < 7; ++i) CHECK_NEAR(w[i], wts[i], 1e-13);
    CHECK_STATUS(cagd_curvelist_to_bspline(list, -1.0, &bad), CAGD_ERR_INVALID_ARGUMENT);
    CHECK_STATUS(cagd_curvelist_to_bspline(NULL, 0.0, &bad), CAGD_ERR_NULL_POINTER);
    CHECK(bad == NULL);
    /* standard form of a piece: end weights 1 */
    CHECK_OK(cagd_curvelist_get(list, 0, &piece));
    CHECK_OK(cagd_curve_standard_form(piece, &sf, &rho));
    CHECK(rho > 0);
    CHECK_OK(cagd_curve_weights(sf, w, 7, &needed));
    CHECK(needed == 4);
    CHECK_NEAR(w[0], 1.0, 1e-15);
    CHECK_NEAR(w[3], 1.0, 1e-15);
    rc = 0;
cleanup:
    cagd_bspline_free(c);
    cagd_bspline_free(back);
    cagd_bspline_free(bad);
    cagd_curvelist_free(list);
    cagd_curve_free(piece);
    cagd_curve_free(sf);
    return rc;
}
