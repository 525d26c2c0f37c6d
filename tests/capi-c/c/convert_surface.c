/* NURBS <-> rational Bezier through the C ABI, the parts beyond one curve list: an
 * unclamped curve's exact round trip (its outer knots copied out and handed back), and a
 * tensor NURBS surface to rational Bezier patches and back (the same knots and net; every
 * patch evaluates to the surface on its rectangle), with bad input for each new entry
 * point. */
#include "ctest.h"

/* Evaluates a tensor Bezier piece (rational or not) at (s, t) by the homogeneous de
 * Casteljau, written here independently of the library. */
static void piece_eval(const double *pts, const double *w, size_t m, size_t n, size_t dim,
                       double s, double t, double *out) {
    double q[16][16][4];
    size_t i, j, k, r;
    for (i = 0; i <= m; ++i)
        for (j = 0; j <= n; ++j) {
            double wij = w ? w[i * (n + 1) + j] : 1.0;
            for (k = 0; k < dim; ++k) q[i][j][k] = wij * pts[(i * (n + 1) + j) * dim + k];
            q[i][j][dim] = wij;
        }
    for (r = 1; r <= n; ++r)
        for (i = 0; i <= m; ++i)
            for (j = 0; j + r <= n; ++j)
                for (k = 0; k <= dim; ++k)
                    q[i][j][k] = (1 - t) * q[i][j][k] + t * q[i][j + 1][k];
    for (r = 1; r <= m; ++r)
        for (i = 0; i + r <= m; ++i)
            for (k = 0; k <= dim; ++k) q[i][0][k] = (1 - s) * q[i][0][k] + s * q[i + 1][0][k];
    for (k = 0; k < dim; ++k) out[k] = q[0][0][k] / q[0][0][dim];
}

int cagd_ctest_convert_unclamped_round_trip(void) {
    int rc = 1;
    /* A cubic NURBS, unclamped at both ends, a double interior knot, 2-D. */
    const double knots[12] = {-0.7, -0.4, -0.1, 0, 0.3, 0.3, 0.8, 1, 1.2, 1.9, 2.0, 2.6};
    const double pts[16] = {0, 0, 1, 2, 2, -1, 3, 2, 4, 0, 5, 1, 6, 0, 7, 3};
    const double wts[8] = {1, 2, 0.5, 1, 3, 1, 0.7, 1.5};
    const double bad_left[3] = {-0.7, 0.5, 0};
    CagdBSpline *c = NULL, *back = NULL, *clamped = NULL, *bad = NULL;
    CagdCurveList *list = NULL;
    double left[8] = {0}, right[8] = {0}, k[16] = {0}, x[2] = {0}, y[2] = {0};
    size_t nl = 0, nr = 0, needed = 0, i;

    CHECK_OK(cagd_bspline_new_rational(3, knots, 12, pts, wts, 8, 2, &c));
    CHECK_OK(cagd_bspline_to_bezier_pieces(c, &list));
    /* size query, then the copies */
    CHECK_STATUS(cagd_bspline_outer_knots(c, CAGD_SIDE_LEFT, NULL, 0, &nl),
                 CAGD_ERR_BUFFER_TOO_SMALL);
    CHECK(nl == 3);
    CHECK_OK(cagd_bspline_outer_knots(c, CAGD_SIDE_LEFT, left, 8, &nl));
    CHECK_OK(cagd_bspline_outer_knots(c, CAGD_SIDE_RIGHT, right, 8, &nr));
    CHECK(nl == 3 && nr == 3);
    CHECK(left[0] == -0.7 && left[2] == -0.1 && right[0] == 1.9 && right[2] == 2.6);
    CHECK_OK(cagd_curvelist_to_bspline_unclamped(list, 0.0, left, nl, right, nr, &back));
    CHECK_OK(cagd_bspline_knots(back, k, 16, &needed));
    CHECK(needed == 12 && memcmp(k, knots, sizeof knots) == 0);
    /* the same curve on the domain [0, 1.2] */
    for (i = 0; i <= 40; ++i) {
        double t = 1.2 * (double)i / 40.0;
        CHECK_OK(cagd_bspline_eval(c, t, x, 2, &needed));
        CHECK_OK(cagd_bspline_eval(back, t, y, 2, &needed));
        CHECK_NEAR(x[0], y[0], 1e-12);
        CHECK_NEAR(x[1], y[1], 1e-12);
    }
    /* without the outer knots: clamped, the same curve */
    CHECK_OK(cagd_curvelist_to_bspline(list, 0.0, &clamped));
    CHECK_OK(cagd_bspline_knots(clamped, k, 16, &needed));
    CHECK(needed == 12 && k[0] == 0 && k[3] == 0 && k[8] == 1.2 && k[11] == 1.2);
    /* bad input: a left knot inside the domain, too few knots, NULL, a bad side */
    CHECK_STATUS(cagd_curvelist_to_bspline_unclamped(list, 0.0, bad_left, 3, right, 3, &bad),
                 CAGD_ERR_BAD_KNOTS);
    CHECK_MESSAGE_HAS("outer_knots.left");
    CHECK_STATUS(cagd_curvelist_to_bspline_unclamped(list, 0.0, left, 2, right, 3, &bad),
                 CAGD_ERR_BAD_KNOTS);
    CHECK_STATUS(cagd_curvelist_to_bspline_unclamped(list, 0.0, left, 3, NULL, 3, &bad),
                 CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_curvelist_to_bspline_unclamped(list, -1.0, left, 3, right, 3, &bad),
                 CAGD_ERR_INVALID_ARGUMENT);
    CHECK(bad == NULL);
    CHECK_STATUS(cagd_bspline_outer_knots(c, 2, left, 8, &nl), CAGD_ERR_INVALID_ARGUMENT);
    CHECK_STATUS(cagd_bspline_outer_knots(NULL, 0, left, 8, &nl), CAGD_ERR_NULL_POINTER);
    rc = 0;
cleanup:
    cagd_bspline_free(c);
    cagd_bspline_free(back);
    cagd_bspline_free(clamped);
    cagd_bspline_free(bad);
    cagd_curvelist_free(list);
    return rc;
}

int cagd_ctest_convert_surface_round_trip(void) {
    int rc = 1;
    /* A NURBS surface of degrees (2, 3): u knots with a simple interior knot (2 spans),
     * v knots with a double one (2 spans), 3-D, non-separable weights. */
    const double ku[7] = {0, 0, 0, 0.4, 1, 1, 1};
    const double kv[10] = {0, 0, 0, 0, 0.5, 0.5, 2, 2, 2, 2};
    enum { NU = 4, NV = 6, DIM = 3 };
    double pts[NU * NV * DIM], w[NU * NV];
    double got[NU * NV * DIM], gw[NU * NV], k[16], dom[8], bp[12 * 3], bw[12], x[3], y[3];
    size_t shape[5] = {0}, needed = 0, count = 0, i, j, n;
    bool rational = false;
    int kind = 0, is_rat = 0, dkind = 0;
    size_t du = 0, dv = 0, dim = 0;
    double bound = -1;
    CagdBSplineSurface *s = NULL, *back = NULL, *bad = NULL;
    CagdPatchPieceList *list = NULL, *tri = NULL;
    CagdTriPatch *tp = NULL;
    const double tri_pts[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};

    for (i = 0; i < NU; ++i)
        for (j = 0; j < NV; ++j) {
            n = i * NV + j;
            pts[n * DIM] = (double)i;
            pts[n * DIM + 1] = (double)j + 0.3 * (double)i;
            pts[n * DIM + 2] = sin(1.7 * (double)n);
            w[n] = 1.0 + 0.5 * cos(0.9 * (double)(n * n));
        }
    CHECK_OK(cagd_bsplinesurface_new(2, 3, ku, 7, kv, 10, pts, w, NU, NV, DIM, &s));
    CHECK_OK(cagd_bsplinesurface_to_bezier_patches(s, &list));
    CHECK_OK(cagd_patchpiecelist_count(list, &count));
    CHECK(count == 4);
    /* every patch is the surface on its rectangle */
    for (n = 0; n < count; ++n) {
        CHECK_OK(cagd_patchpiecelist_info(list, n, &kind, &du, &dv, &dim, &is_rat, &dkind));
        CHECK(kind == CAGD_PIECE_TENSOR && du == 2 && dv == 3 && dim == 3 && is_rat == 1);
        CHECK(dkind == CAGD_DOMAIN_BILINEAR);
        CHECK_OK(cagd_patchpiecelist_domain(list, n, dom, 8, &needed));
        CHECK(needed == 8 && dom[0] == dom[4] && dom[1] == dom[3]);
        CHECK_OK(cagd_patchpiecelist_points(list, n, bp, 36, &needed));
        CHECK(needed == 36);
        CHECK_OK(cagd_patchpiecelist_weights(list, n, bw, 12, &needed));
        for (i = 0; i <= 6; ++i)
            for (j = 0; j <= 6; ++j) {
                double ss = (double)i / 6, tt = (double)j / 6;
                double u = dom[0] + ss * (dom[2] - dom[0]), v = dom[1] + tt * (dom[5] - dom[1]);
                piece_eval(bp, bw, 2, 3, 3, ss, tt, x);
                CHECK_OK(cagd_bsplinesurface_eval(s, u, v, y, 3, &needed));
                CHECK_NEAR(x[0], y[0], 1e-12);
                CHECK_NEAR(x[1], y[1], 1e-12);
                CHECK_NEAR(x[2], y[2], 1e-12);
            }
    }
    /* back: the same knots and net */
    CHECK_OK(cagd_patchpiecelist_to_bsplinesurface(list, 0.0, &back, &bound));
    CHECK(bound >= 0 && bound < 1e-12);
    CHECK_OK(cagd_bsplinesurface_shape(back, shape, &rational));
    CHECK(shape[0] == 2 && shape[1] == 3 && shape[2] == NU && shape[3] == NV && rational);
    CHECK_OK(cagd_bsplinesurface_array(back, 0, k, 16, &needed));
    CHECK(needed == 7 && memcmp(k, ku, sizeof ku) == 0);
    CHECK_OK(cagd_bsplinesurface_array(back, 1, k, 16, &needed));
    CHECK(needed == 10 && memcmp(k, kv, sizeof kv) == 0);
    CHECK_OK(cagd_bsplinesurface_array(back, 2, got, NU * NV * DIM, &needed));
    for (i = 0; i < NU * NV * DIM; ++i) CHECK_NEAR(got[i], pts[i], 1e-12);
    CHECK_OK(cagd_bsplinesurface_array(back, 3, gw, NU * NV, &needed));
    for (i = 0; i < NU * NV; ++i) CHECK_NEAR(gw[i], w[i], 1e-12);
    /* bad input */
    CHECK_STATUS(cagd_bsplinesurface_to_bezier_patches(NULL, &list), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_bsplinesurface_to_bezier_patches(s, NULL), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_patchpiecelist_to_bsplinesurface(list, -1.0, &bad, NULL),
                 CAGD_ERR_INVALID_ARGUMENT);
    CHECK_STATUS(cagd_patchpiecelist_to_bsplinesurface(list, NAN, &bad, NULL),
                 CAGD_ERR_INVALID_ARGUMENT);
    CHECK_STATUS(cagd_patchpiecelist_to_bsplinesurface(NULL, 0.0, &bad, NULL),
                 CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_patchpiecelist_to_bsplinesurface(list, 0.0, NULL, NULL),
                 CAGD_ERR_NULL_POINTER);
    /* a piece whose domain is not an axis-parallel rectangle (a degenerate rectangle) */
    CHECK_OK(cagd_tripatch_new(tri_pts, 1, 3, &tp));
    CHECK_OK(cagd_tripatch_to_rect(tp, NULL, 1, &tri));
    CHECK_STATUS(cagd_patchpiecelist_to_bsplinesurface(tri, 0.0, &bad, NULL),
                 CAGD_ERR_INVALID_ARGUMENT);
    CHECK_MESSAGE_HAS("rectangle");
    CHECK(bad == NULL);
    rc = 0;
cleanup:
    cagd_bsplinesurface_free(s);
    cagd_bsplinesurface_free(back);
    cagd_bsplinesurface_free(bad);
    cagd_patchpiecelist_free(list);
    cagd_patchpiecelist_free(tri);
    cagd_tripatch_free(tp);
    return rc;
}
