/* Reduction with bad input: NULL for every pointer, invalid codes and degree pairs, too
 * many constraints, NaN in a batch, short buffers, aliasing outputs, double free(NULL). */
#include <stdint.h>

#include "ctest.h"

static const double P7[16] = {0, 0, 1, 3, 3, 4, 5, 1, 6, 5, 8, 2, 9, 6, 11, 0};

int cagd_ctest_reduce_bad_input(void) {
    int rc = 1;
    CagdCurve *c = NULL, *q = NULL;
    CagdReport *rep = NULL;
    CagdReduceOptions o;
    void *same = NULL;

    CHECK_STATUS(cagd_reduce_options_init(NULL), CAGD_ERR_NULL_POINTER);
    CHECK_OK(cagd_reduce_options_init(&o));
    /* the defaults: L2 with the end points interpolated */
    CHECK(o.struct_size == sizeof(CagdReduceOptions));
    CHECK(o.method == CAGD_METHOD_L2 && o.target == 3 && o.r == 0 && o.p == 0 &&
          o.l1 == 0.0 && o.l2 == 0.0 && !o.measure && o.space == CAGD_SPACE_EUCLIDEAN);
    CHECK(o.tolerance == 0.0 && o.continuity == 0 && o.max_depth == 30);
    CHECK(o.spline_strategy == CAGD_SPLINE_FIT && o.spline_continuity == -1);
    CHECK_OK(cagd_curve_new(P7, 8, 2, &c));

    CHECK_STATUS(cagd_curve_reduce(NULL, &o, &q, &rep), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_curve_reduce(c, NULL, &q, &rep), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_curve_reduce(c, &o, NULL, &rep), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_curve_reduce(c, &o, &q, NULL), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_curve_reduce(c, &o, (CagdCurve **)&same, (CagdReport **)&same),
                 CAGD_ERR_INVALID_ARGUMENT);

    o.method = 12;
    CHECK_STATUS(cagd_curve_reduce(c, &o, &q, &rep), CAGD_ERR_INVALID_ARGUMENT);
    CHECK_MESSAGE_HAS("12");
    o.method = -1;
    CHECK_STATUS(cagd_curve_reduce(c, &o, &q, &rep), CAGD_ERR_INVALID_ARGUMENT);
    o.method = CAGD_METHOD_L2;
    o.space = 7;
    CHECK_STATUS(cagd_curve_reduce(c, &o, &q, &rep), CAGD_ERR_INVALID_ARGUMENT);
    o.space = CAGD_SPACE_EUCLIDEAN;

    o.target = 7; /* not below the degree */
    CHECK_STATUS(cagd_curve_reduce(c, &o, &q, &rep), CAGD_ERR_BAD_DEGREE_PAIR);
    o.target = 3;
    o.r = 2;
    o.p = 1; /* r + p + 1 = 4 > 3 */
    CHECK_STATUS(cagd_curve_reduce(c, &o, &q, &rep), CAGD_ERR_TOO_MANY_CONSTRAINTS);
    o.r = -2;
    o.p = 0;
    CHECK_STATUS(cagd_curve_reduce(c, &o, &q, &rep), CAGD_ERR_TOO_MANY_CONSTRAINTS);
    o.method = CAGD_METHOD_PERTURB_G1;
    o.l1 = NAN;
    CHECK_STATUS(cagd_curve_reduce(c, &o, &q, &rep), CAGD_ERR_INVALID_ARGUMENT);
    o.l1 = -1.5;
    CHECK_STATUS(cagd_curve_reduce(c, &o, &q, &rep), CAGD_ERR_INVALID_ARGUMENT);
    o.method = CAGD_METHOD_FARIN;
    o.target = 0;
    CHECK_STATUS(cagd_curve_reduce(c, &o, &q, &rep), CAGD_ERR_BAD_DEGREE_PAIR);
    CHECK(q == NULL && rep == NULL); /* never written on failure */

    cagd_report_free(NULL);
    cagd_report_free(NULL);
    rc = 0;
cleanup:
    cagd_report_free(rep);
    cagd_curve_free(q);
    cagd_curve_free(c);
    return rc;
}

int cagd_ctest_report_accessors_bad_input(void) {
    int rc = 1;
    CagdCurve *c = NULL, *q = NULL;
    CagdReport *rep = NULL;
    CagdReduceOptions o;
    double x = -1.0;
    size_t a = 0, b = 0;
    int32_t m = -1;

    CHECK_OK(cagd_curve_new(P7, 8, 2, &c));
    CHECK_OK(cagd_reduce_options_init(&o));
    CHECK_OK(cagd_curve_reduce(c, &o, &q, &rep));
    CHECK_STATUS(cagd_report_method(NULL, &m, &a, &b), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_report_method(rep, NULL, &a, &b), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_report_method(rep, &m, NULL, &b), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_report_method(rep, &m, &a, NULL), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_report_bound(NULL, &x), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_report_bound(rep, NULL), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_report_max_error(NULL, &x), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_report_max_error(rep, NULL), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_report_max_error(rep, &x), CAGD_ERR_NOT_AVAILABLE);
    CHECK_MESSAGE_HAS("measure");
    CHECK(x == -1.0);
    CHECK_STATUS(cagd_report_space(NULL, &m, &x), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_report_space(rep, NULL, &x), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_report_space(rep, &m, NULL), CAGD_ERR_NULL_POINTER);
    CHECK(m == -1 && a == 0 && b == 0);
    rc = 0;
cleanup:
    cagd_report_free(rep);
    cagd_curve_free(q);
    cagd_curve_free(c);
    return rc;
}

int cagd_ctest_reduce_batch_bad_input(void) {
    int rc = 1;
    CagdReduceOptions o;
    double in[32], out[16];
    size_t needed = 77, k;

    memcpy(in, P7, sizeof P7);
    memcpy(in + 16, P7, sizeof P7);
    for (k = 0; k < 16; ++k) out[k] = -1.0;
    CHECK_OK(cagd_reduce_options_init(&o));
    o.method = CAGD_METHOD_ECK;
    o.target = 6;
    CHECK_STATUS(cagd_curve_reduce_batch(NULL, 2, 7, 2, &o, out, 28, &needed),
                 CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_curve_reduce_batch(in, 2, 7, 2, NULL, out, 28, &needed),
                 CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_curve_reduce_batch(in, 2, 7, 2, &o, NULL, 28, &needed),
                 CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_curve_reduce_batch(in, 2, 7, 2, &o, out, 16, NULL),
                 CAGD_ERR_NULL_POINTER);
    CHECK(needed == 77);
    CHECK_STATUS(cagd_curve_reduce_batch(in, 2, 7, 0, &o, out, 16, &needed),
                 CAGD_ERR_INVALID_ARGUMENT);
    CHECK_STATUS(cagd_curve_reduce_batch(in, SIZE_MAX, 7, 2, &o, out, 16, &needed),
                 CAGD_ERR_INVALID_ARGUMENT);
    CHECK_STATUS(cagd_curve_reduce_batch(in, 2, 65, 2, &o, out, 16, &needed),
                 CAGD_ERR_DEGREE_OUT_OF_RANGE);
    /* short buffer: 2 curves of 7 points of 2 doubles need 28 */
    CHECK_STATUS(cagd_curve_reduce_batch(in, 2, 7, 2, &o, out, 16, &needed),
                 CAGD_ERR_BUFFER_TOO_SMALL);
    CHECK(needed == 28 && out[0] == -1.0);
    o.target = 3;
    in[16 + 5] = NAN; /* curve 1, point 2, coordinate 1: batch point 10 */
    needed = 77;
    CHECK_STATUS(cagd_curve_reduce_batch(in, 2, 7, 2, &o, out, 16, &needed),
                 CAGD_ERR_NON_FINITE);
    CHECK_MESSAGE_HAS("points[10][1]");
    CHECK(needed == 16); /* out: contents unspecified on CAGD_ERR_NON_FINITE */
    o.target = 7;
    in[16 + 5] = 1.0;
    CHECK_STATUS(cagd_curve_reduce_batch(in, 2, 7, 2, &o, out, 16, &needed),
                 CAGD_ERR_BAD_DEGREE_PAIR);
    rc = 0;
cleanup:
    return rc;
}

/* The versioning rule of CagdReduceOptions: a struct_size below the first version's size
 * (an uninitialised struct, most likely) is rejected by every function taking options. */
int cagd_ctest_reduce_options_struct_size(void) {
    int rc = 1;
    CagdCurve *c = NULL, *q = NULL;
    CagdReport *rep = NULL;
    CagdReduceOptions o;
    double out[8] = {0};
    size_t needed = 0;

    CHECK_OK(cagd_curve_new(P7, 8, 2, &c));
    CHECK_OK(cagd_reduce_options_init(&o));
    o.struct_size = 0;
    CHECK_STATUS(cagd_curve_reduce(c, &o, &q, &rep), CAGD_ERR_INVALID_ARGUMENT);
    CHECK_MESSAGE_HAS("struct_size");
    o.struct_size = sizeof o - 1;
    CHECK_STATUS(cagd_curve_reduce(c, &o, &q, &rep), CAGD_ERR_INVALID_ARGUMENT);
    CHECK_STATUS(cagd_curve_reduce_batch(P7, 1, 7, 2, &o, out, 8, &needed),
                 CAGD_ERR_INVALID_ARGUMENT);
    CHECK(q == NULL && rep == NULL);
    /* sizeof: accepted, and the default method interpolates the end points */
    o.struct_size = sizeof o;
    CHECK_OK(cagd_curve_reduce(c, &o, &q, &rep));
    CHECK_OK(cagd_curve_points(q, out, 8, &needed));
    CHECK(out[0] == 0.0 && out[1] == 0.0);
    CHECK_NEAR(out[6], 11.0, 1e-12);
    CHECK_NEAR(out[7], 0.0, 1e-12);
    rc = 0;
cleanup:
    cagd_report_free(rep);
    cagd_curve_free(q);
    cagd_curve_free(c);
    return rc;
}
