/* Patch conversions (SPEC-convert 15.4-15.7): triangle <-> rectangles, split along a line,
 * a curve, a trimming chain; CagdPatchPieceList read-back; bad input. Expected values are
 * the public spec vectors conv-15.4-n2, conv-15.6.3-m2n1 and conv-15.7-D5-k2. */
#include <stdint.h>

#include "ctest.h"

/* conv-15.4-n2: quadratic triangle in 3D, i-major. */
static const double TRI2[18] = {0, 0, 0, 0, 1, 1, 0, 2, 0, 1, 0, 1, 1, 1, 2, 2, 0, 0};
static const double RECT_15_4[27] = {0, 0, 0, 0, 1,   1,   0, 2, 0, 1, 0, 1, 1, 0.5,
                                     1.5, 1, 1, 2, 2, 0, 0, 2, 0, 0, 2, 0, 0};
/* conv-15.6.3-m2n1 / conv-15.7-D5-k2: a 2 x 1 patch in 3D. */
static const double RECT21[18] = {0, 0, 0, 0, 1, 0, 1, 0, 1, 1, 1, 2, 2, 0, 2, 2, 1, 4};
static const double LOWER_15_6_3[30] = {
    0, 0, 0, 0, 1.0 / 3, 0, 0, 2.0 / 3, 0, 0, 1, 0, 2.0 / 3, 0, 2.0 / 3,
    2.0 / 3, 1.0 / 3, 1, 2.0 / 3, 2.0 / 3, 4.0 / 3, 4.0 / 3, 0, 4.0 / 3, 4.0 / 3, 1.0 / 3, 2, 2, 0, 2};
static const double D5_15_7[54] = {
    0, 0, 0, 0, 0.2, 0, 0, 0.4, 0, 0, 0.6, 0, 0, 0.8, 0, 0, 1, 0,
    0.5, 0, 0.5, 0.7, 0.2, 0.8, 0.775, 0.4, 1.075, 0.725, 0.6, 1.2, 0.55, 0.8, 1.05, 0.25, 1, 0.5,
    1, 0, 1, 1.4, 0.2, 1.6, 1.55, 0.4, 2.15, 1.45, 0.6, 2.4, 1.1, 0.8, 2.1, 0.5, 1, 1};

/* Checks every double of piece `i`'s points against `want` (n doubles). */
static int points_match(const CagdPatchPieceList *l, size_t i, const double *want, size_t n) {
    double buf[64];
    size_t needed = 0;
    if (n > 64) return 0;
    if (cagd_patchpiecelist_points(l, i, buf, 64, &needed) != CAGD_OK || needed != n) return 0;
    for (size_t k = 0; k < n; k++) {
        if (fabs(buf[k] - want[k]) > 1e-12 * (1.0 + fabs(want[k]))) {
            fprintf(stderr, "point double %zu: %.17g vs %.17g\n", k, buf[k], want[k]);
            return 0;
        }
    }
    return 1;
}

int cagd_ctest_convert_triangle_to_rectangles(void) {
    int rc = 1;
    CagdTriPatch *t = NULL;
    CagdPatchPieceList *l = NULL, *three = NULL, *rat = NULL;
    size_t count = 0, du = 0, dv = 0, dim = 0, needed = 0;
    int kind = 0, rational = -1, dkind = 0;
    double dom[8] = {0}, w[9] = {0};
    const double weights[6] = {1, 2, 1, 1, 3, 1};

    CHECK_OK(cagd_tripatch_new(TRI2, 2, 3, &t));
    CHECK_OK(cagd_tripatch_to_rect(t, NULL, 2, &l));
    CHECK_OK(cagd_patchpiecelist_count(l, &count));
    CHECK(count == 1);
    CHECK_OK(cagd_patchpiecelist_info(l, 0, &kind, &du, &dv, &dim, &rational, &dkind));
    CHECK(kind == CAGD_PIECE_TENSOR && du == 2 && dv == 2 && dim == 3 && rational == 0);
    CHECK(dkind == CAGD_DOMAIN_BILINEAR);
    CHECK(points_match(l, 0, RECT_15_4, 27));
    CHECK_STATUS(cagd_patchpiecelist_domain(l, 0, NULL, 0, &needed), CAGD_ERR_BUFFER_TOO_SMALL);
    CHECK(needed == 8);
    CHECK_OK(cagd_patchpiecelist_domain(l, 0, dom, 8, &needed));
    CHECK(dom[6] == 1.0 && dom[7] == 0.0); /* X11 = (1, 0): the collapsed edge */
    CHECK_STATUS(cagd_patchpiecelist_weights(l, 0, w, 9, &needed), CAGD_ERR_NOT_AVAILABLE);

    CHECK_OK(cagd_tripatch_to_three_rects(t, NULL, 1.0 / 3, 1.0 / 3, 0.5, 0.5, 0.5, &three));
    CHECK_OK(cagd_patchpiecelist_count(three, &count));
    CHECK(count == 3);
    CHECK_OK(cagd_patchpiecelist_domain(three, 1, dom, 8, &needed));
    /* D2 = (U, K, G, P) */
    CHECK(dom[0] == 1.0 && dom[1] == 0.0 && dom[2] == 0.5 && dom[3] == 0.5);
    CHECK(dom[4] == 0.5 && dom[5] == 0.0);

    CHECK_OK(cagd_tripatch_to_three_rects(t, weights, 0.3, 0.3, 0.4, 0.5, 0.6, &rat));
    CHECK_OK(cagd_patchpiecelist_info(rat, 2, &kind, &du, &dv, &dim, &rational, &dkind));
    CHECK(rational == 1 && du == 2 && dv == 2);
    CHECK_OK(cagd_patchpiecelist_weights(rat, 2, w, 9, &needed));
    CHECK(needed == 9 && w[0] > 0);
    rc = 0;
cleanup:
    cagd_patchpiecelist_free(l);
    cagd_patchpiecelist_free(three);
    cagd_patchpiecelist_free(rat);
    cagd_tripatch_free(t);
    return rc;
}

int cagd_ctest_convert_rectangle_splits(void) {
    int rc = 1;
    CagdTensorPatch *p = NULL, *sq = NULL;
    CagdPatchPieceList *tri = NULL, *line = NULL, *curve = NULL, *trim = NULL, *back = NULL;
    size_t count = 0, du = 0, dv = 0, dim = 0, needed = 0;
    int kind = 0, rational = 0, dkind = 0;
    double dom[24] = {0};
    const double a[3] = {0.5, 1.0, 0.25};
    const double intervals[2] = {0.0, 0.7};
    const size_t counts[1] = {4};
    const double coeffs[4] = {0.6, 0.5, 0.2, 0.0};

    CHECK_OK(cagd_tensorpatch_new(RECT21, 2, 1, 3, &p));
    CHECK_OK(cagd_tensorpatch_to_triangles(p, NULL, &tri));
    CHECK_OK(cagd_patchpiecelist_info(tri, 0, &kind, &du, &dv, &dim, &rational, &dkind));
    CHECK(kind == CAGD_PIECE_TRIANGLE && du == 3 && dkind == CAGD_DOMAIN_TRIANGLE);
    CHECK(points_match(tri, 0, LOWER_15_6_3, 30));

    CHECK_OK(cagd_tensorpatch_split_line(p, NULL, 0.25, 0.5, &line));
    CHECK_OK(cagd_patchpiecelist_count(line, &count));
    CHECK(count == 2);
    CHECK_OK(cagd_patchpiecelist_info(line, 1, &kind, &du, &dv, &dim, &rational, &dkind));
    CHECK(du == 2 && dv == 3); /* m x (m + n) */

    CHECK_OK(cagd_tensorpatch_split_curve(p, NULL, a, 3, &curve));
    CHECK_OK(cagd_patchpiecelist_info(curve, 0, &kind, &du, &dv, &dim, &rational, &dkind));
    CHECK(du == 2 && dv == 5 && dkind == CAGD_DOMAIN_RULED);
    CHECK(points_match(curve, 0, D5_15_7, 54));
    CHECK_OK(cagd_patchpiecelist_domain(curve, 0, dom, 24, &needed));
    CHECK(needed == 12 && dom[6] == 0.5 && dom[8] == 1.0 && dom[10] == 0.25); /* s1 = f */

    CHECK_OK(cagd_tensorpatch_trim(p, NULL, CAGD_TRIM_U_OF_V, CAGD_TRIM_KEEP_ABOVE, intervals,
                                   counts, coeffs, 1, &trim));
    CHECK_OK(cagd_patchpiecelist_count(trim, &count));
    CHECK(count == 2); /* the ruled piece and the strip v in [0.7, 1] */

    /* The 15.4 inverse on a square patch that is not degenerate. */
    CHECK_OK(cagd_tensorpatch_new(RECT21, 1, 2, 3, &sq));
    CHECK_STATUS(cagd_tensorpatch_to_triangle(sq, NULL, 1e-12, &back), CAGD_ERR_BAD_DEGREE_PAIR);
    rc = 0;
cleanup:
    cagd_patchpiecelist_free(tri);
    cagd_patchpiecelist_free(line);
    cagd_patchpiecelist_free(curve);
    cagd_patchpiecelist_free(trim);
    cagd_patchpiecelist_free(back);
    cagd_tensorpatch_free(p);
    cagd_tensorpatch_free(sq);
    return rc;
}

int cagd_ctest_convert_bad_input(void) {
    int rc = 1;
    CagdTriPatch *t = NULL;
    CagdTensorPatch *p = NULL, *sq = NULL;
    CagdPatchPieceList *l = NULL, *ok = NULL;
    size_t needed = 0, count = 0, sz = 0;
    int k = 0;
    double buf[64] = {0};
    const double bad_w[6] = {1, 1, 0, 1, 1, 1};
    const double corners[8] = {0, 0, 0.5, 0, 0, 0.5, 0.1, 0.1}; /* folds */
    const double square[27] = {0, 0, 0, 1, 0, 0, 2, 0, 0, 0, 1, 0, 1, 1, 0,
                               2, 1, 5, 0, 2, 0, 1, 2, 0, 2, 2, 0};
    const double intervals[4] = {0.0, 0.5, 0.6, 1.0};
    const size_t counts[2] = {2, 2};
    const double coeffs[4] = {0.5, 0.5, 0.5, 0.5};
    const double out_of_range[2] = {0.5, 1.5};

    CHECK_OK(cagd_tripatch_new(TRI2, 2, 3, &t));
    CHECK_OK(cagd_tensorpatch_new(RECT21, 2, 1, 3, &p));
    CHECK_OK(cagd_tensorpatch_new(square, 2, 2, 3, &sq));
    CHECK_STATUS(cagd_tripatch_to_rect(NULL, NULL, 2, &l), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_tripatch_to_rect(t, NULL, 2, NULL), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_tripatch_to_rect(t, bad_w, 2, &l), CAGD_ERR_NON_POSITIVE_WEIGHT);
    CHECK_STATUS(cagd_tripatch_to_rect(t, NULL, 1, &l), CAGD_ERR_BAD_DEGREE_PAIR);
    CHECK_STATUS(cagd_tripatch_to_quad(t, NULL, NULL, &l), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_tripatch_to_quad(t, NULL, corners, &l), CAGD_ERR_DEGENERATE_SPLIT);
    CHECK_STATUS(cagd_tripatch_to_three_rects(t, NULL, 0.6, 0.6, 0.5, 0.5, 0.5, &l),
                 CAGD_ERR_INVALID_ARGUMENT);
    CHECK_STATUS(cagd_tripatch_to_three_rects(t, NULL, 0.1, 0.1, 0.5, 0.5, 0.5, &l),
                 CAGD_ERR_DEGENERATE_SPLIT);
    CHECK_STATUS(cagd_tripatch_to_three_rects(t, NULL, NAN, 0.3, 0.5, 0.5, 0.5, &l),
                 CAGD_ERR_INVALID_ARGUMENT);
    CHECK_STATUS(cagd_tensorpatch_to_triangle(sq, NULL, 1e-12, &l), CAGD_ERR_NOT_DEGENERATE);
    CHECK_MESSAGE_HAS("residual");
    CHECK_STATUS(cagd_tensorpatch_to_triangle(sq, NULL, -1.0, &l), CAGD_ERR_INVALID_ARGUMENT);
    CHECK_STATUS(cagd_tensorpatch_to_triangles(NULL, NULL, &l), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_tensorpatch_split_line(p, NULL, 0.0, 2.0, &l), CAGD_ERR_INVALID_ARGUMENT);
    CHECK_STATUS(cagd_tensorpatch_split_line(p, NULL, INFINITY, 0.5, &l),
                 CAGD_ERR_INVALID_ARGUMENT);
    CHECK_STATUS(cagd_tensorpatch_split_curve(p, NULL, out_of_range, 2, &l),
                 CAGD_ERR_INVALID_ARGUMENT);
    CHECK_STATUS(cagd_tensorpatch_split_curve(p, NULL, out_of_range, 0, &l),
                 CAGD_ERR_NOT_ENOUGH_POINTS);
    CHECK_STATUS(cagd_tensorpatch_split_curve(p, NULL, NULL, 2, &l), CAGD_ERR_NULL_POINTER);
    /* A gap between the two segments' intervals. */
    CHECK_STATUS(cagd_tensorpatch_trim(p, NULL, CAGD_TRIM_U_OF_V, CAGD_TRIM_KEEP_BELOW,
                                       intervals, counts, coeffs, 2, &l),
                 CAGD_ERR_UNSUPPORTED_TRIM);
    CHECK_STATUS(cagd_tensorpatch_trim(p, NULL, 7, CAGD_TRIM_KEEP_BELOW, intervals, counts,
                                       coeffs, 2, &l),
                 CAGD_ERR_INVALID_ARGUMENT);
    CHECK_STATUS(cagd_tensorpatch_trim(p, NULL, CAGD_TRIM_U_OF_V, CAGD_TRIM_KEEP_BELOW,
                                       intervals, counts, coeffs, 0, &l),
                 CAGD_ERR_UNSUPPORTED_TRIM);
    CHECK(l == NULL); /* nothing written on failure */

    CHECK_OK(cagd_tensorpatch_to_triangles(p, NULL, &ok));
    CHECK_STATUS(cagd_patchpiecelist_count(NULL, &count), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_patchpiecelist_count(ok, NULL), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_patchpiecelist_info(ok, 2, &k, &sz, &sz, &sz, &k, &k),
                 CAGD_ERR_INVALID_ARGUMENT);
    CHECK_STATUS(cagd_patchpiecelist_info(ok, 0, NULL, &sz, &sz, &sz, &k, &k),
                 CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_patchpiecelist_points(ok, 0, NULL, 5, &needed), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_patchpiecelist_points(ok, 0, buf, 5, NULL), CAGD_ERR_NULL_POINTER);
    buf[0] = -7.0;
    CHECK_STATUS(cagd_patchpiecelist_points(ok, 0, buf, 5, &needed), CAGD_ERR_BUFFER_TOO_SMALL);
    CHECK(needed == 30 && buf[0] == -7.0);
    CHECK_STATUS(cagd_patchpiecelist_domain(ok, 5, buf, 64, &needed), CAGD_ERR_INVALID_ARGUMENT);
    cagd_patchpiecelist_free(NULL);
    cagd_patchpiecelist_free(NULL);
    rc = 0;
cleanup:
    cagd_patchpiecelist_free(l);
    cagd_patchpiecelist_free(ok);
    cagd_tripatch_free(t);
    cagd_tensorpatch_free(p);
    cagd_tensorpatch_free(sq);
    return rc;
}
