/* Constant matrices and scalar formulas: S^(n) of seed 001, the basis conversion matrices,
 * W_n and the subdivision count N of seed 000 eq. 14.2.11 (corrected), checked against the
 * reference vectors of /work/shared/spec/vectors-reduce.json (ids cited below) and closed
 * forms, plus NULL / short-buffer / size-query / bad-argument checks.
 * Every matrix entry is an exact rational rounded once; the C division of two small
 * integers is the same correctly rounded value, so those comparisons use ==. */
#include "ctest.h"

/* Products of (n+1) x (n+1) matrices with entries of size <= 15 (||S^(-4)||): a few ulp. */
#define PRODUCT_TOL 1e-13

/* |(A B)_ij - delta_ij| <= tol for two row-major (n+1) x (n+1) matrices. */
static int is_inverse(const double *a, const double *b, size_t n, double tol) {
    size_t s = n + 1, i, j, k;
    for (i = 0; i < s; ++i) {
        for (j = 0; j < s; ++j) {
            double sum = 0.0;
            for (k = 0; k < s; ++k) {
                sum += a[i * s + k] * b[k * s + j];
            }
            if (fabs(sum - (i == j ? 1.0 : 0.0)) > tol) {
                fprintf(stderr, "(A B)[%zu][%zu] = %.17g\n", i, j, sum);
                return 0;
            }
        }
    }
    return 1;
}

int cagd_ctest_uniform_bspline_matrix(void) {
    int rc = 1;
    /* vector S-matrix-3 times 6, and S-matrix-4 times 24 */
    const int s3[16] = {1, 4, 1, 0, 0, 4, 2, 0, 0, 2, 4, 0, 0, 1, 4, 1};
    const int s4[25] = {1, 11, 11, 1, 0, 0, 8, 14, 2, 0, 0, 4, 16, 4, 0,
                        0, 2, 14, 8, 0, 0, 1, 11, 11, 1};
    double s[25] = {0}, inv[25] = {0};
    size_t needed = 0, k;

    CHECK_STATUS(cagd_uniform_bspline_matrix(3, false, NULL, 0, &needed),
                 CAGD_ERR_BUFFER_TOO_SMALL);
    CHECK(needed == 16);
    CHECK_STATUS(cagd_uniform_bspline_matrix(3, false, s, 15, &needed), CAGD_ERR_BUFFER_TOO_SMALL);
    CHECK(s[0] == 0.0);
    CHECK_OK(cagd_uniform_bspline_matrix(3, false, s, 25, &needed));
    CHECK(needed == 16);
    for (k = 0; k < 16; ++k) {
        CHECK(s[k] == s3[k] / 6.0);
    }
    CHECK_OK(cagd_uniform_bspline_matrix(3, true, inv, 25, &needed));
    CHECK(is_inverse(s, inv, 3, PRODUCT_TOL));

    CHECK_OK(cagd_uniform_bspline_matrix(4, false, s, 25, &needed));
    CHECK(needed == 25);
    for (k = 0; k < 25; ++k) {
        CHECK(s[k] == s4[k] / 24.0);
    }
    CHECK_OK(cagd_uniform_bspline_matrix(4, true, inv, 25, &needed));
    CHECK(is_inverse(s, inv, 4, PRODUCT_TOL));
    CHECK(is_inverse(inv, s, 4, PRODUCT_TOL));

    CHECK_OK(cagd_uniform_bspline_matrix(0, false, s, 25, &needed));
    CHECK(needed == 1 && s[0] == 1.0);
    needed = 99;
    CHECK_STATUS(cagd_uniform_bspline_matrix(65, false, s, 25, &needed),
                 CAGD_ERR_DEGREE_OUT_OF_RANGE);
    CHECK(needed == 99);
    CHECK_STATUS(cagd_uniform_bspline_matrix(3, false, s, 25, NULL), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_uniform_bspline_matrix(3, false, NULL, 25, &needed), CAGD_ERR_NULL_POINTER);
    rc = 0;
cleanup:
    return rc;
}

int cagd_ctest_basis_matrix(void) {
    int rc = 1;
    /* Power to Bernstein, n = 2: b_i = sum_{j<=i} C(i,j) / C(2,j) c_j */
    const double power2[9] = {1, 0, 0, 1, 0.5, 0, 1, 1, 1};
    double m[36] = {0}, inv[36] = {0};
    size_t needed = 0, i, j;
    int b;

    CHECK_STATUS(cagd_basis_matrix(CAGD_BASIS_POWER, 0, 2, true, NULL, 0, &needed),
                 CAGD_ERR_BUFFER_TOO_SMALL);
    CHECK(needed == 9);
    CHECK_OK(cagd_basis_matrix(CAGD_BASIS_POWER, 0, 2, true, m, 36, &needed));
    for (i = 0; i < 9; ++i) {
        CHECK(m[i] == power2[i]);
    }
    /* every basis, n = 5: M M^(-1) = I; the first basis function of each is 1 (the Ball
     * bases are a partition of unity: row sums 1; the others have first column 1) */
    for (b = CAGD_BASIS_POWER; b <= CAGD_BASIS_WSGB; ++b) {
        CHECK_OK(cagd_basis_matrix(b, 1, 5, true, m, 36, &needed));
        CHECK(needed == 36);
        CHECK_OK(cagd_basis_matrix(b, 1, 5, false, inv, 36, &needed));
        CHECK(is_inverse(m, inv, 5, PRODUCT_TOL));
        for (i = 0; i < 6; ++i) {
            double row = 0.0;
            for (j = 0; j < 6; ++j) {
                row += m[i * 6 + j];
            }
            if (b >= CAGD_BASIS_SAID_BALL) {
                CHECK_NEAR(row, 1.0, 1e-15);
            } else {
                CHECK(m[i * 6] == 1.0);
            }
        }
    }
    /* Chebyshev, n = 1: T_1(2t - 1) has Bernstein coefficients (-1, 1) */
    CHECK_OK(cagd_basis_matrix(CAGD_BASIS_CHEBYSHEV, 0, 1, true, m, 36, &needed));
    CHECK(needed == 4 && m[1] == -1.0 && m[3] == 1.0);

    CHECK_STATUS(cagd_basis_matrix(6, 0, 2, true, m, 36, &needed), CAGD_ERR_INVALID_ARGUMENT);
    CHECK_MESSAGE_HAS("CagdBasis");
    CHECK_STATUS(cagd_basis_matrix(-1, 0, 2, true, m, 36, &needed), CAGD_ERR_INVALID_ARGUMENT);
    /* WSGB(4, L): L <= max(floor(4/2) - 1, 0) = 1 */
    CHECK_STATUS(cagd_basis_matrix(CAGD_BASIS_WSGB, 2, 4, true, m, 36, &needed),
                 CAGD_ERR_CONDITION_NOT_MET);
    CHECK_STATUS(cagd_basis_matrix(CAGD_BASIS_POWER, 0, 65, true, m, 36, &needed),
                 CAGD_ERR_DEGREE_OUT_OF_RANGE);
    CHECK_STATUS(cagd_basis_matrix(CAGD_BASIS_POWER, 0, 5, true, m, 35, &needed),
                 CAGD_ERR_BUFFER_TOO_SMALL);
    CHECK(needed == 36);
    CHECK_STATUS(cagd_basis_matrix(CAGD_BASIS_POWER, 0, 2, true, m, 36, NULL),
                 CAGD_ERR_NULL_POINTER);
    rc = 0;
cleanup:
    return rc;
}

int cagd_ctest_perturbation_scalars(void) {
    int rc = 1;
    /* vector W_n-table (tol 1e-12) */
    const size_t ns[8] = {2, 3, 4, 5, 6, 8, 10, 20};
    const double wn[8] = {1.0,
                          0.8660254037844386,
                          0.9411764705882353,
                          0.9926591509932045,
                          1.034285171776761,
                          1.0965398054975035,
                          1.1407569470805543,
                          1.250334837980578};
    double w = -1.0;
    size_t k, levels = 99;

    for (k = 0; k < 8; ++k) {
        CHECK_OK(cagd_perturbation_error_factor(ns[k], &w));
        CHECK_NEAR(w, wn[k], 1e-12);
        CHECK(w >= wn[k]); /* rounded up: an upper bound */
    }
    w = -1.0;
    CHECK_STATUS(cagd_perturbation_error_factor(1, &w), CAGD_ERR_BAD_DEGREE_PAIR);
    CHECK_STATUS(cagd_perturbation_error_factor(65, &w), CAGD_ERR_DEGREE_OUT_OF_RANGE);
    CHECK(w == -1.0);
    CHECK_STATUS(cagd_perturbation_error_factor(3, NULL), CAGD_ERR_NULL_POINTER);

    /* vector N-formula-1: n = 5, ||F|| = 100, delta = 1e-3 -> N = 2 */
    CHECK_OK(cagd_subdivision_levels(5, 100.0, 1e-3, &levels));
    CHECK(levels == 2);
    /* ||F|| = 0: already within any tolerance */
    CHECK_OK(cagd_subdivision_levels(5, 0.0, 1e-3, &levels));
    CHECK(levels == 0);
    levels = 99;
    CHECK_STATUS(cagd_subdivision_levels(5, 100.0, 0.0, &levels), CAGD_ERR_INVALID_ARGUMENT);
    CHECK_STATUS(cagd_subdivision_levels(5, -1.0, 1e-3, &levels), CAGD_ERR_INVALID_ARGUMENT);
    CHECK_MESSAGE_HAS("norm_f");
    CHECK_STATUS(cagd_subdivision_levels(5, NAN, 1e-3, &levels), CAGD_ERR_INVALID_ARGUMENT);
    CHECK_STATUS(cagd_subdivision_levels(1, 100.0, 1e-3, &levels), CAGD_ERR_BAD_DEGREE_PAIR);
    CHECK_STATUS(cagd_subdivision_levels(65, 100.0, 1e-3, &levels),
                 CAGD_ERR_DEGREE_OUT_OF_RANGE);
    CHECK(levels == 99);
    CHECK_STATUS(cagd_subdivision_levels(5, 100.0, 1e-3, NULL), CAGD_ERR_NULL_POINTER);
    rc = 0;
cleanup:
    return rc;
}
