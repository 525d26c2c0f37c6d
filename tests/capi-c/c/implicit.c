/* CagdImplicit and curve intersection (SPEC-convert §15.8–15.9): the spec vectors
 * impl-n2-conic-weighted (f = 4 - 4x^2 - 4y^2, F(0,0) = [[2,2],[2,4]]) and
 * impl-15.9.1-A-n3, classification, inversion, intersection with size queries, base
 * points, and bad input (NULL for every pointer, non-planar curves, short buffers). */
#include <stdint.h>

#include "ctest.h"

static const double CONIC[6] = {1.0, 0.0, 1.0, 1.0, 0.0, 1.0};
static const double CONIC_W[3] = {1.0, 1.0, 2.0};

int cagd_ctest_implicit_conic_spec(void) {
    int rc = 1;
    CagdCurve *c = NULL;
    CagdImplicit *imp = NULL;
    double coefs[6] = {0}, bez[12] = {0}, value = 0.0, dist = 0.0, t = -1.0;
    size_t needed = 0, degree = 0, base = 7, power = 0;
    int32_t sign = 7;

    CHECK_OK(cagd_curve_new_rational(CONIC, CONIC_W, 3, 2, &c));
    CHECK_OK(cagd_curve_implicitize(c, 0, &imp));
    CHECK_OK(cagd_implicit_report(imp, &degree, &base, &power));
    CHECK(degree == 2 && base == 0 && power == 1);
    /* Size query, then the coefficients, i-major: c00 c01 c02 c10 c11 c20. */
    CHECK_STATUS(cagd_implicit_coefficients(imp, NULL, 0, &needed), CAGD_ERR_BUFFER_TOO_SMALL);
    CHECK(needed == 6);
    CHECK_STATUS(cagd_implicit_coefficients(imp, coefs, 5, &needed), CAGD_ERR_BUFFER_TOO_SMALL);
    CHECK(coefs[0] == 0.0); /* untouched */
    CHECK_OK(cagd_implicit_coefficients(imp, coefs, 6, &needed));
    CHECK(coefs[0] == 4.0 && coefs[1] == 0.0 && coefs[2] == -4.0);
    CHECK(coefs[3] == 0.0 && coefs[4] == 0.0 && coefs[5] == -4.0);
    /* F(0,0) = C0 = [[2,2],[2,4]] (third block). */
    CHECK_OK(cagd_implicit_bezout(imp, bez, 12, &needed));
    CHECK(needed == 12);
    CHECK(bez[8] == 2.0 && bez[9] == 2.0 && bez[10] == 2.0 && bez[11] == 4.0);
    /* Classification: inside (f > 0), outside, algebraic distance at (0, 0.5) = 3/4. */
    CHECK_OK(cagd_implicit_classify(imp, 0.0, 0.5, &value, &sign, &dist));
    CHECK_NEAR(value, 3.0, 1e-14);
    CHECK(sign == 1);
    CHECK_NEAR(dist, 0.75, 1e-14);
    CHECK_OK(cagd_implicit_classify(imp, 2.0, 0.0, &value, &sign, &dist));
    CHECK(sign == -1);
    /* Inversion: (0.6, 0.8) is on the circle at t = 0.5 (impl-n2-conic-weighted samples). */
    CHECK_OK(cagd_implicit_invert(imp, 0.6, 0.8, &t));
    CHECK_NEAR(t, 0.5, 1e-12);
    t = -1.0;
    CHECK_STATUS(cagd_implicit_invert(imp, 2.0, 2.0, &t), CAGD_ERR_NOT_ON_CURVE);
    CHECK(t == -1.0);
    CHECK_STATUS(cagd_implicit_invert(imp, NAN, 0.0, &t), CAGD_ERR_INVALID_ARGUMENT);
    rc = 0;
cleanup:
    cagd_implicit_free(imp);
    cagd_curve_free(c);
    return rc;
}

int cagd_ctest_implicit_subdivision_matrix(void) {
    int rc = 1;
    double a[9] = {0};
    size_t needed = 0;
    CHECK_STATUS(cagd_implicit_subdivision_matrix(3, 1.0 / 3.0, NULL, 0, &needed),
                 CAGD_ERR_BUFFER_TOO_SMALL);
    CHECK(needed == 9);
    CHECK_OK(cagd_implicit_subdivision_matrix(3, 1.0 / 3.0, a, 9, &needed));
    /* impl-15.9.1-A-n3: [[1,0,0],[4/3,1/3,0],[4/9,2/9,1/9]] */
    CHECK_NEAR(a[0], 1.0, 1e-15);
    CHECK_NEAR(a[3], 4.0 / 3.0, 1e-15);
    CHECK_NEAR(a[4], 1.0 / 3.0, 1e-15);
    CHECK_NEAR(a[6], 4.0 / 9.0, 1e-15);
    CHECK_NEAR(a[7], 2.0 / 9.0, 1e-15);
    CHECK_NEAR(a[8], 1.0 / 9.0, 1e-15);
    CHECK(a[1] == 0.0 && a[2] == 0.0 && a[5] == 0.0);
    CHECK_STATUS(cagd_implicit_subdivision_matrix(0, 0.5, a, 9, &needed),
                 CAGD_ERR_DEGREE_OUT_OF_RANGE);
    CHECK_STATUS(cagd_implicit_subdivision_matrix(3, NAN, a, 9, &needed),
                 CAGD_ERR_INVALID_ARGUMENT);
    CHECK_STATUS(cagd_implicit_subdivision_matrix(3, 0.5, a, 9, NULL), CAGD_ERR_NULL_POINTER);
    rc = 0;
cleanup:
    return rc;
}

int cagd_ctest_curve_intersect(void) {
    int rc = 1;
    /* Parabola (0,0),(1,2),(2,0): y = 4 s (1 - s) against the line y = 0.5. */
    static const double PARA[6] = {0.0, 0.0, 1.0, 2.0, 2.0, 0.0};
    static const double LINE[4] = {-1.0, 0.5, 3.0, 0.5};
    CagdCurve *a = NULL, *b = NULL, *sub = NULL;
    double out[10] = {0};
    size_t needed = 0;
    const double root = (1.0 - sqrt(0.5)) / 2.0;

    CHECK_OK(cagd_curve_new(PARA, 3, 2, &a));
    CHECK_OK(cagd_curve_new(LINE, 2, 2, &b));
    CHECK_STATUS(cagd_curve_intersect(a, b, NULL, 0, &needed), CAGD_ERR_BUFFER_TOO_SMALL);
    CHECK(needed == 2 * CAGD_INTERSECTION_STRIDE);
    CHECK_STATUS(cagd_curve_intersect(a, b, out, 5, &needed), CAGD_ERR_BUFFER_TOO_SMALL);
    CHECK(out[0] == 0.0);
    CHECK_OK(cagd_curve_intersect(a, b, out, 10, &needed));
    CHECK_NEAR(out[0], root, 1e-14);
    CHECK_NEAR(out[5], 1.0 - root, 1e-14);
    CHECK_NEAR(out[3], 0.5, 1e-14);
    CHECK(out[4] == 0.0 && out[9] == 0.0);
    /* The curve with itself overlaps. */
    CHECK_STATUS(cagd_curve_intersect(a, a, out, 10, &needed), CAGD_ERR_COINCIDENT);
    /* Tangency: the line y = 1 touches the apex (1, 1). */
    {
        static const double TOUCH[4] = {-1.0, 1.0, 3.0, 1.0};
        CHECK_OK(cagd_curve_new(TOUCH, 2, 2, &sub));
        CHECK_OK(cagd_curve_intersect(a, sub, out, 10, &needed));
        CHECK(needed == CAGD_INTERSECTION_STRIDE);
        CHECK_NEAR(out[0], 0.5, 1e-7);
        CHECK(out[4] == 1.0);
    }
    rc = 0;
cleanup:
    cagd_curve_free(a);
    cagd_curve_free(b);
    cagd_curve_free(sub);
    return rc;
}

int cagd_ctest_implicit_bad_input(void) {
    int rc = 1;
    static const double P3[9] = {0, 0, 0, 1, 1, 1, 2, 0, 1};
    /* (2 - t)((1 - t) q0 + t q1): points (0,1),(1/2,1/2),(1,0), weights 4, 2, 1. */
    static const double BP[6] = {0.0, 1.0, 0.5, 0.5, 1.0, 0.0};
    static const double BP_W[3] = {4.0, 2.0, 1.0};
    static const double ONE[2] = {1.0, 1.0};
    CagdCurve *c3 = NULL, *bp = NULL, *pt = NULL, *ok = NULL;
    CagdImplicit *imp = NULL;
    size_t needed = 0, degree = 0, base = 0, power = 0;
    double v = 0.0, d = 0.0, t = 0.0, buf[4];
    int32_t s = 0;

    CHECK_OK(cagd_curve_new(P3, 3, 3, &c3));
    CHECK_STATUS(cagd_curve_implicitize(c3, 0, &imp), CAGD_ERR_NOT_PLANAR);
    CHECK(imp == NULL);
    CHECK_STATUS(cagd_curve_implicitize(NULL, 0, &imp), CAGD_ERR_NULL_POINTER);
    CHECK_OK(cagd_curve_new(ONE, 1, 2, &pt));
    CHECK_STATUS(cagd_curve_implicitize(pt, 0, &imp), CAGD_ERR_NOT_ENOUGH_POINTS);
    CHECK_OK(cagd_curve_new_rational(BP, BP_W, 3, 2, &bp));
    CHECK_STATUS(cagd_curve_implicitize(bp, 0, &imp), CAGD_ERR_BASE_POINT);
    CHECK(imp == NULL);
    CHECK_STATUS(cagd_curve_implicitize(bp, 0, NULL), CAGD_ERR_NULL_POINTER);
    CHECK_OK(cagd_curve_implicitize(bp, 1, &imp));
    CHECK_OK(cagd_implicit_report(imp, &degree, &base, &power));
    CHECK(degree == 1 && base == 1 && power == 1);
    CHECK_STATUS(cagd_implicit_report(NULL, &degree, &base, &power), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_implicit_report(imp, NULL, &base, &power), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_implicit_report(imp, &degree, NULL, &power), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_implicit_report(imp, &degree, &base, NULL), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_implicit_coefficients(NULL, buf, 4, &needed), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_implicit_coefficients(imp, NULL, 4, &needed), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_implicit_coefficients(imp, buf, 4, NULL), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_implicit_bezout(NULL, buf, 4, &needed), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_implicit_bezout(imp, buf, 4, NULL), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_implicit_classify(NULL, 0, 0, &v, &s, &d), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_implicit_classify(imp, 0, 0, NULL, &s, &d), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_implicit_classify(imp, 0, 0, &v, NULL, &d), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_implicit_classify(imp, 0, 0, &v, &s, NULL), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_implicit_classify(imp, INFINITY, 0, &v, &s, &d), CAGD_ERR_INVALID_ARGUMENT);
    CHECK_STATUS(cagd_implicit_invert(NULL, 0, 0, &t), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_implicit_invert(imp, 0, 1, NULL), CAGD_ERR_NULL_POINTER);
    /* Intersection: NULLs and a non-planar curve. */
    CHECK_OK(cagd_curve_new(BP, 3, 2, &ok));
    CHECK_STATUS(cagd_curve_intersect(NULL, ok, buf, 4, &needed), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_curve_intersect(ok, NULL, buf, 4, &needed), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_curve_intersect(ok, ok, buf, 4, NULL), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_curve_intersect(ok, ok, NULL, 4, &needed), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_curve_intersect(ok, c3, buf, 4, &needed), CAGD_ERR_NOT_PLANAR);
    CHECK_STATUS(cagd_curve_intersect(pt, ok, buf, 4, &needed), CAGD_ERR_NOT_ENOUGH_POINTS);
    cagd_implicit_free(NULL);
    cagd_implicit_free(NULL);
    rc = 0;
cleanup:
    cagd_implicit_free(imp);
    cagd_curve_free(c3);
    cagd_curve_free(bp);
    cagd_curve_free(pt);
    cagd_curve_free(ok);
    return rc;
}
