// The header must compile as C++17 for C++ CAD kernels (cbindgen's cpp_compat guards),
// and the C functions must be callable from C++ with the typed CagdStatus enum.
#include <cmath>
#include <cstring>

#include "cagd.h"

extern "C" int cagd_ctest_cpp_header(void);

extern "C" int cagd_ctest_cpp_header(void) {
    static_assert(sizeof(CagdStatus) == 4, "CagdStatus is int32_t-sized");
    const double pts[] = {0.0, 0.0, 1.0, 2.0, 2.0, 0.0};
    CagdCurve *c = nullptr;
    double p[2] = {0.0, 0.0};
    std::size_t needed = 0;
    int rc = 1;
    if (cagd_curve_new(pts, 3, 2, &c) == CAGD_OK &&
        cagd_curve_eval(c, 0.5, p, 2, &needed) == CAGD_OK && needed == 2 &&
        std::fabs(p[0] - 1.0) <= 1e-15 && std::fabs(p[1] - 1.0) <= 1e-15 &&
        std::strcmp(cagd_status_name(CAGD_ERR_NULL_POINTER), "CAGD_ERR_NULL_POINTER") == 0) {
        rc = 0;
    }
    cagd_curve_free(c);
    return rc;
}
