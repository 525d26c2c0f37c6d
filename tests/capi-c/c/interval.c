/* CagdIntervalTriPatch: Example 1 of seed 004 (SPEC-convert I.4-I.5, thickness 2 -> 125/36)
 * new -> reduce -> read back -> contains -> free; the elevation matrix; bad input. */
#include <float.h>
#include <stdbool.h>
#include <stdint.h>

#include "ctest.h"

/* Example 1's lower corners (x, y, z), i-major over (i, j), i for u: box = [x, x + 2]. */
static const double EX1_LO[45] = {
    80, 80, 70,  90, 80, 70,  100, 70, 70, 110, 60, 70, 105, 55, 70, /* i = 0 */
    70, 80, 70,  80, 70, 40,  90, 60, 50,  100, 50, 70,              /* i = 1 */
    60, 70, 70,  70, 60, 50,  80, 50, 70,                            /* i = 2 */
    50, 60, 70,  60, 50, 70,                                         /* i = 3 */
    55, 55, 70,                                                      /* i = 4 */
};

int cagd_ctest_intervaltri_example_1(void) {
    int rc = 1;
    CagdIntervalTriPatch *p = NULL, *q = NULL;
    CagdIntervalReport rep;
    double hi[45], lo3[30], hi3[30], thick = 0;
    size_t degree = 0, dim = 0, needed = 0;
    bool contains = false;

    for (int k = 0; k < 45; k++) hi[k] = EX1_LO[k] + 2.0;
    CHECK_OK(cagd_intervaltri_new(EX1_LO, hi, 4, 3, &p));
    CHECK_OK(cagd_intervaltri_shape(p, &degree, &dim, &thick));
    CHECK(degree == 4 && dim == 3 && thick == 2.0);
    CHECK_OK(cagd_intervaltri_reduce(p, 3, 0, &q, &rep));
    CHECK_NEAR(rep.thickness_in, 2.0, 0.0);
    CHECK_NEAR(rep.thickness_out, 125.0 / 36.0, 1e-12);
    CHECK(rep.n_coupled == 0 && rep.containment_degree == 4);
    CHECK(rep.max_violation <= 0.0 && rep.repair < 1e-11);
    CHECK_STATUS(cagd_intervaltri_net(q, false, NULL, 0, &needed), CAGD_ERR_BUFFER_TOO_SMALL);
    CHECK(needed == 30);
    CHECK_OK(cagd_intervaltri_net(q, false, lo3, 30, &needed));
    CHECK_OK(cagd_intervaltri_net(q, true, hi3, 30, &needed));
    /* Box 111 (i = 1, j = 1: index 5): [155/2, 169/2] x [185/3, 397/6] x [10, 32] (I.5). */
    CHECK_NEAR(lo3[15], 155.0 / 2.0, 1e-11);
    CHECK_NEAR(hi3[15], 169.0 / 2.0, 1e-11);
    CHECK_NEAR(lo3[16], 185.0 / 3.0, 1e-11);
    CHECK_NEAR(hi3[16], 397.0 / 6.0, 1e-11);
    CHECK_NEAR(lo3[17], 10.0, 1e-11);
    CHECK_NEAR(hi3[17], 32.0, 1e-11);
    CHECK_OK(cagd_intervaltri_contains(q, p, 0, &contains));
    CHECK(contains);
    CHECK_OK(cagd_intervaltri_contains(p, q, 0, &contains));
    CHECK(!contains);
    cagd_intervaltri_free(q);
    q = NULL;
    /* The tighter model (SPEC-convert I.2: N = 10 gives 2.622). */
    CHECK_OK(cagd_intervaltri_reduce(p, 3, 10, &q, NULL));
    CHECK_OK(cagd_intervaltri_shape(q, &degree, &dim, &thick));
    CHECK(degree == 3);
    CHECK_NEAR(thick, 2.622, 5e-4);
    CHECK_OK(cagd_intervaltri_contains(q, p, 10, &contains));
    CHECK(contains);
    rc = 0;
cleanup:
    cagd_intervaltri_free(q);
    cagd_intervaltri_free(p);
    return rc;
}

int cagd_ctest_intervaltri_elevation_matrix(void) {
    int rc = 1;
    double e[60];
    size_t needed = 0;

    CHECK_STATUS(cagd_triangle_elevation_matrix(2, 3, NULL, 0, &needed), CAGD_ERR_BUFFER_TOO_SMALL);
    CHECK(needed == 60);
    CHECK_OK(cagd_triangle_elevation_matrix(2, 3, e, 60, &needed));
    /* Row 5 is H~_111 = (H_011 + H_101 + H_110) / 3: columns 1, 3, 4 of the degree-2 net. */
    CHECK_NEAR(e[5 * 6 + 1], 1.0 / 3.0, 0.0);
    CHECK_NEAR(e[5 * 6 + 3], 1.0 / 3.0, 0.0);
    CHECK_NEAR(e[5 * 6 + 4], 1.0 / 3.0, 0.0);
    CHECK(e[0] == 1.0 && e[59] == 1.0);
    CHECK_STATUS(cagd_triangle_elevation_matrix(3, 2, e, 60, &needed), CAGD_ERR_BAD_DEGREE_PAIR);
    CHECK_STATUS(cagd_triangle_elevation_matrix(2, 65, e, 60, &needed),
                 CAGD_ERR_DEGREE_OUT_OF_RANGE);
    CHECK_STATUS(cagd_triangle_elevation_matrix(2, 3, e, 60, NULL), CAGD_ERR_NULL_POINTER);
    rc = 0;
cleanup:
    return rc;
}

int cagd_ctest_intervaltri_bad_input(void) {
    int rc = 1;
    CagdIntervalTriPatch *p = NULL, *q = NULL;
    static const double lo[6] = {0, 1, 0, 2, 1, 0};
    double hi[6] = {1, 2, 1, 3, 2, 1}, bad[6];
    size_t n = 0, needed = 0;
    double t = 0, buf[6];
    bool yes = false;

    CHECK_STATUS(cagd_intervaltri_new(NULL, hi, 2, 1, &p), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_intervaltri_new(lo, NULL, 2, 1, &p), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_intervaltri_new(lo, hi, 2, 1, NULL), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_intervaltri_new(lo, hi, 2, 0, &p), CAGD_ERR_INVALID_ARGUMENT);
    CHECK_STATUS(cagd_intervaltri_new(lo, hi, 65, 1, &p), CAGD_ERR_DEGREE_OUT_OF_RANGE);
    CHECK_STATUS(cagd_intervaltri_new(lo, hi, SIZE_MAX, 1, &p), CAGD_ERR_DEGREE_OUT_OF_RANGE);
    memcpy(bad, hi, sizeof bad);
    bad[3] = NAN;
    CHECK_STATUS(cagd_intervaltri_new(lo, bad, 2, 1, &p), CAGD_ERR_NON_FINITE);
    bad[3] = INFINITY;
    CHECK_STATUS(cagd_intervaltri_new(lo, bad, 2, 1, &p), CAGD_ERR_NON_FINITE);
    bad[3] = 1.5; /* lo[3] = 2 > 1.5 */
    CHECK_STATUS(cagd_intervaltri_new(lo, bad, 2, 1, &p), CAGD_ERR_EMPTY_INTERVAL);
    CHECK_MESSAGE_HAS("box 3");
    CHECK(p == NULL);
    CHECK_OK(cagd_intervaltri_new(lo, hi, 2, 1, &p));
    CHECK_STATUS(cagd_intervaltri_shape(NULL, &n, &n, &t), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_intervaltri_shape(p, &n, &n, NULL), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_intervaltri_net(NULL, false, buf, 6, &needed), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_intervaltri_net(p, true, NULL, 6, &needed), CAGD_ERR_NULL_POINTER);
    buf[0] = -7.0;
    CHECK_STATUS(cagd_intervaltri_net(p, true, buf, 5, &needed), CAGD_ERR_BUFFER_TOO_SMALL);
    CHECK(needed == 6 && buf[0] == -7.0);
    CHECK_STATUS(cagd_intervaltri_reduce(p, 2, 0, &q, NULL), CAGD_ERR_BAD_DEGREE_PAIR);
    CHECK_STATUS(cagd_intervaltri_reduce(p, 1, 1, &q, NULL), CAGD_ERR_BAD_DEGREE_PAIR);
    CHECK_STATUS(cagd_intervaltri_reduce(p, 1, 65, &q, NULL), CAGD_ERR_DEGREE_OUT_OF_RANGE);
    CHECK_STATUS(cagd_intervaltri_reduce(NULL, 1, 0, &q, NULL), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_intervaltri_reduce(p, 1, 0, NULL, NULL), CAGD_ERR_NULL_POINTER);
    CHECK(q == NULL);
    CHECK_STATUS(cagd_intervaltri_contains(p, NULL, 0, &yes), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_intervaltri_contains(p, p, 0, NULL), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_intervaltri_contains(p, p, 65, &yes), CAGD_ERR_DEGREE_OUT_OF_RANGE);
    CHECK_OK(cagd_intervaltri_contains(p, p, 0, &yes));
    CHECK(yes);
    cagd_intervaltri_free(NULL);
    cagd_intervaltri_free(NULL);
    rc = 0;
cleanup:
    cagd_intervaltri_free(q);
    cagd_intervaltri_free(p);
    return rc;
}

/* Final 10^7 fuzz run (seed 103): boxes from -DBL_MAX to DBL_MAX have widths past the
 * double range; cagd_intervaltri_shape returned CAGD_OK with thickness = inf. Now
 * CAGD_ERR_NON_FINITE, nothing written; a patch of finite thickness still answers. */
int cagd_ctest_intervaltri_thickness_overflow(void) {
    int rc = 1;
    CagdIntervalTriPatch *p = NULL;
    double lo[3] = {-DBL_MAX, -DBL_MAX, -DBL_MAX}, hi[3] = {DBL_MAX, DBL_MAX, DBL_MAX};
    size_t n = 77, d = 77;
    double t = -7.0;
    CHECK_OK(cagd_intervaltri_new(lo, hi, 1, 1, &p));
    CHECK_STATUS(cagd_intervaltri_shape(p, &n, &d, &t), CAGD_ERR_NON_FINITE);
    CHECK(t == -7.0 && n == 77 && d == 77);
    cagd_intervaltri_free(p);
    p = NULL;
    lo[0] = lo[1] = lo[2] = -DBL_MAX / 4;
    hi[0] = hi[1] = hi[2] = 0.0;
    CHECK_OK(cagd_intervaltri_new(lo, hi, 1, 1, &p));
    CHECK_OK(cagd_intervaltri_shape(p, &n, &d, &t));
    CHECK(n == 1 && d == 1 && t == DBL_MAX / 4);
    rc = 0;
cleanup:
    cagd_intervaltri_free(p);
    return rc;
}
