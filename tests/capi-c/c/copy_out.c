/* The one-call copies of results of unknown size: cagd_curvelist_copy, cagd_bspline_copy,
 * cagd_tensorpatchlist_copy, cagd_tripatchlist_copy. Each is compared with the per-piece
 * handle accessors bit for bit; capacity 0 asks the sizes; a short buffer writes nothing
 * but the sizes; NULLs. */
#include <stdlib.h>

#include "ctest.h"

/* A cubic 2D B-spline with two interior knots (three spans), rational or not. */
static const double KN[10] = {0, 0, 0, 0, 0.25, 0.6, 1, 1, 1, 1};
static const double SP[12] = {0, 0, 1, 2, 2, 3, 4, 1, 5, -1, 7, 0};
static const double SW[6] = {1, 2, 0.5, 1, 1.5, 1};

/* Field-wise equality (the structs have padding bytes, which memcmp must not read). */
static int same_sizes(const CagdCurveListSizes *a, const CagdCurveListSizes *b) {
    return a->n_pieces == b->n_pieces && a->dim == b->dim && a->rational == b->rational &&
           a->intervals_len == b->intervals_len && a->points_len == b->points_len &&
           a->weights_len == b->weights_len && a->bounds_len == b->bounds_len;
}

/* Compares a curve list's one-call copy with its per-piece accessors. */
static int check_curvelist(const CagdCurveList *list, int rational, int with_bounds) {
    int rc = 1;
    CagdCurveListSizes s, s2;
    size_t *deg = NULL, count = 0, i, off = 0, woff = 0, needed = 0;
    double *iv = NULL, *pts = NULL, *w = NULL, *b = NULL, buf[64], a = 0, e = 0, bound = 0;
    CagdCurve *c = NULL;

    memset(&s, 0, sizeof s);
    CHECK_STATUS(cagd_curvelist_copy(list, NULL, 0, NULL, 0, NULL, 0, NULL, 0, NULL, 0, &s),
                 CAGD_ERR_BUFFER_TOO_SMALL);
    CHECK_OK(cagd_curvelist_count(list, &count));
    CHECK(s.n_pieces == count && s.dim == 2 && s.intervals_len == 2 * count);
    CHECK(s.rational == (rational != 0));
    CHECK(s.bounds_len == (with_bounds ? count : 0));
    CHECK(rational ? s.weights_len == s.points_len / 2 : s.weights_len == 0);
    deg = malloc(sizeof(size_t) * s.n_pieces);
    iv = malloc(sizeof(double) * s.intervals_len);
    pts = malloc(sizeof(double) * s.points_len);
    w = malloc(sizeof(double) * (s.weights_len + 1));
    b = malloc(sizeof(double) * (s.bounds_len + 1));
    CHECK(deg && iv && pts && w && b);
    /* one buffer short: only the sizes are written */
    deg[0] = 99;
    CHECK_STATUS(cagd_curvelist_copy(list, deg, s.n_pieces, iv, s.intervals_len, pts,
                                     s.points_len - 1, w, s.weights_len, b, s.bounds_len, &s2),
                 CAGD_ERR_BUFFER_TOO_SMALL);
    CHECK(deg[0] == 99 && same_sizes(&s, &s2));
    CHECK_MESSAGE_HAS("points_out_cap");
    CHECK_OK(cagd_curvelist_copy(list, deg, s.n_pieces, iv, s.intervals_len, pts, s.points_len,
                                 w, s.weights_len, b, s.bounds_len, &s2));
    CHECK(same_sizes(&s, &s2));
    for (i = 0; i < count; ++i) {
        size_t d = 0, np;
        CHECK_OK(cagd_curvelist_get(list, i, &c));
        CHECK_OK(cagd_curve_degree(c, &d));
        CHECK(deg[i] == d);
        np = d + 1;
        CHECK_OK(cagd_curve_points(c, buf, 64, &needed));
        CHECK(needed == np * 2 && memcmp(buf, pts + off, needed * sizeof(double)) == 0);
        if (rational) {
            CHECK_OK(cagd_curve_weights(c, buf, 64, &needed));
            CHECK(memcmp(buf, w + woff, np * sizeof(double)) == 0);
        }
        CHECK_OK(cagd_curvelist_interval(list, i, &a, &e));
        CHECK(iv[2 * i] == a && iv[2 * i + 1] == e);
        if (with_bounds) {
            CHECK_OK(cagd_curvelist_bound(list, i, &bound));
            CHECK(b[i] == bound);
        }
        off += np * 2;
        woff += np;
        cagd_curve_free(c);
        c = NULL;
    }
    CHECK(off == s.points_len);
    rc = 0;
cleanup:
    cagd_curve_free(c);
    free(deg);
    free(iv);
    free(pts);
    free(w);
    free(b);
    return rc;
}

int cagd_ctest_curvelist_copy(void) {
    int rc = 1;
    CagdBSpline *sp = NULL, *sr = NULL, *red = NULL;
    CagdCurveList *l1 = NULL, *l2 = NULL, *l3 = NULL;
    CagdCurve *c = NULL;
    CagdReport *rep = NULL;
    CagdReduceOptions o;
    CagdCurveListSizes s;
    double p7[16] = {0, 0, 1, 3, 3, 4, 5, 1, 6, 5, 8, 2, 9, 6, 11, 0};

    CHECK_OK(cagd_bspline_new(3, KN, 10, SP, 6, 2, &sp));
    CHECK_OK(cagd_bspline_to_beziers(sp, &l1));
    CHECK(check_curvelist(l1, 0, 0) == 0);
    CHECK_OK(cagd_bspline_new_rational(3, KN, 10, SP, SW, 6, 2, &sr));
    CHECK_OK(cagd_bspline_to_beziers(sr, &l2));
    CHECK(check_curvelist(l2, 1, 0) == 0);
    /* the pieces of a reduction to a tolerance carry bounds */
    CHECK_OK(cagd_curve_new(p7, 8, 2, &c));
    CHECK_OK(cagd_reduce_options_init(&o));
    o.tolerance = 0.01;
    CHECK_OK(cagd_curve_reduce_to_tolerance(c, &o, &red, &rep));
    CHECK_OK(cagd_report_pieces(rep, &l3));
    CHECK(check_curvelist(l3, 0, 1) == 0);
    /* NULLs */
    CHECK_STATUS(cagd_curvelist_copy(NULL, NULL, 0, NULL, 0, NULL, 0, NULL, 0, NULL, 0, &s),
                 CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_curvelist_copy(l1, NULL, 0, NULL, 0, NULL, 0, NULL, 0, NULL, 0, NULL),
                 CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_curvelist_copy(l1, NULL, 3, NULL, 0, NULL, 0, NULL, 0, NULL, 0, &s),
                 CAGD_ERR_NULL_POINTER);
    rc = 0;
cleanup:
    cagd_curvelist_free(l3);
    cagd_curvelist_free(l2);
    cagd_curvelist_free(l1);
    cagd_report_free(rep);
    cagd_bspline_free(red);
    cagd_bspline_free(sr);
    cagd_bspline_free(sp);
    cagd_curve_free(c);
    return rc;
}

int cagd_ctest_bspline_copy(void) {
    int rc = 1;
    CagdBSpline *sp = NULL, *sr = NULL;
    CagdBSplineSizes s;
    double k[16], p[16], w[8], hk[16], hp[16], hw[8], overlap[40];
    size_t needed = 0;

    CHECK_OK(cagd_bspline_new(3, KN, 10, SP, 6, 2, &sp));
    CHECK_STATUS(cagd_bspline_copy(sp, NULL, 0, NULL, 0, NULL, 0, &s), CAGD_ERR_BUFFER_TOO_SMALL);
    CHECK(s.degree == 3 && s.dim == 2 && s.n_points == 6 && !s.rational);
    CHECK(s.knots_len == 10 && s.points_len == 12 && s.weights_len == 0);
    CHECK_OK(cagd_bspline_copy(sp, k, 16, p, 16, NULL, 0, &s));
    CHECK_OK(cagd_bspline_knots(sp, hk, 16, &needed));
    CHECK(memcmp(k, hk, 10 * sizeof(double)) == 0);
    CHECK_OK(cagd_bspline_points(sp, hp, 16, &needed));
    CHECK(memcmp(p, hp, 12 * sizeof(double)) == 0);
    /* rational */
    CHECK_OK(cagd_bspline_new_rational(3, KN, 10, SP, SW, 6, 2, &sr));
    CHECK_STATUS(cagd_bspline_copy(sr, k, 16, p, 16, w, 5, &s), CAGD_ERR_BUFFER_TOO_SMALL);
    CHECK(s.rational && s.weights_len == 6);
    CHECK_OK(cagd_bspline_copy(sr, k, 16, p, 16, w, 8, &s));
    CHECK_OK(cagd_bspline_weights(sr, hw, 8, &needed));
    CHECK(memcmp(w, hw, 6 * sizeof(double)) == 0);
    CHECK_OK(cagd_bspline_points(sr, hp, 16, &needed));
    CHECK(memcmp(p, hp, 12 * sizeof(double)) == 0);
    /* overlapping buffers, NULLs */
    CHECK_STATUS(cagd_bspline_copy(sr, overlap, 16, overlap + 8, 16, w, 8, &s),
                 CAGD_ERR_INVALID_ARGUMENT);
    CHECK_STATUS(cagd_bspline_copy(NULL, k, 16, p, 16, w, 8, &s), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_bspline_copy(sr, k, 16, p, 16, w, 8, NULL), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_bspline_copy(sr, k, 16, NULL, 16, w, 8, &s), CAGD_ERR_NULL_POINTER);
    rc = 0;
cleanup:
    cagd_bspline_free(sr);
    cagd_bspline_free(sp);
    return rc;
}

/* tensor-1 and tri-1 of shared/spec/vectors-reduce.json (as in patch_reduce.c) */
static const double T1_P[36] = {0, 0, 0, 1, 0, 1, 2, 0, 0, 3, 0, 2, 0, 1, 2, 1, 1, 3,
                                2, 1, 1, 3, 1, 0, 0, 2, 0, 1, 2, -1, 2, 2, 4, 3, 2, 1};
static const double TRI1_T[30] = {0, 0, -3, 0, 1, 2, 0, 2, 0, 0, 3, -2, 1, 0, 0,
                                  1, 1, -2, 1, 2, 3, 2, 0, 3, 2, 1, 1, 3, 0, -1};

int cagd_ctest_patchlist_copy(void) {
    int rc = 1;
    CagdTensorPatch *p = NULL, *piece = NULL;
    CagdTriPatch *t = NULL, *tpiece = NULL;
    CagdTensorPatchList *list = NULL;
    CagdTriPatchList *tlist = NULL;
    CagdReport *rep = NULL, *trep = NULL;
    CagdReduceOptions o;
    CagdPatchListSizes s;
    size_t *deg = NULL, i, off = 0, needed = 0, du = 0, dv = 0, dim = 0;
    double *dom = NULL, *pts = NULL, *b = NULL, hd[6], hb = 0, hp[64];

    CHECK_OK(cagd_reduce_options_init(&o));
    o.tolerance = 0.05;
    CHECK_OK(cagd_tensorpatch_new(T1_P, 2, 3, 3, &p));
    o.patch_method = CAGD_PATCH_BY_CURVES;
    o.target = 1;
    o.target_v = 2;
    CHECK_OK(cagd_tensorpatch_reduce_to_tolerance(p, &o, &list, &rep));
    CHECK_STATUS(cagd_tensorpatchlist_copy(list, NULL, 0, NULL, 0, NULL, 0, NULL, 0, &s),
                 CAGD_ERR_BUFFER_TOO_SMALL);
    CHECK(s.n_pieces > 1 && s.dim == 3 && s.degrees_len == 2 * s.n_pieces);
    CHECK(s.domains_len == 4 * s.n_pieces && s.bounds_len == s.n_pieces);
    deg = malloc(sizeof(size_t) * s.degrees_len);
    dom = malloc(sizeof(double) * s.domains_len);
    pts = malloc(sizeof(double) * s.points_len);
    b = malloc(sizeof(double) * s.bounds_len);
    CHECK(deg && dom && pts && b);
    CHECK_OK(cagd_tensorpatchlist_copy(list, deg, s.degrees_len, dom, s.domains_len, pts,
                                       s.points_len, b, s.bounds_len, &s));
    for (i = 0; i < s.n_pieces; ++i) {
        CHECK_OK(cagd_tensorpatchlist_get(list, i, &piece, hd, &hb));
        CHECK_OK(cagd_tensorpatch_shape(piece, &du, &dv, &dim));
        CHECK(deg[2 * i] == du && deg[2 * i + 1] == dv);
        CHECK(memcmp(dom + 4 * i, hd, 4 * sizeof(double)) == 0 && b[i] == hb);
        CHECK_OK(cagd_tensorpatch_points(piece, hp, 64, &needed));
        CHECK(memcmp(pts + off, hp, needed * sizeof(double)) == 0);
        off += needed;
        cagd_tensorpatch_free(piece);
        piece = NULL;
    }
    CHECK(off == s.points_len);
    free(deg);
    free(dom);
    free(pts);
    free(b);
    deg = NULL;
    dom = pts = b = NULL;
    /* triangles */
    CHECK_OK(cagd_tripatch_new(TRI1_T, 3, 3, &t));
    o.patch_method = CAGD_PATCH_PERTURB;
    o.target = 2;
    CHECK_OK(cagd_tripatch_reduce_to_tolerance(t, &o, &tlist, &trep));
    CHECK_STATUS(cagd_tripatchlist_copy(tlist, NULL, 0, NULL, 0, NULL, 0, NULL, 0, &s),
                 CAGD_ERR_BUFFER_TOO_SMALL);
    CHECK(s.degrees_len == s.n_pieces && s.domains_len == 6 * s.n_pieces);
    deg = malloc(sizeof(size_t) * s.degrees_len);
    dom = malloc(sizeof(double) * s.domains_len);
    pts = malloc(sizeof(double) * s.points_len);
    b = malloc(sizeof(double) * s.bounds_len);
    CHECK(deg && dom && pts && b);
    CHECK_STATUS(cagd_tripatchlist_copy(tlist, deg, s.degrees_len, dom, s.domains_len, pts,
                                        s.points_len, b, s.bounds_len - 1, &s),
                 CAGD_ERR_BUFFER_TOO_SMALL);
    CHECK_OK(cagd_tripatchlist_copy(tlist, deg, s.degrees_len, dom, s.domains_len, pts,
                                    s.points_len, b, s.bounds_len, &s));
    off = 0;
    for (i = 0; i < s.n_pieces; ++i) {
        CHECK_OK(cagd_tripatchlist_get(tlist, i, &tpiece, hd, &hb));
        CHECK_OK(cagd_tripatch_shape(tpiece, &du, &dim));
        CHECK(deg[i] == du);
        CHECK(memcmp(dom + 6 * i, hd, 6 * sizeof(double)) == 0 && b[i] == hb);
        CHECK_OK(cagd_tripatch_points(tpiece, hp, 64, &needed));
        CHECK(memcmp(pts + off, hp, needed * sizeof(double)) == 0);
        off += needed;
        cagd_tripatch_free(tpiece);
        tpiece = NULL;
    }
    CHECK(off == s.points_len);
    CHECK_STATUS(cagd_tripatchlist_copy(NULL, NULL, 0, NULL, 0, NULL, 0, NULL, 0, &s),
                 CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_tensorpatchlist_copy(list, NULL, 0, NULL, 0, NULL, 0, NULL, 0, NULL),
                 CAGD_ERR_NULL_POINTER);
    rc = 0;
cleanup:
    free(deg);
    free(dom);
    free(pts);
    free(b);
    cagd_tensorpatch_free(piece);
    cagd_tripatch_free(tpiece);
    cagd_tensorpatchlist_free(list);
    cagd_tripatchlist_free(tlist);
    cagd_report_free(rep);
    cagd_report_free(trep);
    cagd_tensorpatch_free(p);
    cagd_tripatch_free(t);
    return rc;
}

int cagd_ctest_wsgblist_copy(void) {
    int rc = 1;
    static const double P7[16] = {0, 0, 1, 3, 3, 4, 5, 1, 6, 5, 8, 2, 9, 6, 11, 0};
    CagdWsgbCurve *c = NULL, *piece = NULL;
    CagdWsgbCurveList *list = NULL;
    CagdReduceOptions o;
    CagdWsgbListSizes s;
    size_t *deg = NULL, *ord = NULL, i, off = 0, needed = 0, n = 0, l = 0, dim = 0;
    double *iv = NULL, *pts = NULL, *b = NULL, hp[32], start = 0, end = 0, bound = 0;

    CHECK_OK(cagd_wsgb_new(P7, 8, 2, 1, &c));
    CHECK_OK(cagd_reduce_options_init(&o));
    o.target = 4;
    o.tolerance = 0.005; /* several pieces for these (unit-sized) points */
    CHECK_OK(cagd_wsgb_reduce_to_tolerance(c, CAGD_WSGB_PERTURBATION, &o, &list));
    CHECK_STATUS(cagd_wsgblist_copy(list, NULL, 0, NULL, 0, NULL, 0, NULL, 0, NULL, 0, &s),
                 CAGD_ERR_BUFFER_TOO_SMALL);
    CHECK(s.n_pieces > 1 && s.dim == 2 && s.intervals_len == 2 * s.n_pieces);
    deg = malloc(sizeof(size_t) * s.n_pieces);
    ord = malloc(sizeof(size_t) * s.n_pieces);
    iv = malloc(sizeof(double) * s.intervals_len);
    pts = malloc(sizeof(double) * s.points_len);
    b = malloc(sizeof(double) * s.n_pieces);
    CHECK(deg && ord && iv && pts && b);
    CHECK_STATUS(cagd_wsgblist_copy(list, deg, s.n_pieces, ord, s.n_pieces - 1, iv,
                                    s.intervals_len, pts, s.points_len, b, s.n_pieces, &s),
                 CAGD_ERR_BUFFER_TOO_SMALL);
    CHECK_MESSAGE_HAS("orders_out_cap");
    CHECK_OK(cagd_wsgblist_copy(list, deg, s.n_pieces, ord, s.n_pieces, iv, s.intervals_len,
                                pts, s.points_len, b, s.n_pieces, &s));
    for (i = 0; i < s.n_pieces; ++i) {
        CHECK_OK(cagd_wsgblist_get(list, i, &piece, &start, &end, &bound));
        CHECK_OK(cagd_wsgb_shape(piece, &n, &l, &dim));
        CHECK(deg[i] == n && ord[i] == l && dim == 2);
        CHECK(iv[2 * i] == start && iv[2 * i + 1] == end && b[i] == bound);
        CHECK_OK(cagd_wsgb_points(piece, hp, 32, &needed));
        CHECK(memcmp(pts + off, hp, needed * sizeof(double)) == 0);
        off += needed;
        cagd_wsgb_free(piece);
        piece = NULL;
    }
    CHECK(off == s.points_len);
    CHECK_STATUS(cagd_wsgblist_copy(NULL, NULL, 0, NULL, 0, NULL, 0, NULL, 0, NULL, 0, &s),
                 CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_wsgblist_copy(list, NULL, 0, NULL, 0, NULL, 0, NULL, 0, NULL, 0, NULL),
                 CAGD_ERR_NULL_POINTER);
    rc = 0;
cleanup:
    free(deg);
    free(ord);
    free(iv);
    free(pts);
    free(b);
    cagd_wsgb_free(piece);
    cagd_wsgblist_free(list);
    cagd_wsgb_free(c);
    return rc;
}
