/* Status names, the thread-local message and the version macros. */
#include "ctest.h"

#if !defined(CAGD_VERSION_MAJOR) || !defined(CAGD_VERSION_MINOR) || !defined(CAGD_VERSION_PATCH)
#error "cagd.h must define the CAGD_VERSION_* macros"
#endif

int cagd_ctest_status_names(void) {
    int rc = 1;
    CHECK(strcmp(cagd_status_name(CAGD_OK), "CAGD_OK") == 0);
    CHECK(strcmp(cagd_status_name(CAGD_ERR_NULL_POINTER), "CAGD_ERR_NULL_POINTER") == 0);
    CHECK(strcmp(cagd_status_name(CAGD_ERR_PANIC), "CAGD_ERR_PANIC") == 0);
    CHECK(strcmp(cagd_status_name(-7), "CAGD_ERR_UNKNOWN") == 0);
    CHECK(strcmp(cagd_status_name(1000), "CAGD_ERR_UNKNOWN") == 0);
    /* The numbers are part of the ABI. */
    CHECK(CAGD_OK == 0 && CAGD_ERR_NULL_POINTER == 1 && CAGD_ERR_BUFFER_TOO_SMALL == 2);
    CHECK(CAGD_ERR_NON_FINITE == 20 && CAGD_ERR_NON_POSITIVE_WEIGHT == 21);
    CHECK(CAGD_ERR_PANIC == 99);
    CHECK(sizeof(CagdStatus) == 4);
    rc = 0;
cleanup:
    return rc;
}

int cagd_ctest_last_error_message(void) {
    int rc = 1;
    CagdCurve *c = NULL;
    const double pts[4] = {0.0, 0.0, 1.0, 1.0};
    const double w_bad[2] = {1.0, -0.5};
    size_t degree = 0;

    CHECK_STATUS(cagd_curve_new_rational(pts, w_bad, 2, 2, &c), CAGD_ERR_NON_POSITIVE_WEIGHT);
    CHECK(c == NULL); /* outputs only on success */
    CHECK_MESSAGE_HAS("weights[1] = -0.5");
    /* status_name and free leave the message alone */
    (void)cagd_status_name(CAGD_ERR_NON_POSITIVE_WEIGHT);
    cagd_curve_free(NULL);
    CHECK_MESSAGE_HAS("weights[1] = -0.5");
    /* the next successful call clears it */
    CHECK_OK(cagd_curve_new(pts, 2, 2, &c));
    CHECK(strcmp(cagd_last_error_message(), "") == 0);
    CHECK_STATUS(cagd_curve_degree(NULL, &degree), CAGD_ERR_NULL_POINTER);
    CHECK_MESSAGE_HAS("curve");
    rc = 0;
cleanup:
    cagd_curve_free(c);
    return rc;
}
