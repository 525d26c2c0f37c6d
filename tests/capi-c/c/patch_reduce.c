/* Patch reduction: new -> reduce -> read back -> free, against the spec vectors tensor-1
 * and tri-1 (spec rule, tol 1e-12) and closed forms (elevated patches come back), and the
 * reductions to a tolerance (every piece within the tolerance, pieces tile the domain). */
#include <stdint.h>

#include "ctest.h"

/* tensor-1: P[i][j], m = 2 (i, along u), n = 3 (j, along v), 3D */
static const double T1_P[36] = {0, 0, 0, 1, 0, 1, 2, 0, 0, 3, 0, 2, 0, 1, 2, 1, 1, 3,
                                2, 1, 1, 3, 1, 0, 0, 2, 0, 1, 2, -1, 2, 2, 4, 3, 2, 1};
/* tensor-1: expected Q (degree (1, 2)): z = 127/120, 17/24, 133/120, 13/120, 59/24, 127/120 */
static const double T1_Q[18] = {0.0, 0.0, 1.0583333333333333, 1.5, 0.0, 0.7083333333333334,
                                3.0, 0.0, 1.1083333333333334, 0.0, 2.0, 0.10833333333333334,
                                1.5, 2.0, 2.4583333333333335, 3.0, 2.0, 1.0583333333333333};
static const double T1_BOUND = 1.8416666666666666;

/* tri-1: T i-major, n = 3, 3D */
static const double TRI1_T[30] = {0, 0, -3, 0, 1, 2, 0, 2, 0, 0, 3, -2, 1, 0, 0,
                                  1, 1, -2, 1, 2, 3, 2, 0, 3, 2, 1, 1, 3, 0, -1};
/* tri-1: expected Q (degree 2): z = -12/5, 11/10, -7/5, 8/5, 21/10, -2/5 */
static const double TRI1_Q[18] = {0.0, 0.0, -2.4, 0.0, 1.5, 1.1, 0.0, 3.0, -1.4,
                                  1.5, 0.0, 1.6, 1.5, 1.5, 2.1, 3.0, 0.0, -0.4};

/* The spec rule: max |got - expected| <= tol * max(1, max |expected|). */
static int spec_close(const double *got, const double *expected, size_t n, double tol) {
    double scale = 1.0, worst = 0.0;
    size_t i;
    for (i = 0; i < n; ++i) {
        if (fabs(expected[i]) > scale) scale = fabs(expected[i]);
        if (!(fabs(got[i] - expected[i]) <= worst)) worst = fabs(got[i] - expected[i]);
    }
    if (!(worst <= tol * scale)) {
        fprintf(stderr, "deviation %.3g exceeds %.3g\n", worst, tol * scale);
        return 0;
    }
    return 1;
}

int cagd_ctest_tensorpatch_reduce_spec(void) {
    int rc = 1;
    CagdTensorPatch *p = NULL, *q = NULL;
    CagdReport *rep = NULL;
    CagdReduceOptions o;
    double out[18] = {0}, bound = -1, measured = -1;
    size_t needed = 0, deg[4] = {0}, pieces = 0, m = 0, n = 0, dim = 0;
    int32_t pm = -1;

    CHECK_OK(cagd_tensorpatch_new(T1_P, 2, 3, 3, &p));
    CHECK_OK(cagd_reduce_options_init(&o));
    o.patch_method = CAGD_PATCH_PERTURB;
    o.target = 1;
    o.target_v = 2;
    o.measure = true;
    CHECK_OK(cagd_tensorpatch_reduce(p, &o, &q, &rep));
    CHECK_OK(cagd_tensorpatch_shape(q, &m, &n, &dim));
    CHECK(m == 1 && n == 2 && dim == 3);
    CHECK_OK(cagd_tensorpatch_points(q, out, 18, &needed));
    CHECK(needed == 18 && spec_close(out, T1_Q, 18, 1e-12));
    CHECK_OK(cagd_report_patch(rep, &pm, deg, &pieces));
    CHECK(pm == CAGD_PATCH_PERTURB && deg[0] == 2 && deg[1] == 3 && deg[2] == 1 && deg[3] == 2);
    CHECK(pieces == 1);
    CHECK_OK(cagd_report_bound(rep, &bound));
    CHECK_OK(cagd_report_max_error(rep, &measured));
    /* the bound is the smaller of the spec's and the convex-hull one */
    CHECK(measured <= bound && bound <= T1_BOUND * (1 + 1e-12));
    rc = 0;
cleanup:
    cagd_report_free(rep);
    cagd_tensorpatch_free(q);
    cagd_tensorpatch_free(p);
    return rc;
}

int cagd_ctest_tripatch_reduce_spec(void) {
    int rc = 1;
    CagdTriPatch *t = NULL, *q = NULL;
    CagdReport *rep = NULL;
    CagdReduceOptions o;
    double out[18] = {0}, bound = -1;
    size_t needed = 0, deg[4] = {0}, pieces = 0, n = 0, dim = 0;
    int32_t pm = -1;

    CHECK_OK(cagd_tripatch_new(TRI1_T, 3, 3, &t));
    CHECK_OK(cagd_reduce_options_init(&o));
    o.patch_method = CAGD_PATCH_PERTURB;
    o.target = 2;
    CHECK_OK(cagd_tripatch_reduce(t, &o, &q, &rep));
    CHECK_OK(cagd_tripatch_shape(q, &n, &dim));
    CHECK(n == 2 && dim == 3);
    CHECK_OK(cagd_tripatch_points(q, out, 18, &needed));
    CHECK(needed == 18 && spec_close(out, TRI1_Q, 18, 1e-12));
    CHECK_OK(cagd_report_patch(rep, &pm, deg, &pieces));
    CHECK(pm == CAGD_PATCH_PERTURB && deg[0] == 3 && deg[2] == 2 && pieces == 1);
    CHECK_OK(cagd_report_bound(rep, &bound));
    CHECK(bound > 0.0 && isfinite(bound));
    CHECK_STATUS(cagd_report_max_error(rep, &bound), CAGD_ERR_NOT_AVAILABLE);
    rc = 0;
cleanup:
    cagd_report_free(rep);
    cagd_tripatch_free(q);
    cagd_tripatch_free(t);
    return rc;
}

/* Elevated patches come back exactly (up to the rounding of the operators). */
int cagd_ctest_patch_reduce_roundtrip(void) {
    int rc = 1;
    CagdTensorPatch *p = NULL, *e = NULL, *q = NULL;
    CagdTriPatch *t = NULL, *te = NULL, *tq = NULL;
    CagdReport *rep = NULL, *trep = NULL;
    CagdReduceOptions o;
    /* P(u, v) = (u, v, uv): bilinear; the degree-2 net of (u, v, uv) on the triangle */
    const double bilinear[12] = {0, 0, 0, 0, 1, 0, 1, 0, 0, 1, 1, 1};
    const double tri2[18] = {0, 0, 0, 0, 0.5, 0, 0, 1, 0, 0.5, 0, 0, 0.5, 0.5, 0.5, 1, 0, 0};
    double out[18] = {0}, bound = -1;
    size_t needed = 0, k;

    CHECK_OK(cagd_reduce_options_init(&o));
    /* tensor: (3, 2) -> (1, 1) column by column and row by row, L2 with ends */
    CHECK_OK(cagd_tensorpatch_new(bilinear, 1, 1, 3, &p));
    CHECK_OK(cagd_tensorpatch_elevate(p, 2, 1, &e));
    o.patch_method = CAGD_PATCH_BY_CURVES;
    o.method = CAGD_METHOD_L2;
    o.target = 1;
    o.target_v = 1;
    CHECK_OK(cagd_tensorpatch_reduce(e, &o, &q, &rep));
    CHECK_OK(cagd_tensorpatch_points(q, out, 12, &needed));
    CHECK(needed == 12);
    /* operators rounded once applied to data of size 1: 1e-14 */
    for (k = 0; k < 12; ++k) CHECK_NEAR(out[k], bilinear[k], 1e-14);
    CHECK_OK(cagd_report_bound(rep, &bound));
    CHECK(bound < 1e-13);
    /* triangle: degree 4 -> 2 by L2 with the boundary curves reduced by L2 (ends kept) */
    CHECK_OK(cagd_tripatch_new(tri2, 2, 3, &t));
    CHECK_OK(cagd_tripatch_elevate(t, 2, &te));
    o.patch_method = CAGD_PATCH_L2;
    o.constraint = CAGD_CONSTRAINT_BOUNDARY;
    o.target = 2;
    CHECK_OK(cagd_tripatch_reduce(te, &o, &tq, &trep));
    CHECK_OK(cagd_tripatch_points(tq, out, 18, &needed));
    CHECK(needed == 18);
    for (k = 0; k < 18; ++k) CHECK_NEAR(out[k], tri2[k], 1e-14);
    rc = 0;
cleanup:
    cagd_report_free(trep);
    cagd_report_free(rep);
    cagd_tripatch_free(tq);
    cagd_tripatch_free(te);
    cagd_tripatch_free(t);
    cagd_tensorpatch_free(q);
    cagd_tensorpatch_free(e);
    cagd_tensorpatch_free(p);
    return rc;
}

int cagd_ctest_patch_reduce_to_tolerance(void) {
    int rc = 1;
    CagdTensorPatch *p = NULL, *piece = NULL;
    CagdTriPatch *t = NULL, *tpiece = NULL;
    CagdTensorPatchList *list = NULL;
    CagdTriPatchList *tlist = NULL;
    CagdReport *rep = NULL, *trep = NULL;
    CagdReduceOptions o;
    double dom[4], ver[6], bound = -1, worst = -1, area = 0, x[3], y[3];
    size_t count = 0, deg[4], pieces = 0, i, k;
    int32_t pm = -1;

    CHECK_OK(cagd_reduce_options_init(&o));
    o.tolerance = 0.05;
    /* tensor-1's patch to degree (1, 2) by curves (L2, ends kept: C0 pieces) */
    CHECK_OK(cagd_tensorpatch_new(T1_P, 2, 3, 3, &p));
    o.patch_method = CAGD_PATCH_BY_CURVES;
    o.target = 1;
    o.target_v = 2;
    CHECK_OK(cagd_tensorpatch_reduce_to_tolerance(p, &o, &list, &rep));
    CHECK_OK(cagd_tensorpatchlist_count(list, &count));
    CHECK_OK(cagd_report_patch(rep, &pm, deg, &pieces));
    CHECK(pieces == count && count > 1 && pm == CAGD_PATCH_BY_CURVES);
    CHECK_OK(cagd_report_bound(rep, &worst));
    CHECK(worst <= 0.05);
    for (i = 0; i < count; ++i) {
        CHECK_OK(cagd_tensorpatchlist_get(list, i, &piece, dom, &bound));
        CHECK(bound <= worst && dom[0] < dom[1] && dom[2] < dom[3]);
        area += (dom[1] - dom[0]) * (dom[3] - dom[2]);
        /* the piece at its centre is within its bound of the patch there */
        CHECK_OK(cagd_tensorpatch_eval(piece, 0.5, 0.5, x, 3, &k));
        CHECK_OK(cagd_tensorpatch_eval(p, 0.5 * (dom[0] + dom[1]), 0.5 * (dom[2] + dom[3]), y,
                                       3, &k));
        CHECK(sqrt((x[0] - y[0]) * (x[0] - y[0]) + (x[1] - y[1]) * (x[1] - y[1]) +
                   (x[2] - y[2]) * (x[2] - y[2])) <= bound);
        cagd_tensorpatch_free(piece);
        piece = NULL;
    }
    CHECK_NEAR(area, 1.0, 1e-15); /* dyadic sub-domains tile the square exactly */
    /* tri-1's patch to degree 2 by perturbation */
    CHECK_OK(cagd_tripatch_new(TRI1_T, 3, 3, &t));
    o.patch_method = CAGD_PATCH_PERTURB;
    o.target = 2;
    CHECK_OK(cagd_tripatch_reduce_to_tolerance(t, &o, &tlist, &trep));
    CHECK_OK(cagd_tripatchlist_count(tlist, &count));
    CHECK(count > 1);
    CHECK_OK(cagd_report_bound(trep, &worst));
    CHECK(worst <= 0.05);
    area = 0;
    for (i = 0; i < count; ++i) {
        double cu, cv;
        CHECK_OK(cagd_tripatchlist_get(tlist, i, &tpiece, ver, &bound));
        CHECK(bound <= worst);
        /* |det(A - C, B - C)| / 2 */
        area += 0.5 * fabs((ver[0] - ver[4]) * (ver[3] - ver[5]) -
                           (ver[1] - ver[5]) * (ver[2] - ver[4]));
        /* centroid: local (1/3, 1/3) is C + (A - C)/3 + (B - C)/3 */
        cu = (ver[0] + ver[2] + ver[4]) / 3.0;
        cv = (ver[1] + ver[3] + ver[5]) / 3.0;
        CHECK_OK(cagd_tripatch_eval(tpiece, 1.0 / 3, 1.0 / 3, x, 3, &k));
        CHECK_OK(cagd_tripatch_eval(t, cu, cv, y, 3, &k));
        CHECK(sqrt((x[0] - y[0]) * (x[0] - y[0]) + (x[1] - y[1]) * (x[1] - y[1]) +
                   (x[2] - y[2]) * (x[2] - y[2])) <= bound + 1e-15);
        cagd_tripatch_free(tpiece);
        tpiece = NULL;
    }
    CHECK_NEAR(area, 0.5, 1e-15);
    rc = 0;
cleanup:
    cagd_tripatch_free(tpiece);
    cagd_tensorpatch_free(piece);
    cagd_report_free(trep);
    cagd_report_free(rep);
    cagd_tripatchlist_free(tlist);
    cagd_tensorpatchlist_free(list);
    cagd_tripatch_free(t);
    cagd_tensorpatch_free(p);
    return rc;
}

int cagd_ctest_patch_reduce_bad_input(void) {
    int rc = 1;
    CagdTensorPatch *p = NULL, *q = NULL, *piece = NULL;
    CagdTriPatch *t = NULL, *tq = NULL, *tpiece = NULL;
    CagdTensorPatchList *list = NULL;
    CagdTriPatchList *tlist = NULL;
    CagdReport *rep = NULL, *crep = NULL;
    CagdCurve *c = NULL, *cq = NULL;
    CagdReduceOptions o;
    const double line[4] = {0, 0, 1, 1};
    double d[6], b = 0;
    size_t deg[4], n = 0;
    int32_t pm = 0;

    CHECK_OK(cagd_tensorpatch_new(T1_P, 2, 3, 3, &p));
    CHECK_OK(cagd_tripatch_new(TRI1_T, 3, 3, &t));
    CHECK_OK(cagd_reduce_options_init(&o));
    o.target = 1;
    o.target_v = 2;
    /* NULLs */
    CHECK_STATUS(cagd_tensorpatch_reduce(NULL, &o, &q, &rep), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_tensorpatch_reduce(p, NULL, &q, &rep), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_tensorpatch_reduce(p, &o, NULL, &rep), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_tensorpatch_reduce(p, &o, &q, NULL), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_tensorpatch_reduce(p, &o, (CagdTensorPatch **)(void *)&rep, &rep),
                 CAGD_ERR_INVALID_ARGUMENT);
    CHECK_STATUS(cagd_tripatch_reduce(NULL, &o, &tq, &rep), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_tripatch_reduce(t, NULL, &tq, &rep), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_tripatch_reduce(t, &o, NULL, &rep), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_tripatch_reduce(t, &o, &tq, NULL), CAGD_ERR_NULL_POINTER);
    o.tolerance = 0.1;
    CHECK_STATUS(cagd_tensorpatch_reduce_to_tolerance(NULL, &o, &list, &rep),
                 CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_tensorpatch_reduce_to_tolerance(p, NULL, &list, &rep),
                 CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_tensorpatch_reduce_to_tolerance(p, &o, NULL, &rep), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_tensorpatch_reduce_to_tolerance(p, &o, &list, NULL), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_tripatch_reduce_to_tolerance(NULL, &o, &tlist, &rep), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_tripatch_reduce_to_tolerance(t, NULL, &tlist, &rep), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_tripatch_reduce_to_tolerance(t, &o, NULL, &rep), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_tripatch_reduce_to_tolerance(t, &o, &tlist, NULL), CAGD_ERR_NULL_POINTER);
    /* invalid codes and combinations */
    o.struct_size = 8;
    CHECK_STATUS(cagd_tensorpatch_reduce(p, &o, &q, &rep), CAGD_ERR_INVALID_ARGUMENT);
    CHECK_STATUS(cagd_tripatch_reduce(t, &o, &tq, &rep), CAGD_ERR_INVALID_ARGUMENT);
    o.struct_size = sizeof o;
    o.patch_method = 3;
    CHECK_STATUS(cagd_tensorpatch_reduce(p, &o, &q, &rep), CAGD_ERR_INVALID_ARGUMENT);
    o.patch_method = CAGD_PATCH_L2; /* triangles only */
    CHECK_STATUS(cagd_tensorpatch_reduce(p, &o, &q, &rep), CAGD_ERR_INVALID_ARGUMENT);
    o.patch_method = CAGD_PATCH_BY_CURVES; /* tensor only */
    CHECK_STATUS(cagd_tripatch_reduce(t, &o, &tq, &rep), CAGD_ERR_INVALID_ARGUMENT);
    o.constraint = CAGD_CONSTRAINT_CORNERS; /* by curves takes no constraint */
    CHECK_STATUS(cagd_tensorpatch_reduce(p, &o, &q, &rep), CAGD_ERR_INVALID_ARGUMENT);
    o.patch_method = CAGD_PATCH_PERTURB; /* triangle perturbation takes none either */
    o.target = 2;
    CHECK_STATUS(cagd_tripatch_reduce(t, &o, &tq, &rep), CAGD_ERR_INVALID_ARGUMENT);
    o.constraint = 7;
    CHECK_STATUS(cagd_tensorpatch_reduce(p, &o, &q, &rep), CAGD_ERR_INVALID_ARGUMENT);
    o.constraint = CAGD_CONSTRAINT_NONE;
    /* degree pairs */
    o.target = 1;
    o.target_v = 1; /* perturbation is (m - 1, n - 1) only */
    CHECK_STATUS(cagd_tensorpatch_reduce(p, &o, &q, &rep), CAGD_ERR_BAD_DEGREE_PAIR);
    o.target = 3;
    CHECK_STATUS(cagd_tripatch_reduce(t, &o, &tq, &rep), CAGD_ERR_BAD_DEGREE_PAIR);
    o.patch_method = CAGD_PATCH_L2;
    o.constraint = CAGD_CONSTRAINT_CORNERS;
    o.target = 0;
    CHECK_STATUS(cagd_tripatch_reduce(t, &o, &tq, &rep), CAGD_ERR_TOO_MANY_CONSTRAINTS);
    /* tolerance */
    o.constraint = CAGD_CONSTRAINT_NONE;
    o.target = 2;
    o.tolerance = 0.0;
    CHECK_STATUS(cagd_tripatch_reduce_to_tolerance(t, &o, &tlist, &rep), CAGD_ERR_INVALID_ARGUMENT);
    o.tolerance = NAN;
    o.patch_method = CAGD_PATCH_PERTURB;
    o.target = 1;
    o.target_v = 2;
    CHECK_STATUS(cagd_tensorpatch_reduce_to_tolerance(p, &o, &list, &rep),
                 CAGD_ERR_INVALID_ARGUMENT);
    CHECK(q == NULL && tq == NULL && list == NULL && tlist == NULL && rep == NULL);
    /* the list accessors */
    o.tolerance = 0.5;
    CHECK_OK(cagd_tensorpatch_reduce_to_tolerance(p, &o, &list, &rep));
    CHECK_STATUS(cagd_tensorpatchlist_count(NULL, &n), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_tensorpatchlist_count(list, NULL), CAGD_ERR_NULL_POINTER);
    CHECK_OK(cagd_tensorpatchlist_count(list, &n));
    CHECK_STATUS(cagd_tensorpatchlist_get(NULL, 0, &piece, d, &b), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_tensorpatchlist_get(list, 0, NULL, d, &b), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_tensorpatchlist_get(list, 0, &piece, NULL, &b), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_tensorpatchlist_get(list, 0, &piece, d, NULL), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_tensorpatchlist_get(list, n, &piece, d, &b), CAGD_ERR_INVALID_ARGUMENT);
    o.target = 2;
    CHECK_OK(cagd_tripatch_reduce_to_tolerance(t, &o, &tlist, &crep));
    CHECK_STATUS(cagd_tripatchlist_count(NULL, &n), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_tripatchlist_count(tlist, NULL), CAGD_ERR_NULL_POINTER);
    CHECK_OK(cagd_tripatchlist_count(tlist, &n));
    CHECK_STATUS(cagd_tripatchlist_get(NULL, 0, &tpiece, d, &b), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_tripatchlist_get(tlist, 0, NULL, d, &b), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_tripatchlist_get(tlist, 0, &tpiece, NULL, &b), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_tripatchlist_get(tlist, 0, &tpiece, d, NULL), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_tripatchlist_get(tlist, SIZE_MAX, &tpiece, d, &b),
                 CAGD_ERR_INVALID_ARGUMENT);
    CHECK(piece == NULL && tpiece == NULL);
    /* the patch report accessor */
    CHECK_STATUS(cagd_report_patch(NULL, &pm, deg, &n), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_report_patch(rep, NULL, deg, &n), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_report_patch(rep, &pm, NULL, &n), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_report_patch(rep, &pm, deg, NULL), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_report_space(rep, &pm, &b), CAGD_ERR_NOT_AVAILABLE);
    cagd_report_free(crep);
    crep = NULL;
    CHECK_OK(cagd_curve_new(line, 2, 2, &c));
    CHECK_OK(cagd_curve_elevate(c, 2, &cq));
    cagd_curve_free(c);
    c = NULL;
    o.method = CAGD_METHOD_L2;
    o.target = 1;
    CHECK_OK(cagd_curve_reduce(cq, &o, &c, &crep));
    CHECK_STATUS(cagd_report_patch(crep, &pm, deg, &n), CAGD_ERR_NOT_AVAILABLE);
    cagd_tensorpatchlist_free(NULL);
    cagd_tripatchlist_free(NULL);
    rc = 0;
cleanup:
    cagd_curve_free(cq);
    cagd_curve_free(c);
    cagd_report_free(crep);
    cagd_report_free(rep);
    cagd_tripatchlist_free(tlist);
    cagd_tensorpatchlist_free(list);
    cagd_tripatch_free(tpiece);
    cagd_tensorpatch_free(piece);
    cagd_tripatch_free(tq);
    cagd_tensorpatch_free(q);
    cagd_tripatch_free(t);
    cagd_tensorpatch_free(p);
    return rc;
}
