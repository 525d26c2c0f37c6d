/* CagdTensorPatch and CagdTriPatch: new -> read back -> free, and bad input. */
#include <stdint.h>

#include "ctest.h"

/* Bilinear patch, i-major: P00, P01, P10, P11 in 3D. */
static const double BILINEAR[12] = {0, 0, 0, 0, 1, 0, 1, 0, 0, 1, 1, 1};
/* Quadratic triangle, i-major: T00 T01 T02 T10 T11 T20 in 2D. */
static const double TRI2[12] = {0, 0, 0, 1, 0, 2, 1, 0, 1, 1, 2, 0};

int cagd_ctest_tensorpatch_roundtrip(void) {
    int rc = 1;
    CagdTensorPatch *p = NULL;
    size_t m = 0, n = 0, dim = 0, needed = 0;
    double buf[12] = {0};

    CHECK_OK(cagd_tensorpatch_new(BILINEAR, 1, 1, 3, &p));
    CHECK_OK(cagd_tensorpatch_shape(p, &m, &n, &dim));
    CHECK(m == 1 && n == 1 && dim == 3);
    CHECK_STATUS(cagd_tensorpatch_points(p, NULL, 0, &needed), CAGD_ERR_BUFFER_TOO_SMALL);
    CHECK(needed == 12);
    CHECK_OK(cagd_tensorpatch_points(p, buf, 12, &needed));
    CHECK(memcmp(buf, BILINEAR, sizeof BILINEAR) == 0);
    rc = 0;
cleanup:
    cagd_tensorpatch_free(p);
    return rc;
}

int cagd_ctest_tensorpatch_bad_input(void) {
    int rc = 1;
    CagdTensorPatch *p = NULL;
    size_t m = 0, needed = 0;
    double buf[12] = {0}, nan_pts[12];

    memcpy(nan_pts, BILINEAR, sizeof nan_pts);
    nan_pts[7] = NAN;
    CHECK_STATUS(cagd_tensorpatch_new(NULL, 1, 1, 3, &p), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_tensorpatch_new(BILINEAR, 1, 1, 3, NULL), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_tensorpatch_new(BILINEAR, 1, 1, 0, &p), CAGD_ERR_INVALID_ARGUMENT);
    CHECK_STATUS(cagd_tensorpatch_new(BILINEAR, 65, 0, 3, &p), CAGD_ERR_DEGREE_OUT_OF_RANGE);
    CHECK_STATUS(cagd_tensorpatch_new(BILINEAR, 1, SIZE_MAX, 3, &p),
                 CAGD_ERR_DEGREE_OUT_OF_RANGE);
    CHECK_STATUS(cagd_tensorpatch_new(nan_pts, 1, 1, 3, &p), CAGD_ERR_NON_FINITE);
    CHECK(p == NULL);
    CHECK_OK(cagd_tensorpatch_new(BILINEAR, 1, 1, 3, &p));
    CHECK_STATUS(cagd_tensorpatch_shape(NULL, &m, &m, &m), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_tensorpatch_shape(p, NULL, &m, &m), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_tensorpatch_shape(p, &m, NULL, &m), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_tensorpatch_shape(p, &m, &m, NULL), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_tensorpatch_points(NULL, buf, 12, &needed), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_tensorpatch_points(p, NULL, 12, &needed), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_tensorpatch_points(p, buf, 12, NULL), CAGD_ERR_NULL_POINTER);
    buf[2] = -1.0;
    CHECK_STATUS(cagd_tensorpatch_points(p, buf, 11, &needed), CAGD_ERR_BUFFER_TOO_SMALL);
    CHECK(needed == 12 && buf[2] == -1.0); /* nothing written */
    cagd_tensorpatch_free(NULL);
    cagd_tensorpatch_free(NULL);
    rc = 0;
cleanup:
    cagd_tensorpatch_free(p);
    return rc;
}

int cagd_ctest_tripatch_roundtrip(void) {
    int rc = 1;
    CagdTriPatch *p = NULL;
    size_t n = 0, dim = 0, needed = 0;
    double buf[12] = {0};

    CHECK_OK(cagd_tripatch_new(TRI2, 2, 2, &p));
    CHECK_OK(cagd_tripatch_shape(p, &n, &dim));
    CHECK(n == 2 && dim == 2);
    CHECK_STATUS(cagd_tripatch_points(p, NULL, 0, &needed), CAGD_ERR_BUFFER_TOO_SMALL);
    CHECK(needed == 12); /* (n + 1)(n + 2) / 2 * dim = 6 * 2 */
    CHECK_OK(cagd_tripatch_points(p, buf, 12, &needed));
    CHECK(memcmp(buf, TRI2, sizeof TRI2) == 0);
    rc = 0;
cleanup:
    cagd_tripatch_free(p);
    return rc;
}

int cagd_ctest_tripatch_bad_input(void) {
    int rc = 1;
    CagdTriPatch *p = NULL;
    size_t n = 0, needed = 0;
    double buf[12] = {0}, inf_pts[12];

    memcpy(inf_pts, TRI2, sizeof inf_pts);
    inf_pts[0] = INFINITY;
    CHECK_STATUS(cagd_tripatch_new(NULL, 2, 2, &p), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_tripatch_new(TRI2, 2, 2, NULL), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_tripatch_new(TRI2, 2, 0, &p), CAGD_ERR_INVALID_ARGUMENT);
    CHECK_STATUS(cagd_tripatch_new(TRI2, 65, 2, &p), CAGD_ERR_DEGREE_OUT_OF_RANGE);
    CHECK_STATUS(cagd_tripatch_new(TRI2, SIZE_MAX, 2, &p), CAGD_ERR_DEGREE_OUT_OF_RANGE);
    CHECK_STATUS(cagd_tripatch_new(inf_pts, 2, 2, &p), CAGD_ERR_NON_FINITE);
    CHECK(p == NULL);
    CHECK_OK(cagd_tripatch_new(TRI2, 2, 2, &p));
    CHECK_STATUS(cagd_tripatch_shape(NULL, &n, &n), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_tripatch_shape(p, NULL, &n), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_tripatch_shape(p, &n, NULL), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_tripatch_points(NULL, buf, 12, &needed), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_tripatch_points(p, NULL, 12, &needed), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_tripatch_points(p, buf, 12, NULL), CAGD_ERR_NULL_POINTER);
    buf[3] = -1.0;
    CHECK_STATUS(cagd_tripatch_points(p, buf, 11, &needed), CAGD_ERR_BUFFER_TOO_SMALL);
    CHECK(needed == 12 && buf[3] == -1.0); /* nothing written */
    cagd_tripatch_free(NULL);
    cagd_tripatch_free(NULL);
    rc = 0;
cleanup:
    cagd_tripatch_free(p);
    return rc;
}
