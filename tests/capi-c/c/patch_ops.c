/* Patch operations: evaluation, elevation, subdivision, against closed forms.
 * Tensor: the bilinear net P00 = (0,0,0), P01 = (0,1,0), P10 = (1,0,0), P11 = (1,1,1) is
 * P(u, v) = (u, v, uv); elevated to degree (m, n) its points are (i/m, j/n, ij/(mn))
 * (the Bernstein coefficients of u are i/m, and of uv the products).
 * Triangle: the degree-n net T_ij = (i/n, j/n, ij/(n(n-1))) is T(u, v) = (u, v, uv)
 * (the Bernstein coefficients of u are i/n; of uv, ij/(n(n-1))). */
#include <stdint.h>

#include "ctest.h"

static const double BILINEAR[12] = {0, 0, 0, 0, 1, 0, 1, 0, 0, 1, 1, 1};

/* Fills the degree-n triangular net of (u, v, uv), i-major. */
static void tri_uv(size_t n, double *pts) {
    size_t i, j, o = 0;
    for (i = 0; i <= n; ++i) {
        for (j = 0; j <= n - i; ++j) {
            pts[o++] = (double)i / n;
            pts[o++] = (double)j / n;
            pts[o++] = (double)(i * j) / (n * (n - 1));
        }
    }
}

/* Convex combinations of values <= 1: a few ulp. */
#define TOL 1e-15

int cagd_ctest_tensorpatch_ops(void) {
    int rc = 1;
    CagdTensorPatch *p = NULL, *e = NULL, *l = NULL, *r = NULL, *b = NULL, *t = NULL;
    double q[3] = {0}, pts[36] = {0};
    size_t needed = 0, m = 0, n = 0, dim = 0, i, j;

    CHECK_OK(cagd_tensorpatch_new(BILINEAR, 1, 1, 3, &p));
    CHECK_STATUS(cagd_tensorpatch_eval(p, 0.3, 0.7, NULL, 0, &needed), CAGD_ERR_BUFFER_TOO_SMALL);
    CHECK(needed == 3);
    CHECK_OK(cagd_tensorpatch_eval(p, 0.3, 0.7, q, 3, &needed));
    CHECK_NEAR(q[0], 0.3, TOL);
    CHECK_NEAR(q[1], 0.7, TOL);
    CHECK_NEAR(q[2], 0.21, TOL);
    /* elevation by (1, 2): degree (2, 3), points (i/2, j/3, ij/6) */
    CHECK_OK(cagd_tensorpatch_elevate(p, 1, 2, &e));
    CHECK_OK(cagd_tensorpatch_shape(e, &m, &n, &dim));
    CHECK(m == 2 && n == 3 && dim == 3);
    CHECK_OK(cagd_tensorpatch_points(e, pts, 36, &needed));
    CHECK(needed == 36);
    for (i = 0; i <= 2; ++i) {
        for (j = 0; j <= 3; ++j) {
            const double *x = pts + (i * 4 + j) * 3;
            CHECK_NEAR(x[0], i / 2.0, TOL);
            CHECK_NEAR(x[1], j / 3.0, TOL);
            CHECK_NEAR(x[2], (double)(i * j) / 6.0, TOL);
        }
    }
    /* split at u = 0.25: first(u', v) = P(u'/4, v), second(u', v) = P(1/4 + 3u'/4, v) */
    CHECK_OK(cagd_tensorpatch_subdivide_u(e, 0.25, &l, &r));
    CHECK_OK(cagd_tensorpatch_eval(l, 0.5, 0.4, q, 3, &needed));
    CHECK_NEAR(q[0], 0.125, TOL);
    CHECK_NEAR(q[1], 0.4, TOL);
    CHECK_NEAR(q[2], 0.05, TOL);
    CHECK_OK(cagd_tensorpatch_eval(r, 0.5, 0.4, q, 3, &needed));
    CHECK_NEAR(q[0], 0.625, TOL);
    CHECK_NEAR(q[2], 0.25, TOL);
    /* split at v = 0.5: second(u, v') = P(u, 1/2 + v'/2) */
    CHECK_OK(cagd_tensorpatch_subdivide_v(p, 0.5, &b, &t));
    CHECK_OK(cagd_tensorpatch_eval(t, 0.8, 0.2, q, 3, &needed));
    CHECK_NEAR(q[0], 0.8, TOL);
    CHECK_NEAR(q[1], 0.6, TOL);
    CHECK_NEAR(q[2], 0.48, TOL);
    CHECK_OK(cagd_tensorpatch_eval(b, 0.8, 0.2, q, 3, &needed));
    CHECK_NEAR(q[1], 0.1, TOL);
    rc = 0;
cleanup:
    cagd_tensorpatch_free(t);
    cagd_tensorpatch_free(b);
    cagd_tensorpatch_free(r);
    cagd_tensorpatch_free(l);
    cagd_tensorpatch_free(e);
    cagd_tensorpatch_free(p);
    return rc;
}

int cagd_ctest_tripatch_ops(void) {
    int rc = 1;
    CagdTriPatch *p = NULL, *e = NULL, *pieces[4] = {NULL, NULL, NULL, NULL};
    double net[18], pts[45] = {0}, want[45], q[3] = {0};
    /* the maps of the four midpoint pieces: (u, v) = (cu + su u', cv + sv v') */
    const double cu[4] = {0, 0.5, 0, 0.5}, cv[4] = {0, 0, 0.5, 0.5};
    const double sg[4] = {0.5, 0.5, 0.5, -0.5};
    size_t needed = 0, n = 0, dim = 0, i, k;

    tri_uv(2, net);
    CHECK_OK(cagd_tripatch_new(net, 2, 3, &p));
    CHECK_OK(cagd_tripatch_eval(p, 0.2, 0.3, q, 3, &needed));
    CHECK(needed == 3);
    CHECK_NEAR(q[0], 0.2, TOL);
    CHECK_NEAR(q[1], 0.3, TOL);
    CHECK_NEAR(q[2], 0.06, TOL);
    /* elevation by 2: degree 4, net (i/4, j/4, ij/12) */
    CHECK_OK(cagd_tripatch_elevate(p, 2, &e));
    CHECK_OK(cagd_tripatch_shape(e, &n, &dim));
    CHECK(n == 4 && dim == 3);
    CHECK_OK(cagd_tripatch_points(e, pts, 45, &needed));
    CHECK(needed == 45); /* 15 points * 3 */
    tri_uv(4, want);
    for (k = 0; k < 45; ++k) CHECK_NEAR(pts[k], want[k], TOL);
    /* midpoint subdivision: piece l at (u', v') is T(cu + s u', cv + s v') */
    CHECK_OK(cagd_tripatch_subdivide_midpoint(p, pieces));
    for (i = 0; i < 4; ++i) {
        const double up = 0.25, vp = 0.6;
        double u = cu[i] + sg[i] * up, v = cv[i] + sg[i] * vp;
        CHECK_OK(cagd_tripatch_shape(pieces[i], &n, &dim));
        CHECK(n == 2);
        CHECK_OK(cagd_tripatch_eval(pieces[i], up, vp, q, 3, &needed));
        CHECK_NEAR(q[0], u, TOL);
        CHECK_NEAR(q[1], v, TOL);
        CHECK_NEAR(q[2], u * v, TOL);
    }
    rc = 0;
cleanup:
    for (i = 0; i < 4; ++i) cagd_tripatch_free(pieces[i]);
    cagd_tripatch_free(e);
    cagd_tripatch_free(p);
    return rc;
}

int cagd_ctest_patch_ops_bad_input(void) {
    int rc = 1;
    CagdTensorPatch *p = NULL, *x = NULL, *y = NULL;
    CagdTriPatch *t = NULL, *tx = NULL, *pieces[4] = {NULL, NULL, NULL, NULL};
    double q[3] = {-7.0, -7.0, -7.0}, net[18];
    size_t needed = 0, i;

    tri_uv(2, net);
    CHECK_OK(cagd_tensorpatch_new(BILINEAR, 1, 1, 3, &p));
    CHECK_OK(cagd_tripatch_new(net, 2, 3, &t));
    /* tensor eval */
    CHECK_STATUS(cagd_tensorpatch_eval(NULL, 0.5, 0.5, q, 3, &needed), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_tensorpatch_eval(p, 0.5, 0.5, NULL, 3, &needed), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_tensorpatch_eval(p, 0.5, 0.5, q, 3, NULL), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_tensorpatch_eval(p, NAN, 0.5, q, 3, &needed), CAGD_ERR_INVALID_ARGUMENT);
    CHECK_STATUS(cagd_tensorpatch_eval(p, 0.5, -INFINITY, q, 3, &needed),
                 CAGD_ERR_INVALID_ARGUMENT);
    CHECK_STATUS(cagd_tensorpatch_eval(p, 0.5, 0.5, q, 2, &needed), CAGD_ERR_BUFFER_TOO_SMALL);
    CHECK(needed == 3 && q[0] == -7.0);
    /* tensor elevate */
    CHECK_STATUS(cagd_tensorpatch_elevate(NULL, 1, 1, &x), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_tensorpatch_elevate(p, 1, 1, NULL), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_tensorpatch_elevate(p, 64, 0, &x), CAGD_ERR_DEGREE_OUT_OF_RANGE);
    CHECK_STATUS(cagd_tensorpatch_elevate(p, 0, SIZE_MAX, &x), CAGD_ERR_DEGREE_OUT_OF_RANGE);
    /* tensor subdivision */
    CHECK_STATUS(cagd_tensorpatch_subdivide_u(NULL, 0.5, &x, &y), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_tensorpatch_subdivide_u(p, 0.5, NULL, &y), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_tensorpatch_subdivide_u(p, 0.5, &x, NULL), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_tensorpatch_subdivide_u(p, 0.5, &x, &x), CAGD_ERR_INVALID_ARGUMENT);
    CHECK_STATUS(cagd_tensorpatch_subdivide_u(p, 1.5, &x, &y), CAGD_ERR_INVALID_ARGUMENT);
    CHECK_STATUS(cagd_tensorpatch_subdivide_u(p, NAN, &x, &y), CAGD_ERR_INVALID_ARGUMENT);
    CHECK_STATUS(cagd_tensorpatch_subdivide_v(NULL, 0.5, &x, &y), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_tensorpatch_subdivide_v(p, 0.5, NULL, &y), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_tensorpatch_subdivide_v(p, 0.5, &x, NULL), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_tensorpatch_subdivide_v(p, -0.1, &x, &y), CAGD_ERR_INVALID_ARGUMENT);
    CHECK(x == NULL && y == NULL);
    /* triangle */
    CHECK_STATUS(cagd_tripatch_eval(NULL, 0.2, 0.2, q, 3, &needed), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_tripatch_eval(t, 0.2, 0.2, NULL, 3, &needed), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_tripatch_eval(t, 0.2, 0.2, q, 3, NULL), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_tripatch_eval(t, 0.2, NAN, q, 3, &needed), CAGD_ERR_INVALID_ARGUMENT);
    CHECK_STATUS(cagd_tripatch_eval(t, 0.2, 0.2, NULL, 0, &needed), CAGD_ERR_BUFFER_TOO_SMALL);
    CHECK(needed == 3 && q[0] == -7.0);
    CHECK_STATUS(cagd_tripatch_elevate(NULL, 1, &tx), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_tripatch_elevate(t, 1, NULL), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_tripatch_elevate(t, 63, &tx), CAGD_ERR_DEGREE_OUT_OF_RANGE);
    CHECK_STATUS(cagd_tripatch_elevate(t, SIZE_MAX, &tx), CAGD_ERR_DEGREE_OUT_OF_RANGE);
    CHECK(tx == NULL);
    CHECK_STATUS(cagd_tripatch_subdivide_midpoint(NULL, pieces), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_tripatch_subdivide_midpoint(t, NULL), CAGD_ERR_NULL_POINTER);
    for (i = 0; i < 4; ++i) CHECK(pieces[i] == NULL);
    rc = 0;
cleanup:
    for (i = 0; i < 4; ++i) cagd_tripatch_free(pieces[i]);
    cagd_tripatch_free(tx);
    cagd_tripatch_free(t);
    cagd_tensorpatch_free(y);
    cagd_tensorpatch_free(x);
    cagd_tensorpatch_free(p);
    return rc;
}
