/* Regressions found by the C ABI fuzz harness (fuzz/capi, issue 18): each was a silent
 * garbage result (NaN / inf with CAGD_OK) or a caught panic (CAGD_ERR_PANIC). */
#include <float.h>

#include "ctest.h"

/* Evaluating far outside [0, 1] overflows: CAGD_ERR_NON_FINITE, nothing written (was
 * CAGD_OK with inf / NaN in the buffer). */
int cagd_ctest_fuzz_eval_overflow_is_non_finite(void) {
    int rc = 1;
    CagdCurve *c = NULL;
    const double pts[3] = {1e300, -1e300, 1e300};
    double out[4] = {9.0, 9.0, 9.0, 9.0};
    const double ts[2] = {0.5, 1e10};
    size_t needed = 77;
    CHECK_OK(cagd_curve_new(pts, 3, 1, &c));
    CHECK_STATUS(cagd_curve_eval(c, 1e10, out, 4, &needed), CAGD_ERR_NON_FINITE);
    CHECK_MESSAGE_HAS("not finite");
    CHECK(needed == 77 && out[0] == 9.0);
    CHECK_STATUS(cagd_curve_eval_many(c, ts, 2, out, 4, &needed), CAGD_ERR_NON_FINITE);
    CHECK(needed == 77 && out[0] == 9.0 && out[1] == 9.0);
    /* inside the domain the same curve is fine */
    CHECK_OK(cagd_curve_eval(c, 0.5, out, 4, &needed));
    CHECK(needed == 1 && isfinite(out[0]));
    rc = 0;
cleanup:
    cagd_curve_free(c);
    return rc;
}

/* Two degree-16 curves: the substituted polynomial has degree 256, beyond the exact
 * binomials: CAGD_ERR_DEGREE_OUT_OF_RANGE (was CAGD_ERR_PANIC, "binomial(256, 0) beyond
 * the exact table"). */
int cagd_ctest_fuzz_intersect_degree_product_refused(void) {
    int rc = 1;
    CagdCurve *a = NULL, *b = NULL;
    double pa[17 * 2], pb[17 * 2];
    size_t needed = 0;
    for (int i = 0; i <= 16; ++i) {
        pa[2 * i] = i / 16.0;
        pa[2 * i + 1] = (i % 3) * 0.25;
        pb[2 * i] = (i % 2) * 0.5;
        pb[2 * i + 1] = i / 16.0;
    }
    CHECK_OK(cagd_curve_new(pa, 17, 2, &a));
    CHECK_OK(cagd_curve_new(pb, 17, 2, &b));
    CHECK_STATUS(cagd_curve_intersect(a, b, NULL, 0, &needed), CAGD_ERR_DEGREE_OUT_OF_RANGE);
    CHECK_MESSAGE_HAS("256");
    rc = 0;
cleanup:
    cagd_curve_free(a);
    cagd_curve_free(b);
    return rc;
}

/* Splitting a bicubic patch along a curve of degree 29 gives pieces of degree
 * 3 + 3 * 29 = 90 > 64: CAGD_ERR_DEGREE_OUT_OF_RANGE (was CAGD_ERR_PANIC in the binomial
 * table). Degree 20 (3 + 60 = 63) still works. */
int cagd_ctest_fuzz_split_curve_piece_degree_refused(void) {
    int rc = 1;
    CagdTensorPatch *p = NULL;
    CagdPatchPieceList *l = NULL;
    double pts[16 * 3];
    double coeffs[30];
    for (int i = 0; i < 16; ++i) {
        pts[3 * i] = (i / 4) / 3.0;
        pts[3 * i + 1] = (i % 4) / 3.0;
        pts[3 * i + 2] = 0.1 * i;
    }
    for (int i = 0; i < 30; ++i) coeffs[i] = 0.5;
    CHECK_OK(cagd_tensorpatch_new(pts, 3, 3, 3, &p));
    CHECK_STATUS(cagd_tensorpatch_split_curve(p, NULL, coeffs, 30, &l),
                 CAGD_ERR_DEGREE_OUT_OF_RANGE);
    CHECK(l == NULL);
    CHECK_OK(cagd_tensorpatch_split_curve(p, NULL, coeffs, 21, &l));
    rc = 0;
cleanup:
    cagd_patchpiecelist_free(l);
    cagd_tensorpatch_free(p);
    return rc;
}

/* Coordinates near DBL_MAX: a reduction either fails with a status or reports a finite
 * bound; cagd_report_bound never gives inf with CAGD_OK (it did). */
int cagd_ctest_fuzz_report_bound_never_infinite(void) {
    int rc = 1;
    CagdCurve *c = NULL, *r = NULL;
    CagdReport *rep = NULL;
    CagdReduceOptions o;
    const double pts[4 * 2] = {DBL_MAX, -DBL_MAX, -DBL_MAX, DBL_MAX,
                               DBL_MAX, DBL_MAX,  -DBL_MAX, -DBL_MAX};
    double bound = -1.0;
    CHECK_OK(cagd_curve_new(pts, 4, 2, &c));
    CHECK_OK(cagd_reduce_options_init(&o));
    o.target = 2;
    CagdStatus st = cagd_curve_reduce(c, &o, &r, &rep);
    if (st == CAGD_OK) {
        st = cagd_report_bound(rep, &bound);
        CHECK(st == CAGD_ERR_NOT_AVAILABLE || (st == CAGD_OK && isfinite(bound) && bound >= 0));
    } else {
        CHECK(st != CAGD_ERR_PANIC && r == NULL && rep == NULL);
    }
    rc = 0;
cleanup:
    cagd_report_free(rep);
    cagd_curve_free(r);
    cagd_curve_free(c);
    return rc;
}

/* A rational curve whose elevated Euclidean points overflow (w P = 4 DBL_MAX):
 * cagd_bezier_elevate fails with CAGD_ERR_NON_FINITE and writes no point (was CAGD_OK
 * with inf in `out`); cagd_curve_elevate refuses the same curve (it made a handle with
 * inf points, which only cagd_curve_points reported). */
int cagd_ctest_fuzz_bezier_elevate_overflow_is_non_finite(void) {
    int rc = 1;
    const double pts[2] = {DBL_MAX, DBL_MAX};
    const double w[2] = {4.0, 4.0};
    double out[4] = {9.0, 9.0, 9.0, 9.0}, wout[4] = {9.0, 9.0, 9.0, 9.0};
    size_t needed = 0;
    CHECK_STATUS(cagd_bezier_elevate(pts, 2, 1, w, 1, out, 4, &needed, wout, 4),
                 CAGD_ERR_NON_FINITE);
    CHECK_MESSAGE_HAS("not finite");
    CHECK(out[0] == 9.0 && out[1] == 9.0 && out[2] == 9.0 && wout[0] == 9.0);
    {
        CagdCurve *c = NULL, *e = NULL;
        CHECK_OK(cagd_curve_new_rational(pts, w, 2, 1, &c));
        CagdStatus st = cagd_curve_elevate(c, 1, &e);
        cagd_curve_free(c);
        CHECK(st == CAGD_ERR_NON_FINITE && e == NULL);
    }
    /* the same curve with moderate coordinates is fine */
    const double small[2] = {1.0, 2.0};
    CHECK_OK(cagd_bezier_elevate(small, 2, 1, w, 1, out, 4, &needed, wout, 4));
    CHECK(needed == 3 && isfinite(out[0]) && isfinite(out[1]) && isfinite(out[2]));
    rc = 0;
cleanup:
    return rc;
}

/* Coordinates at the f64 limit: the certified bound of cagd_bezier_reduce overflows. The
 * CagdBezierReport holds NaN there (no bound; cagd_report_bound answers
 * CAGD_ERR_NOT_AVAILABLE for the same reduction), never inf (was bound = inf with
 * CAGD_OK). */
int cagd_ctest_fuzz_bezier_report_bound_never_infinite(void) {
    int rc = 1;
    CagdReduceOptions o;
    CagdBezierReport rep;
    CagdCurve *c = NULL, *r = NULL;
    CagdReport *hr = NULL;
    double bound = -1.0;
    const double pts[4] = {1e306, -1e306, 1e306, -1e306};
    double out[3];
    size_t needed = 0;
    CHECK_OK(cagd_reduce_options_init(&o));
    o.target = 2;
    rep.struct_size = sizeof rep;
    CHECK_OK(cagd_bezier_reduce(pts, 4, 1, NULL, &o, out, 3, &needed, NULL, 0, &rep));
    CHECK(needed == 3 && isfinite(out[0]) && isfinite(out[1]) && isfinite(out[2]));
    CHECK(isnan(rep.bound) || (isfinite(rep.bound) && rep.bound >= 0.0));
    CHECK(isnan(rep.homogeneous_bound) ||
          (isfinite(rep.homogeneous_bound) && rep.homogeneous_bound >= 0.0));
    CHECK(isnan(rep.max_error) || isfinite(rep.max_error));
    /* the handle call agrees: no bound there either when the struct holds NaN */
    CHECK_OK(cagd_curve_new(pts, 4, 1, &c));
    CHECK_OK(cagd_curve_reduce(c, &o, &r, &hr));
    CagdStatus st = cagd_report_bound(hr, &bound);
    CHECK(isnan(rep.bound) ? st == CAGD_ERR_NOT_AVAILABLE : (st == CAGD_OK && bound == rep.bound));
    rc = 0;
cleanup:
    cagd_report_free(hr);
    cagd_curve_free(r);
    cagd_curve_free(c);
    return rc;
}

/* A batch whose reduced coordinates overflow (input at the f64 limit): the checked input is
 * finite, so the overflow is CAGD_ERR_NON_FINITE (was CAGD_ERR_PANIC, "internal error:
 * batch failed after validation"), with and without bounds. */
int cagd_ctest_fuzz_curve_reduce_batch_overflow_is_non_finite(void) {
    int rc = 1;
    CagdReduceOptions o;
    const double pts[2 * 4] = {DBL_MAX, -DBL_MAX, -DBL_MAX, -DBL_MAX,
                               1.0,     2.0,      3.0,      4.0};
    double out[2 * 3], bounds[2];
    size_t needed = 0;
    CHECK_OK(cagd_reduce_options_init(&o));
    o.target = 2;
    CHECK_STATUS(cagd_curve_reduce_batch(pts, 2, 3, 1, &o, out, 6, &needed),
                 CAGD_ERR_NON_FINITE);
    CHECK_MESSAGE_HAS("overflows");
    CHECK_STATUS(cagd_curve_reduce_batch_bounded(pts, 2, 3, 1, &o, out, 6, &needed, bounds),
                 CAGD_ERR_NON_FINITE);
    /* the second curve alone is fine, with a finite bound */
    CHECK_OK(cagd_curve_reduce_batch_bounded(pts + 4, 1, 3, 1, &o, out, 6, &needed, bounds));
    CHECK(needed == 3 && isfinite(bounds[0]) && bounds[0] >= 0.0);
    rc = 0;
cleanup:
    return rc;
}

/* A cubic with weights near 3e307: the span's extrapolation factor overflowed and came back
 * as inf with CAGD_OK; now CAGD_ERR_NON_FINITE and no handle. */
int cagd_ctest_fuzz_nurbs_span_extrapolation_overflow_refused(void) {
    int rc = 1;
    CagdCurve *c = NULL;
    CagdBSpline *s = NULL;
    const double pts[12] = {-0.81734078177096192, -0.69626782334772352, -0.1418372106881125,
                            -0.81734078177096203, -0.69626782334772364, -0.14183721068811253,
                            -0.81734078177096203, -0.69626782334772375, -0.1418372106881125,
                            -0.81734078177096192, -0.69626782334772364, -0.1418372106881125};
    const double w[4] = {2.9034141281968608e+307, 3.3749686795364603e+307,
                         3.8684986447012899e+307, 4.3548541185563846e+307};
    const double knots[6] = {0, 0.43506026258100694, 0.50245346866153107,
                             0.63790735483377092, 0.9754764859999433, 1.4307827005976057};
    double x = 9.0;
    CHECK_OK(cagd_curve_new_rational(pts, w, 4, 3, &c));
    CHECK_STATUS(cagd_bezier_to_nurbs_span(c, knots, &s, &x), CAGD_ERR_NON_FINITE);
    CHECK(s == NULL && x == 9.0);
    rc = 0;
cleanup:
    cagd_bspline_free(s);
    cagd_curve_free(c);
    return rc;
}

/* A (2, 1) patch with alternating coordinates near the largest double: the invariant
 * F_j = P_0j - 2 P_1j + P_2j overflowed and came back as -inf with CAGD_OK (long fuzz run);
 * now CAGD_ERR_NON_FINITE with only the sizes written. */
int cagd_ctest_fuzz_tensor_degeneracy_overflow_is_non_finite(void) {
    int rc = 1;
    CagdTensorPatch *p = NULL;
    const double pts[6] = {-1.5e308, -1.5e308, 1.5e308, 1.5e308, -1.5e308, -1.5e308};
    double f[2] = {9.0, 9.0}, g[3] = {9.0, 9.0, 9.0};
    size_t fn = 77, gn = 77;
    CHECK_OK(cagd_tensorpatch_new(pts, 2, 1, 1, &p));
    CHECK_STATUS(cagd_tensorpatch_degeneracy(p, f, 2, &fn, g, 3, &gn), CAGD_ERR_NON_FINITE);
    CHECK_MESSAGE_HAS("not finite");
    CHECK(fn == 2 && gn == 3 && f[0] == 9.0 && g[0] == 9.0);
    rc = 0;
cleanup:
    cagd_tensorpatch_free(p);
    return rc;
}

/* Subdividing or cutting a segment far outside [0, 1]: pieces whose points or weights
 * overflow are refused (were CAGD_OK handles holding inf / non-positive weights, which
 * only a later cagd_curve_points / cagd_curve_weights call reported, as NON_FINITE). */
int cagd_ctest_fuzz_subdivide_extrapolation_refused(void) {
    int rc = 1;
    CagdCurve *c = NULL, *q = NULL, *l = NULL, *r = NULL;
    const double pts[8] = {0.0, 0.0, 1.0, 3.0, 3.0, 4.0, 5.0, 1.0};
    const double h = 0.70710678118654752;
    const double qp[6] = {1.0, 0.0, 1.0, 1.0, 0.0, 1.0}, qw[3] = {1.0, h, 1.0};
    double out[8];
    size_t needed = 0;
    CHECK_OK(cagd_curve_new(pts, 4, 2, &c));
    CHECK_STATUS(cagd_curve_subdivide(c, 1e120, &l, &r), CAGD_ERR_NON_FINITE);
    CHECK(l == NULL && r == NULL);
    CHECK_STATUS(cagd_curve_segment(c, -1e120, 0.5, &l), CAGD_ERR_NON_FINITE);
    CHECK(l == NULL);
    CHECK_OK(cagd_curve_new_rational(qp, qw, 3, 2, &q));
    {
        CagdStatus st = cagd_curve_subdivide(q, -1e200, &l, &r);
        CHECK(st == CAGD_ERR_NON_POSITIVE_WEIGHT || st == CAGD_ERR_NON_FINITE);
        CHECK(l == NULL && r == NULL);
    }
    /* far but representable: finite pieces */
    CHECK_OK(cagd_curve_subdivide(c, 1e50, &l, &r));
    CHECK_OK(cagd_curve_points(l, out, 8, &needed));
    CHECK(needed == 8 && out[0] == 0.0 && out[1] == 0.0);
    rc = 0;
cleanup:
    cagd_curve_free(c);
    cagd_curve_free(q);
    cagd_curve_free(l);
    cagd_curve_free(r);
    return rc;
}

/* A uniform NURBS with a coordinate at DBL_MAX (C ABI fuzz session 0x533eda5fd3486d99):
 * reduced in a scaled frame, and with `measure` its sampled error measured there too (the
 * model-space measurement overflowed in the homogeneous points and the call returned
 * CAGD_ERR_NON_FINITE, which its doc does not list); the error is at most the bound. */
int cagd_ctest_fuzz_uniform_nurbs_near_dbl_max_measured(void) {
    int rc = 1;
    CagdBSpline *s = NULL, *q = NULL;
    CagdReport *rep = NULL;
    const double p[12] = {-1e16, -9.9998886718268301e-321, 3, 1e16, 1.0000000000000011,
                          1.7976931348623157e+308, 1e-08, 0, -9.9998886718268301e-321, 0, 3,
                          1e16};
    const double w[6] = {3.2407868174935386, 4.0352860783076947, 2.2778534221163467,
                         1.1665886321272612, 1.274978810947673, 0.60069200466841544};
    const double k[10] = {0, 0.5, 1, 1.5, 2, 2.5, 3, 3.5, 4, 4.5};
    double bound = -1.0, e = -1.0;
    int merge;
    CagdReduceOptions o;
    CHECK_OK(cagd_bspline_new_rational(3, k, 10, p, w, 6, 2, &s));
    for (merge = 0; merge < 2; ++merge) {
        CHECK_OK(cagd_reduce_options_init(&o));
        o.method = CAGD_METHOD_L2;
        o.target = 1;
        o.merge = merge;
        o.measure = true;
        CHECK_OK(cagd_bspline_reduce_uniform(s, &o, &q, &rep));
        CHECK_OK(cagd_report_bound(rep, &bound));
        CHECK_OK(cagd_report_max_error(rep, &e));
        CHECK(isfinite(bound) && e > 1e306 && e <= bound);
        cagd_bspline_free(q);
        cagd_report_free(rep);
        q = NULL;
        rep = NULL;
    }
    rc = 0;
cleanup:
    cagd_report_free(rep);
    cagd_bspline_free(q);
    cagd_bspline_free(s);
    return rc;
}
