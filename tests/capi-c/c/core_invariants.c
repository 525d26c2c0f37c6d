/* Degeneracy invariants (seed 000 §14.1) and parametric distances, checked against the
 * reference vectors of /work/shared/spec/vectors-reduce.json (ids cited below) and closed
 * forms, plus NULL / short-buffer / size-query / bad-argument checks.
 * The invariants of integer nets are sums of small integers times exact binomials: exact
 * in double, so those comparisons use ==. */
#include "ctest.h"

/* Rounding of the thirds of deg-tri-2 (inputs |T| <= 2, binomial weights <= 3, 10 terms):
 * a few ulp of 2^3 * 2. */
#define TRI_TOL 1e-14
/* cagd_core::curve_distance / patch distances: relative accuracy 1e-12 (documented); the
 * distances below are 0.5 and 0.25. */
#define DIST_TOL 1e-12

int cagd_ctest_curve_forward_difference(void) {
    int rc = 1;
    CagdCurve *c = NULL, *r = NULL;
    /* vector deg-curve-1: P = (0,0), (1,3), (3,4), (5,1), (6,5); F = (0, 13) */
    const double pts[10] = {0, 0, 1, 3, 3, 4, 5, 1, 6, 5};
    /* quarter circle, weights 1, w, 1: homogeneous F = (1 - 2w, 1 - 2w, 2 - 2w) */
    const double arc[6] = {1, 0, 1, 1, 0, 1};
    const double w = sqrt(0.5), ws[3] = {1.0, w, 1.0};
    double f[3] = {7, 7, 7};
    size_t needed = 0;

    CHECK_OK(cagd_curve_new(pts, 5, 2, &c));
    CHECK_STATUS(cagd_curve_forward_difference(c, NULL, 0, &needed), CAGD_ERR_BUFFER_TOO_SMALL);
    CHECK(needed == 2);
    needed = 0;
    CHECK_STATUS(cagd_curve_forward_difference(c, f, 1, &needed), CAGD_ERR_BUFFER_TOO_SMALL);
    CHECK(needed == 2 && f[0] == 7.0);
    CHECK_OK(cagd_curve_forward_difference(c, f, 3, &needed));
    CHECK(needed == 2 && f[0] == 0.0 && f[1] == 13.0 && f[2] == 7.0);

    CHECK_OK(cagd_curve_new_rational(arc, ws, 3, 2, &r));
    CHECK_OK(cagd_curve_forward_difference(r, f, 3, &needed));
    CHECK(needed == 3);
    CHECK_NEAR(f[0], 1.0 - 2.0 * w, 1e-15);
    CHECK_NEAR(f[1], 1.0 - 2.0 * w, 1e-15);
    CHECK_NEAR(f[2], 2.0 - 2.0 * w, 1e-15);

    CHECK_STATUS(cagd_curve_forward_difference(NULL, f, 3, &needed), CAGD_ERR_NULL_POINTER);
    CHECK_MESSAGE_HAS("curve");
    CHECK_STATUS(cagd_curve_forward_difference(c, f, 3, NULL), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_curve_forward_difference(c, NULL, 3, &needed), CAGD_ERR_NULL_POINTER);
    rc = 0;
cleanup:
    cagd_curve_free(c);
    cagd_curve_free(r);
    return rc;
}

int cagd_ctest_tensorpatch_degeneracy(void) {
    int rc = 1;
    CagdTensorPatch *p = NULL;
    /* vector deg-tensor-1: m = n = 2, P_ij i-major */
    const double pts[27] = {0, 0, 0, 1, 0, 1,  2, 0, 0, 0, 1, 2, 1, 1, 3,
                            2, 1, 1, 0, 2, 0, 1, 2, -1, 2, 2, 4};
    const double f_want[9] = {0, 0, -4, 0, 0, -6, 0, 0, 2};
    const double g_want[9] = {0, 0, -2, 0, 0, -3, 0, 0, 6};
    double f[9] = {0}, g[9] = {0}, both[18] = {0};
    size_t fn = 0, gn = 0, k;

    CHECK_OK(cagd_tensorpatch_new(pts, 2, 2, 3, &p));
    /* size query of both at once */
    CHECK_STATUS(cagd_tensorpatch_degeneracy(p, NULL, 0, &fn, NULL, 0, &gn),
                 CAGD_ERR_BUFFER_TOO_SMALL);
    CHECK(fn == 9 && gn == 9);
    /* F fits, G does not: both sizes written, F untouched */
    fn = gn = 0;
    f[0] = 5.0;
    CHECK_STATUS(cagd_tensorpatch_degeneracy(p, f, 9, &fn, g, 8, &gn), CAGD_ERR_BUFFER_TOO_SMALL);
    CHECK(fn == 9 && gn == 9 && f[0] == 5.0);
    CHECK_MESSAGE_HAS("g_cap");
    CHECK_OK(cagd_tensorpatch_degeneracy(p, f, 9, &fn, g, 9, &gn));
    for (k = 0; k < 9; ++k) {
        CHECK(f[k] == f_want[k]);
        CHECK(g[k] == g_want[k]);
    }
    /* adjacent halves of one buffer are fine; overlapping ones are rejected */
    CHECK_OK(cagd_tensorpatch_degeneracy(p, both, 9, &fn, both + 9, 9, &gn));
    CHECK(both[2] == -4.0 && both[11] == -2.0);
    CHECK_STATUS(cagd_tensorpatch_degeneracy(p, both, 9, &fn, both + 8, 9, &gn),
                 CAGD_ERR_INVALID_ARGUMENT);
    CHECK_MESSAGE_HAS("overlap");
    CHECK_STATUS(cagd_tensorpatch_degeneracy(p, f, 9, &fn, g, 9, &fn), CAGD_ERR_INVALID_ARGUMENT);
    CHECK_STATUS(cagd_tensorpatch_degeneracy(NULL, f, 9, &fn, g, 9, &gn), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_tensorpatch_degeneracy(p, f, 9, NULL, g, 9, &gn), CAGD_ERR_NULL_POINTER);
    CHECK_MESSAGE_HAS("f_needed");
    CHECK_STATUS(cagd_tensorpatch_degeneracy(p, f, 9, &fn, NULL, 9, &gn), CAGD_ERR_NULL_POINTER);
    CHECK_MESSAGE_HAS("g_out");
    rc = 0;
cleanup:
    cagd_tensorpatch_free(p);
    return rc;
}

int cagd_ctest_tripatch_degeneracy(void) {
    int rc = 1;
    CagdTriPatch *p = NULL, *q = NULL;
    /* vector deg-tri-2: a degree-2 patch elevated to 3 (i-major, j in 0..=3-i): F_k = 0 */
    const double t[20] = {0.0,        1.0,       -2.0 / 3.0, 1.0,       -4.0 / 3.0,
                          1.0,        -2.0,      1.0,        2.0 / 3.0, 1.0,
                          0.0,        4.0 / 3.0, -2.0 / 3.0, 5.0 / 3.0, 4.0 / 3.0,
                          1.0,        2.0 / 3.0, 5.0 / 3.0,  2.0,       1.0};
    /* degree 1, dim 1: T_00 = 0, T_01 = 0, T_10 = 1: F_0 = T_01 - T_00 = 0,
     * F_1 = T_10 - T_00 = 1 */
    const double lin[3] = {0.0, 0.0, 1.0};
    double f[8] = {0};
    size_t needed = 0, k;

    CHECK_OK(cagd_tripatch_new(t, 3, 2, &p));
    CHECK_STATUS(cagd_tripatch_degeneracy(p, NULL, 0, &needed), CAGD_ERR_BUFFER_TOO_SMALL);
    CHECK(needed == 8);
    CHECK_STATUS(cagd_tripatch_degeneracy(p, f, 7, &needed), CAGD_ERR_BUFFER_TOO_SMALL);
    CHECK_OK(cagd_tripatch_degeneracy(p, f, 8, &needed));
    for (k = 0; k < 8; ++k) {
        CHECK_NEAR(f[k], 0.0, TRI_TOL);
    }
    CHECK_OK(cagd_tripatch_new(lin, 1, 1, &q));
    CHECK_OK(cagd_tripatch_degeneracy(q, f, 8, &needed));
    CHECK(needed == 2 && f[0] == 0.0 && f[1] == 1.0);
    CHECK_STATUS(cagd_tripatch_degeneracy(NULL, f, 8, &needed), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_tripatch_degeneracy(p, f, 8, NULL), CAGD_ERR_NULL_POINTER);
    rc = 0;
cleanup:
    cagd_tripatch_free(p);
    cagd_tripatch_free(q);
    return rc;
}

int cagd_ctest_distances(void) {
    int rc = 1;
    CagdCurve *a = NULL, *b = NULL, *c3 = NULL;
    CagdTensorPatch *pa = NULL, *pb = NULL;
    CagdTriPatch *ta = NULL, *tb = NULL;
    /* a(t) = (2t, 4t(1-t)), b(t) = (2t, 0.5): max |4t(1-t) - 0.5| = 0.5 at t = 0, 1 */
    const double quad[6] = {0, 0, 1, 2, 2, 0}, line[4] = {0, 0.5, 2, 0.5};
    const double pts3[6] = {0, 0, 0, 1, 1, 1};
    /* P(u, v) = (u, v, uv) and the same lifted by 0.25 in z, degree (1, 2) */
    const double bil[12] = {0, 0, 0, 0, 1, 0, 1, 0, 0, 1, 1, 1};
    const double lift[18] = {0, 0, 0.25, 0, 0.5, 0.25, 0, 1, 0.25,
                             1, 0, 0.25, 1, 0.5, 0.75, 1, 1, 1.25};
    /* triangles (u, v) and the same shifted by 0.25 in x */
    const double tri[6] = {0, 0, 0, 1, 1, 0}, tri_s[6] = {0.25, 0, 0.25, 1, 1.25, 0};
    double d = -1.0;

    CHECK_OK(cagd_curve_new(quad, 3, 2, &a));
    CHECK_OK(cagd_curve_new(line, 2, 2, &b));
    CHECK_OK(cagd_curve_new(pts3, 2, 3, &c3));
    CHECK_OK(cagd_curve_distance(a, b, &d));
    CHECK_NEAR(d, 0.5, DIST_TOL);
    CHECK_OK(cagd_curve_distance(a, a, &d));
    CHECK(d == 0.0);
    d = -1.0;
    CHECK_STATUS(cagd_curve_distance(a, c3, &d), CAGD_ERR_DIMENSION_MISMATCH);
    CHECK(d == -1.0);
    CHECK_STATUS(cagd_curve_distance(NULL, b, &d), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_curve_distance(a, NULL, &d), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_curve_distance(a, b, NULL), CAGD_ERR_NULL_POINTER);

    CHECK_OK(cagd_tensorpatch_new(bil, 1, 1, 3, &pa));
    CHECK_OK(cagd_tensorpatch_new(lift, 1, 2, 3, &pb));
    CHECK_OK(cagd_tensorpatch_distance(pa, pb, &d));
    CHECK_NEAR(d, 0.25, DIST_TOL);
    CHECK_STATUS(cagd_tensorpatch_distance(pa, NULL, &d), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_tensorpatch_distance(pa, pb, NULL), CAGD_ERR_NULL_POINTER);

    CHECK_OK(cagd_tripatch_new(tri, 1, 2, &ta));
    CHECK_OK(cagd_tripatch_new(tri_s, 1, 2, &tb));
    CHECK_OK(cagd_tripatch_distance(ta, tb, &d));
    CHECK_NEAR(d, 0.25, DIST_TOL);
    CHECK_STATUS(cagd_tripatch_distance(NULL, tb, &d), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_tripatch_distance(ta, tb, NULL), CAGD_ERR_NULL_POINTER);
    rc = 0;
cleanup:
    cagd_curve_free(a);
    cagd_curve_free(b);
    cagd_curve_free(c3);
    cagd_tensorpatch_free(pa);
    cagd_tensorpatch_free(pb);
    cagd_tripatch_free(ta);
    cagd_tripatch_free(tb);
    return rc;
}
