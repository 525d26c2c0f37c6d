/* The cagd C ABI fuzz harness: one operation per cagd_* function of include/cagd.h.
 * FZ_FUNCS lists them; tests/capi-c/src/fuzz.rs fails when a function of the header is
 * not listed there, so a new entry point cannot be left out. Each operation draws its
 * arguments (valid handles or NULL, sizes from 0 to huge, good or hostile numbers, every
 * kind of output buffer), makes the call through fz_status (the status oracle) and
 * checks its outputs (finite numbers, consistent sizes, bounds above measured errors). */
#include "harness_impl.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

/* clang-format off */
#define FZ_FUNCS \
    X(cagd_bspline_new) X(cagd_bspline_new_rational) X(cagd_bspline_free) \
    X(cagd_bspline_degree) X(cagd_bspline_dim) X(cagd_bspline_n_points) \
    X(cagd_bspline_is_rational) X(cagd_bspline_domain) X(cagd_bspline_knots) \
    X(cagd_bspline_points) X(cagd_bspline_weights) X(cagd_bspline_from_beziers) \
    X(cagd_bspline_eval) X(cagd_bspline_derivatives) X(cagd_bspline_insert_knot) \
    X(cagd_bspline_to_beziers) X(cagd_bspline_reduce) X(cagd_bspline_reduce_uniform) \
    X(cagd_bsplinesurface_new) X(cagd_bsplinesurface_free) X(cagd_bsplinesurface_shape) \
    X(cagd_bsplinesurface_array) X(cagd_bsplinesurface_eval) \
    X(cagd_bsplinesurface_reduce) X(cagd_bsplinesurface_reduce_to_tolerance) \
    X(cagd_nurbs_span_to_bezier) X(cagd_bezier_to_nurbs_span) \
    X(cagd_nurbs22_span_to_bezier) X(cagd_bezier22_to_nurbs22_span) \
    X(cagd_bspline_to_bezier_pieces) X(cagd_curvelist_to_bspline) \
    X(cagd_curve_standard_form) X(cagd_patchpiecelist_free) X(cagd_patchpiecelist_count) \
    X(cagd_patchpiecelist_info) X(cagd_patchpiecelist_points) \
    X(cagd_patchpiecelist_weights) X(cagd_patchpiecelist_domain) \
    X(cagd_tensorpatch_to_triangles) X(cagd_tensorpatch_split_line) \
    X(cagd_tensorpatch_split_curve) X(cagd_tensorpatch_trim) X(cagd_tripatch_to_rect) \
    X(cagd_tripatch_to_quad) X(cagd_tripatch_to_three_rects) \
    X(cagd_tensorpatch_to_triangle) X(cagd_curve_new) X(cagd_curve_new_rational) \
    X(cagd_curve_free) X(cagd_curve_degree) X(cagd_curve_dim) X(cagd_curve_is_rational) \
    X(cagd_curve_points) X(cagd_curve_weights) X(cagd_curvelist_free) \
    X(cagd_curvelist_count) X(cagd_curvelist_get) X(cagd_curvelist_interval) \
    X(cagd_curvelist_bound) X(cagd_curve_eval) X(cagd_curve_eval_many) \
    X(cagd_curve_elevate) X(cagd_curve_subdivide) X(cagd_curve_segment) \
    X(cagd_curve_implicitize) X(cagd_implicit_free) X(cagd_implicit_report) \
    X(cagd_implicit_coefficients) X(cagd_implicit_bezout) X(cagd_implicit_classify) \
    X(cagd_implicit_invert) X(cagd_curve_intersect) X(cagd_implicit_subdivision_matrix) \
    X(cagd_intervaltri_new) X(cagd_intervaltri_free) X(cagd_intervaltri_shape) \
    X(cagd_intervaltri_net) X(cagd_intervaltri_contains) X(cagd_intervaltri_reduce) \
    X(cagd_triangle_elevation_matrix) X(cagd_curve_forward_difference) \
    X(cagd_tensorpatch_degeneracy) X(cagd_tripatch_degeneracy) X(cagd_curve_distance) \
    X(cagd_tensorpatch_distance) X(cagd_tripatch_distance) X(cagd_last_error_message) \
    X(cagd_uniform_bspline_matrix) X(cagd_basis_matrix) \
    X(cagd_perturbation_error_factor) X(cagd_subdivision_levels) \
    X(cagd_tensorpatchlist_free) X(cagd_tensorpatchlist_count) \
    X(cagd_tensorpatchlist_get) X(cagd_tripatchlist_free) X(cagd_tripatchlist_count) \
    X(cagd_tripatchlist_get) X(cagd_tensorpatch_reduce) X(cagd_tripatch_reduce) \
    X(cagd_tensorpatch_reduce_to_tolerance) X(cagd_tripatch_reduce_to_tolerance) \
    X(cagd_report_patch) X(cagd_bspline_to_polynomial) \
    X(cagd_bsplinesurface_to_polynomial) X(cagd_curve_reduce) X(cagd_curve_reduce_batch) X(cagd_curve_reduce_batch_bounded) \
    X(cagd_curve_exact_degree) X(cagd_curve_reduce_exact) X(cagd_curve_reduce_g1_optimal) \
    X(cagd_reduce_operator) X(cagd_report_method_params) X(cagd_reduce_options_init) \
    X(cagd_curve_reduce_to_tolerance) X(cagd_curve_reduce_to_tolerance_stepwise) \
    X(cagd_report_free) X(cagd_report_method) X(cagd_report_bound) \
    X(cagd_report_max_error) X(cagd_report_space) X(cagd_report_piecewise) \
    X(cagd_report_pieces) X(cagd_report_step_bounds) X(cagd_report_spline) \
    X(cagd_report_spline_strategy) X(cagd_report_spline_continuity) X(cagd_status_name) \
    X(cagd_tensorpatch_new) X(cagd_tensorpatch_free) X(cagd_tensorpatch_shape) \
    X(cagd_tensorpatch_points) X(cagd_tensorpatch_eval) X(cagd_tensorpatch_elevate) \
    X(cagd_tensorpatch_subdivide_u) X(cagd_tensorpatch_subdivide_v) X(cagd_tripatch_new) \
    X(cagd_tripatch_free) X(cagd_tripatch_shape) X(cagd_tripatch_points) \
    X(cagd_tripatch_eval) X(cagd_tripatch_elevate) X(cagd_tripatch_subdivide_midpoint) \
    X(cagd_wsgb_new) X(cagd_wsgb_free) X(cagd_wsgb_shape) X(cagd_wsgb_points) \
    X(cagd_wsgb_eval) X(cagd_wsgb_to_bezier) X(cagd_wsgb_from_bezier) \
    X(cagd_wsgb_elevate) X(cagd_wsgb_leading_coefficient) \
    X(cagd_wsgb_reduce_to_tolerance) X(cagd_wsgblist_free) X(cagd_wsgblist_count) \
    X(cagd_wsgblist_get) X(cagd_wsgb_reduce) X(cagd_bezier_elevate) \
    X(cagd_bezier_elevate_batch) X(cagd_bezier_reduce) X(cagd_bezier_reduce_batch) \
    X(cagd_bspline_copy) X(cagd_bspline_outer_knots) \
    X(cagd_bsplinesurface_to_bezier_patches) X(cagd_curvelist_copy) \
    X(cagd_curvelist_to_bspline_unclamped) X(cagd_patchpiecelist_to_bsplinesurface) \
    X(cagd_report_bound_level) X(cagd_tensorpatchlist_copy) X(cagd_tripatchlist_copy) \
    X(cagd_wsgblist_copy)
/* clang-format on */

#define X(name) FN_##name,
enum { FZ_FUNCS FN_COUNT };
#undef X

/* ---------------------------------------------------------------- helpers */

/* A handle output `v` of type `struct T *`: NULL now and then (cagd must refuse it). */
#define OUT_H(T, v)                                                                        \
    struct T *v = NULL;                                                                    \
    int v##_n = fz_r(48) == 0;                                                             \
    fz.call_null |= v##_n
#define HP(v) (v##_n ? NULL : &v)
#define KEEP(TYPE, v) fz_handle_out(TYPE, st, v, v##_n)
/* A required scalar output. */
#define OUT_S(T, v)                                                                        \
    T v = 0;                                                                               \
    int v##_n = fz_r(48) == 0;                                                             \
    fz.call_null |= v##_n
/* A scalar output that may be NULL by contract. */
#define OUT_SO(T, v)                                                                       \
    T v = 0;                                                                               \
    int v##_n = fz_r(8) == 0
#define SP(v) (v##_n ? NULL : &v)
#define FIN(v)                                                                             \
    do {                                                                                   \
        if (st == CAGD_OK && !v##_n) fz_finite((double)(v), #v);                          \
    } while (0)
/* A required input handle: NULL now and then. */
#define IN_H(TYPE, T, v)                                                                   \
    const struct T *v = (const struct T *)fz_pick(TYPE);                                   \
    fz.call_null |= v == NULL
/* The call with a buffer output `ob` (re-run once for the exact-size mode). */
#define OUTCALL(ob, expr)                                                                  \
    do {                                                                                   \
        fz_ob_init(&ob);                                                                   \
        for (;;) {                                                                         \
            st = fz_status(expr);                                                          \
            if (!fz_ob_again(&ob, st)) break;                                              \
        }                                                                                  \
        fz_ob_check(&ob, st, 1);                                                           \
    } while (0)
#define SKIP_IF_NEEDED                                                                     \
    do {                                                                                   \
        if (fz.skip) return;                                                               \
    } while (0)

static union {
    CagdReduceOptions o;
    unsigned char pad[512];
} opts_store;

/* Options: cagd_reduce_options_init, then a few fields changed; a wrong struct_size or
 * NULL now and then. */
static const CagdReduceOptions *gen_opts(void) {
    if (fz_r(48) == 0) {
        fz.call_null = 1;
        return NULL;
    }
    memset(&opts_store, 0, sizeof opts_store);
    CagdReduceOptions *o = &opts_store.o;
    (void)cagd_reduce_options_init(o);
    unsigned k = fz_r(4);
    for (unsigned i = 0; i < k; ++i) {
        switch (fz_r(20)) {
        case 0: o->method = fz_enum(12); break;
        case 1: o->target = fz_small_deg(); break;
        case 2: o->r = fz_r(8) ? (int32_t)fz_r(5) - 1 : fz_enum(4); break;
        case 3: o->p = fz_r(8) ? (int32_t)fz_r(5) - 1 : fz_enum(4); break;
        case 4: o->l1 = fz_double(); break;
        case 5: o->l2 = fz_double(); break;
        case 6: o->measure = fz_r(2); break;
        case 7: o->space = fz_enum(2); break;
        case 8: o->tolerance = fz_tol(); break;
        case 9: o->continuity = fz_r(16) ? fz_r(4) : fz_huge(); break;
        case 10: o->max_depth = fz_r(16) ? fz_r(12) : fz_huge(); break;
        case 11: o->target_v = fz_small_deg(); break;
        case 12: o->patch_method = fz_enum(3); break;
        case 13: o->constraint = fz_enum(3); break;
        case 14: o->merge = fz_enum(2); break;
        case 15: o->spline_strategy = fz_enum(3); break;
        case 16: o->spline_continuity = fz_r(8) ? (int32_t)fz_r(4) - 1 : fz_enum(3); break;
        case 17: o->struct_size = fz_r(2) ? fz_r(sizeof *o) : sizeof *o + fz_r(256); break;
        case 18: o->bound_level = fz_enum(3); break;
        default: o->target = fz_r(4); break;
        }
    }
    if (o->struct_size < sizeof *o) {
        fz.call_null |= 0; /* refused with CAGD_ERR_INVALID_ARGUMENT, not asserted */
    }
    return o;
}

/* A side call (made to check another call's result, or to seed a pool): its status is
 * checked against its own function's doc comment. */
#define SIDE(name, expr) fz_status_of(FN_##name, expr)

/* The report oracle: a bound is finite and >= 0, a measured error finite, >= 0 and not
 * above the bound. */
static double check_report(const struct CagdReport *rep) {
    double b = -1.0, e = -1.0;
    CagdStatus sb = SIDE(cagd_report_bound, cagd_report_bound(rep, &b));
    CagdStatus se = SIDE(cagd_report_max_error, cagd_report_max_error(rep, &e));
    if (sb == CAGD_OK && (!isfinite(b) || b < 0.0)) {
        fz_fail("report bound %g is not finite and >= 0", b);
    }
    if (se == CAGD_OK && (!isfinite(e) || e < 0.0)) {
        fz_fail("report max_error %g is not finite and >= 0", e);
    }
    if (sb == CAGD_OK && se == CAGD_OK && e > b * (1.0 + 1e-12)) {
        fz_fail("measured error %.17g exceeds the certified bound %.17g", e, b);
    }
    /* A B-spline report's step bound, checked here so that a violation names the
     * function that made the report (not a later cagd_report_spline call). */
    double seg = -1.0;
    size_t pieces = 0, si = 0, so = 0;
    CagdStatus ss = SIDE(cagd_report_spline, cagd_report_spline(rep, &seg, &pieces, &si, &so));
    if (ss == CAGD_OK && (!isfinite(seg) || seg < 0.0)) {
        fz_fail("report segment bound %g is not finite and >= 0", seg);
    }
    return sb == CAGD_OK ? b : -1.0;
}

static void keep_report(CagdStatus st, struct CagdReport *rep, int rep_n) {
    if (st == CAGD_OK && rep != NULL) {
        check_report(rep);
    }
    fz_handle_out(FZ_REPORT, st, rep, rep_n);
}

/* ||a - b|| without overflow of the squares (coordinates near 1e300 made the harness's
 * own measurement +inf beside a finite bound of 1.6e288). */
static double diff_norm(const double *a, const double *b, size_t dim) {
    double s = 0.0;
    for (size_t k = 0; k < dim; ++k) s = fmax(s, fabs(a[k] - b[k]));
    if (s == 0.0 || !isfinite(s)) return s;
    double q = 0.0;
    for (size_t k = 0; k < dim; ++k) q += ((a[k] - b[k]) / s) * ((a[k] - b[k]) / s);
    return s * sqrt(q);
}

/* An independent check of a Bézier reduction: the distance of source and result at 129
 * parameters must not exceed the certified bound (Euclidean space only). */
static void check_curve_bound(const struct CagdCurve *src, const struct CagdCurve *dst,
                              const struct CagdReport *rep) {
    double bound = -1.0;
    int32_t space = -1;
    double hb = 0.0;
    if (cagd_report_bound(rep, &bound) != CAGD_OK) {
        return;
    }
    if (cagd_report_space(rep, &space, &hb) == CAGD_OK && space != CAGD_SPACE_EUCLIDEAN) {
        return;
    }
    size_t dim = 0, need = 0;
    if (cagd_curve_dim(src, &dim) != CAGD_OK || dim == 0 || dim > 16) {
        return;
    }
    double scale = 0.0;
    static double pts[FZ_IN_CAP / 4];
    if (cagd_curve_points(src, pts, FZ_IN_CAP / 4, &need) == CAGD_OK) {
        for (size_t i = 0; i < need; ++i) {
            scale = fmax(scale, fabs(pts[i]));
        }
    }
    /* Both curves at the 129 parameters in one call each (129 calls each were most of
     * the harness's own time in a reduction's operation). */
    static double ts[129], a[129 * 16], b[129 * 16];
    if (ts[128] != 1.0) {
        for (int i = 0; i <= 128; ++i) ts[i] = (double)i / 128.0;
    }
    if (cagd_curve_eval_many(src, ts, 129, a, 129 * 16, &need) != CAGD_OK ||
        cagd_curve_eval_many(dst, ts, 129, b, 129 * 16, &need) != CAGD_OK) {
        return;
    }
    double worst = 0.0;
    for (size_t i = 0; i <= 128; ++i) {
        worst = fmax(worst, diff_norm(a + i * dim, b + i * dim, dim));
    }
    if (worst > bound * (1.0 + 1e-9) + 1e-12 * scale + 1e-300) {
        fz_fail("measured distance %.17g at 129 parameters exceeds the certified bound %.17g",
                worst, bound);
    }
}

static size_t curve_degree(const struct CagdCurve *c, size_t dflt) {
    size_t d;
    return c != NULL && cagd_curve_degree(c, &d) == CAGD_OK ? d : dflt;
}

static void tensor_shape(const struct CagdTensorPatch *p, size_t *m, size_t *n) {
    size_t dim;
    if (p == NULL || cagd_tensorpatch_shape(p, m, n, &dim) != CAGD_OK) {
        *m = fz_r(4);
        *n = fz_r(4);
    }
}

static size_t tri_degree(const struct CagdTriPatch *p) {
    size_t d, dim;
    return p != NULL && cagd_tripatch_shape(p, &d, &dim) == CAGD_OK ? d : fz_r(4);
}

/* ---------------------------------------------------------------- multi-buffer copies */

/* The copy functions (cagd_*_copy) fill several caller buffers at once and report the
 * sizes in a struct. Each buffer lives in its own region of mb_store (doubles and
 * size_t alike: 8 bytes each), poisoned before the call. */
#define MB_MAX 6
#define MB_STRIDE 4096
static double mb_store[MB_MAX][MB_STRIDE + 16];

static double mb_poison(void) {
    const uint64_t bits = 0x7FF4DEADBEEF0002ull;
    double d;
    memcpy(&d, &bits, sizeof d);
    return d;
}

static int mb_is_poison(double d) {
    uint64_t b;
    memcpy(&b, &d, sizeof b);
    return b == 0x7FF4DEADBEEF0002ull;
}

typedef struct Mb {
    void *p;
    size_t cap;
    int misaligned;
} Mb;

/* Poisons the part of buffer k that mb_check reads: `cap + 8` elements (all of the
 * store once was 197 KB of writes per copy call). A misaligned buffer is not checked. */
static void mb_poison_buf(const Mb *b, size_t k) {
    if (b->p == NULL || b->misaligned) return;
    size_t n = b->cap + 8 < MB_STRIDE + 16 ? b->cap + 8 : MB_STRIDE + 16;
    for (size_t i = 0; i < n; ++i) mb_store[k][i] = mb_poison();
}

/* A random buffer k: size query, NULL with a capacity, short, misaligned or roomy. */
static void mb_draw(Mb *b, size_t k) {
    b->misaligned = 0;
    switch (fz_r(12)) {
    case 0:
        b->p = NULL;
        b->cap = 0;
        break;
    case 1:
        b->p = NULL;
        b->cap = 1 + fz_r(8);
        fz.call_null = 1;
        break;
    case 2:
        b->p = mb_store[k];
        b->cap = fz_r(8);
        break;
    case 3:
        b->p = (char *)mb_store[k] + 4;
        b->cap = 1 + fz_r(64);
        b->misaligned = 1;
        fz.call_misaligned = 1;
        break;
    default:
        b->p = mb_store[k];
        b->cap = MB_STRIDE;
        break;
    }
}

/* Exactly `len` elements (NULL when 0 now and then); 0 when it does not fit. */
static int mb_exact(Mb *b, size_t k, size_t len) {
    b->misaligned = 0;
    if (len > MB_STRIDE) return 0;
    b->p = len == 0 && fz_r(2) ? NULL : mb_store[k];
    b->cap = len;
    return 1;
}

/* After CAGD_OK: the first `len` elements written (finite doubles when `dbl`), nothing
 * after them. After a failure: nothing written. */
static void mb_check(const Mb *b, size_t k, CagdStatus st, size_t len, int dbl,
                     const char *what) {
    if (b->p == NULL || b->misaligned) return;
    const double *d = mb_store[k];
    if (st != CAGD_OK) {
        for (size_t i = 0; i < b->cap + 8 && i < MB_STRIDE + 16; ++i) {
            if (!mb_is_poison(d[i])) fz_fail("%s[%zu] written on failure", what, i);
        }
        return;
    }
    if (len > b->cap) fz_fail("CAGD_OK but %s needs %zu > capacity %zu", what, len, b->cap);
    for (size_t i = 0; i < len; ++i) {
        if (mb_is_poison(d[i])) fz_fail("CAGD_OK but %s[%zu] of %zu not written", what, i, len);
        if (dbl && !isfinite(d[i])) fz_fail("CAGD_OK but %s[%zu] = %g", what, i, d[i]);
    }
    for (size_t i = len; i < b->cap + 8 && i < len + 8; ++i) {
        if (!mb_is_poison(d[i])) fz_fail("%s[%zu] written beyond its %zu", what, i, len);
    }
}

/* BUFFER_TOO_SMALL must name a buffer whose capacity is below its length. */
static void mb_too_small(CagdStatus st, const Mb *b, const size_t *len, size_t n) {
    if (st != CAGD_ERR_BUFFER_TOO_SMALL) return;
    for (size_t k = 0; k < n; ++k) {
        if (b[k].cap < len[k]) return;
    }
    fz_fail("CAGD_ERR_BUFFER_TOO_SMALL but every capacity holds its size");
}

typedef CagdStatus (*MbCall)(Mb *b, void *sizes);
typedef void (*MbLens)(const void *sizes, size_t *len);
static const void *mb_h; /* the handle of the current copy */

/* One copy call (or a size query and then exactly the sizes it gave): `n` buffers,
 * `dbl[k]` when buffer k holds doubles; `len` receives the lengths of the sizes. */
static CagdStatus mb_run(size_t n, const int *dbl, const char *const *names, MbCall call,
                         MbLens lens, void *sizes, size_t sizes_bytes, size_t *len, Mb *b) {
    int sizes_null = fz_r(48) == 0;
    fz.call_null |= sizes_null;
    int exact = fz_r(3) == 0;
    CagdStatus st = CAGD_OK;
    for (size_t k = 0; k < n; ++k) len[k] = 0;
    for (int phase = 0;; ++phase) {
        if (exact && phase == 1) {
            int fits = 1;
            for (size_t k = 0; k < n; ++k) fits &= len[k] <= MB_STRIDE;
            if (!fits) break;
        }
        memset(sizes, 0xFF, sizes_bytes);
        for (size_t k = 0; k < n; ++k) {
            if (!exact) {
                mb_draw(&b[k], k);
            } else if (phase == 0) {
                b[k].p = NULL;
                b[k].cap = 0;
                b[k].misaligned = 0;
            } else {
                (void)mb_exact(&b[k], k, len[k]);
            }
            mb_poison_buf(&b[k], k);
        }
        st = fz_status(call(b, sizes_null ? NULL : sizes));
        if ((st == CAGD_OK || st == CAGD_ERR_BUFFER_TOO_SMALL) && !sizes_null) {
            lens(sizes, len);
        } else {
            for (size_t k = 0; k < n; ++k) len[k] = 0;
        }
        if (exact && phase == 1 && st == CAGD_ERR_BUFFER_TOO_SMALL) {
            fz_fail("buffers of exactly the queried sizes are too small");
        }
        if (!(exact && phase == 0 && st == CAGD_ERR_BUFFER_TOO_SMALL && !sizes_null)) break;
    }
    if (!sizes_null) mb_too_small(st, b, len, n);
    for (size_t k = 0; k < n; ++k) mb_check(&b[k], k, st, len[k], dbl[k], names[k]);
    return st;
}

static size_t mb_sz(size_t k, size_t i) { return ((const size_t *)(const void *)mb_store[k])[i]; }

#define MB_SZ(k) ((size_t *)b[k].p), b[k].cap
#define MB_D(k) ((double *)b[k].p), b[k].cap

/* ---------------------------------------------------------------- curves */

static void op_cagd_curve_new(void) {
    size_t deg = fz_deg(), dim = fz_dim(), n = fz_count(fz_add(deg, 1));
    const double *pts = fz_in(fz_mul(n, dim), FZ_VALUES);
    SKIP_IF_NEEDED;
    OUT_H(CagdCurve, c);
    CagdStatus st = fz_status(cagd_curve_new(pts, n, dim, HP(c)));
    KEEP(FZ_CURVE, c);
}

static void op_cagd_curve_new_rational(void) {
    size_t deg = fz_deg(), dim = fz_dim(), n = fz_count(fz_add(deg, 1));
    const double *pts = fz_in(fz_mul(n, dim), FZ_VALUES);
    const double *w = fz_in(n, FZ_WEIGHTS);
    SKIP_IF_NEEDED;
    OUT_H(CagdCurve, c);
    CagdStatus st = fz_status(cagd_curve_new_rational(pts, w, n, dim, HP(c)));
    KEEP(FZ_CURVE, c);
}

static void op_cagd_curve_free(void) {
    cagd_curve_free((struct CagdCurve *)fz_take(FZ_CURVE));
    fz_status(CAGD_OK);
}

static void op_cagd_curve_degree(void) {
    IN_H(FZ_CURVE, CagdCurve, c);
    OUT_S(size_t, d);
    CagdStatus st = fz_status(cagd_curve_degree(c, SP(d)));
    (void)st;
}

static void op_cagd_curve_dim(void) {
    IN_H(FZ_CURVE, CagdCurve, c);
    OUT_S(size_t, d);
    CagdStatus st = fz_status(cagd_curve_dim(c, SP(d)));
    if (st == CAGD_OK && d == 0) fz_fail("dim 0");
}

static void op_cagd_curve_is_rational(void) {
    IN_H(FZ_CURVE, CagdCurve, c);
    OUT_S(bool, r);
    CagdStatus st = fz_status(cagd_curve_is_rational(c, SP(r)));
    (void)st;
}

static void op_cagd_curve_points(void) {
    IN_H(FZ_CURVE, CagdCurve, c);
    FzOb ob;
    CagdStatus st;
    OUTCALL(ob, cagd_curve_points(c, ob.p, ob.cap, ob.needed_p));
}

static void op_cagd_curve_weights(void) {
    IN_H(FZ_CURVE, CagdCurve, c);
    FzOb ob;
    CagdStatus st;
    OUTCALL(ob, cagd_curve_weights(c, ob.p, ob.cap, ob.needed_p));
}

static void op_cagd_curve_eval(void) {
    IN_H(FZ_CURVE, CagdCurve, c);
    double t = fz_param();
    FzOb ob;
    CagdStatus st;
    OUTCALL(ob, cagd_curve_eval(c, t, ob.p, ob.cap, ob.needed_p));
}

static void op_cagd_curve_eval_many(void) {
    IN_H(FZ_CURVE, CagdCurve, c);
    size_t n = fz_count(1 + fz_r(16));
    const double *ts = fz_in(n, FZ_PARAMS);
    SKIP_IF_NEEDED;
    FzOb ob;
    CagdStatus st;
    OUTCALL(ob, cagd_curve_eval_many(c, ts, n, ob.p, ob.cap, ob.needed_p));
}

static void op_cagd_curve_elevate(void) {
    IN_H(FZ_CURVE, CagdCurve, c);
    size_t r = fz_small_deg();
    OUT_H(CagdCurve, o);
    CagdStatus st = fz_status(cagd_curve_elevate(c, r, HP(o)));
    KEEP(FZ_CURVE, o);
}

static void op_cagd_curve_subdivide(void) {
    IN_H(FZ_CURVE, CagdCurve, c);
    double t = fz_param();
    OUT_H(CagdCurve, l);
    OUT_H(CagdCurve, r);
    CagdStatus st = fz_status(cagd_curve_subdivide(c, t, HP(l), HP(r)));
    KEEP(FZ_CURVE, l);
    KEEP(FZ_CURVE, r);
}

static void op_cagd_curve_segment(void) {
    IN_H(FZ_CURVE, CagdCurve, c);
    double a = fz_param(), b = fz_param();
    OUT_H(CagdCurve, o);
    CagdStatus st = fz_status(cagd_curve_segment(c, a, b, HP(o)));
    KEEP(FZ_CURVE, o);
}

static void op_cagd_curve_implicitize(void) {
    IN_H(FZ_CURVE, CagdCurve, c);
    int32_t div = fz_r(8) ? (int32_t)fz_r(2) : (int32_t)fz_u64();
    OUT_H(CagdImplicit, o);
    CagdStatus st = fz_status(cagd_curve_implicitize(c, div, HP(o)));
    KEEP(FZ_IMPLICIT, o);
}

static void op_cagd_curve_intersect(void) {
    IN_H(FZ_CURVE, CagdCurve, a);
    IN_H(FZ_CURVE, CagdCurve, b);
    FzOb ob;
    CagdStatus st;
    OUTCALL(ob, cagd_curve_intersect(a, b, ob.p, ob.cap, ob.needed_p));
    if (st == CAGD_OK && ob.needed % CAGD_INTERSECTION_STRIDE != 0) {
        fz_fail("%zu doubles is not a multiple of CAGD_INTERSECTION_STRIDE", ob.needed);
    }
}

static void op_cagd_curve_forward_difference(void) {
    IN_H(FZ_CURVE, CagdCurve, c);
    FzOb ob;
    CagdStatus st;
    OUTCALL(ob, cagd_curve_forward_difference(c, ob.p, ob.cap, ob.needed_p));
}

static void op_cagd_curve_distance(void) {
    IN_H(FZ_CURVE, CagdCurve, a);
    IN_H(FZ_CURVE, CagdCurve, b);
    OUT_S(double, d);
    CagdStatus st = fz_status(cagd_curve_distance(a, b, SP(d)));
    FIN(d);
}

static void op_cagd_curve_standard_form(void) {
    IN_H(FZ_CURVE, CagdCurve, c);
    OUT_H(CagdCurve, o);
    OUT_SO(double, rho);
    CagdStatus st = fz_status(cagd_curve_standard_form(c, HP(o), SP(rho)));
    FIN(rho);
    KEEP(FZ_CURVE, o);
}

static void op_cagd_curve_exact_degree(void) {
    IN_H(FZ_CURVE, CagdCurve, c);
    double tol = fz_r(4) ? fz_tol() : 0.0;
    OUT_S(size_t, d);
    CagdStatus st = fz_status(cagd_curve_exact_degree(c, tol, SP(d)));
    if (st == CAGD_OK && d > curve_degree(c, SIZE_MAX)) fz_fail("exact degree %zu > degree", d);
}

static void op_cagd_curve_reduce(void) {
    IN_H(FZ_CURVE, CagdCurve, c);
    const CagdReduceOptions *o = gen_opts();
    OUT_H(CagdCurve, out);
    OUT_H(CagdReport, rep);
    CagdStatus st = fz_status(cagd_curve_reduce(c, o, HP(out), HP(rep)));
    if (st == CAGD_OK) check_curve_bound(c, out, rep);
    KEEP(FZ_CURVE, out);
    keep_report(st, rep, rep_n);
}

static void op_cagd_curve_reduce_batch_bounded(void) {
    size_t nc = fz_count(1 + fz_r(4)), deg = fz_deg(), dim = fz_dim();
    const double *pts = fz_in(fz_mul(fz_mul(nc, fz_add(deg, 1)), dim), FZ_VALUES);
    SKIP_IF_NEEDED;
    const CagdReduceOptions *o = gen_opts();
    /* bounds_out: NULL (no bounds) or a buffer of n_curves doubles (poisoned) */
    static double bounds[4096 + 8];
    double *bp = NULL;
    if (nc <= 4096 && fz_r(2)) {
        bp = bounds;
        for (size_t i = 0; i < nc + 8; ++i) bounds[i] = mb_poison();
    }
    FzOb ob;
    CagdStatus st;
    OUTCALL(ob, cagd_curve_reduce_batch_bounded(pts, nc, deg, dim, o, ob.p, ob.cap, ob.needed_p, bp));
    if (st == CAGD_OK && bp != NULL) {
        if (o->bound_level != CAGD_BOUND_FAST && o->bound_level != CAGD_BOUND_TIGHT) {
            fz_fail("CAGD_OK with bounds_out and bound_level %d", (int)o->bound_level);
        }
        for (size_t i = 0; i < nc; ++i) {
            if (mb_is_poison(bounds[i])) fz_fail("bounds_out[%zu] of %zu not written", i, nc);
            /* documented: "+inf only if the computation overflowed" (no NaN, no sign) */
            if (isnan(bounds[i]) || bounds[i] < 0.0 || bounds[i] == -INFINITY)
                fz_fail("bounds_out[%zu] = %g is not a bound (>= 0 or +inf)", i, bounds[i]);
        }
        if (!mb_is_poison(bounds[nc])) fz_fail("bounds_out written beyond n_curves = %zu", nc);
    }
    /* not written on failure, but for an overflow of the reduced points (documented) */
    if (st != CAGD_OK && st != CAGD_ERR_NON_FINITE && bp != NULL) {
        for (size_t i = 0; i < nc; ++i) {
            if (!mb_is_poison(bounds[i])) fz_fail("bounds_out[%zu] written on failure", i);
        }
    }
}

static void op_cagd_curve_reduce_batch(void) {
    size_t nc = fz_count(1 + fz_r(4)), deg = fz_deg(), dim = fz_dim();
    const double *pts = fz_in(fz_mul(fz_mul(nc, fz_add(deg, 1)), dim), FZ_VALUES);
    SKIP_IF_NEEDED;
    const CagdReduceOptions *o = gen_opts();
    FzOb ob;
    CagdStatus st;
    OUTCALL(ob, cagd_curve_reduce_batch(pts, nc, deg, dim, o, ob.p, ob.cap, ob.needed_p));
    (void)st;
}

static void op_cagd_curve_reduce_exact(void) {
    IN_H(FZ_CURVE, CagdCurve, c);
    OUT_H(CagdCurve, out);
    OUT_H(CagdReport, rep);
    CagdStatus st = fz_status(cagd_curve_reduce_exact(c, HP(out), HP(rep)));
    if (st == CAGD_OK) check_curve_bound(c, out, rep);
    KEEP(FZ_CURVE, out);
    keep_report(st, rep, rep_n);
}

static void op_cagd_curve_reduce_g1_optimal(void) {
    IN_H(FZ_CURVE, CagdCurve, c);
    bool measure = fz_r(2);
    OUT_H(CagdCurve, out);
    OUT_H(CagdReport, rep);
    CagdStatus st = fz_status(cagd_curve_reduce_g1_optimal(c, measure, HP(out), HP(rep)));
    if (st == CAGD_OK) check_curve_bound(c, out, rep);
    KEEP(FZ_CURVE, out);
    keep_report(st, rep, rep_n);
}

/* An independent check of a reduction to a tolerance: the spline has degree `target` and
 * the curve's dimension on [0, 1], its certified bound is within the tolerance, and the
 * distance of curve and spline at 129 parameters does not exceed the bound. With
 * `steps` (the stepwise algorithm), its `n - target` step bounds are finite and >= 0 (each
 * is a certified bound of the step, which may exceed the seed's a-priori share
 * `tolerance / (n - target)`: the certified total is checked against the tolerance). */
static void check_tolerance_spline(const struct CagdCurve *src, const struct CagdBSpline *spl,
                                   const struct CagdReport *rep, const CagdReduceOptions *o,
                                   int steps) {
    double bound = -1.0;
    size_t dim = 0, sdim = 0, deg = 0, n = 0, need = 0;
    if (cagd_report_bound(rep, &bound) != CAGD_OK || cagd_curve_dim(src, &dim) != CAGD_OK ||
        cagd_curve_degree(src, &n) != CAGD_OK || dim == 0 || dim > 16) {
        return;
    }
    if (cagd_bspline_degree(spl, &deg) != CAGD_OK || cagd_bspline_dim(spl, &sdim) != CAGD_OK ||
        deg != o->target || sdim != dim) {
        fz_fail("spline of degree %zu, dim %zu for target %zu, dim %zu", deg, sdim, o->target,
                dim);
    }
    double a = -1.0, b = -1.0;
    if (cagd_bspline_domain(spl, &a, &b) != CAGD_OK || a != 0.0 || b != 1.0) {
        fz_fail("spline domain [%g, %g], not [0, 1]", a, b);
    }
    if (!(bound <= o->tolerance)) {
        fz_fail("certified bound %.17g above the tolerance %.17g", bound, o->tolerance);
    }
    if (steps) {
        static double sb[160];
        if (cagd_report_step_bounds(rep, sb, 160, &need) == CAGD_OK) {
            if (need != n - o->target) fz_fail("%zu step bounds for %zu steps", need, n - o->target);
            for (size_t i = 0; i < need; ++i) {
                if (!isfinite(sb[i]) || sb[i] < 0.0) {
                    fz_fail("step bound %zu = %.17g is not finite and >= 0", i, sb[i]);
                }
            }
        }
    }
    double scale = 0.0;
    static double pts[FZ_IN_CAP / 4];
    if (cagd_curve_points(src, pts, FZ_IN_CAP / 4, &need) == CAGD_OK) {
        for (size_t i = 0; i < need; ++i) scale = fmax(scale, fabs(pts[i]));
    }
    static double ts[129], pa[129 * 16], pb[16];
    for (int i = 0; i <= 128; ++i) ts[i] = (double)i / 128.0;
    if (cagd_curve_eval_many(src, ts, 129, pa, 129 * 16, &need) != CAGD_OK) return;
    double worst = 0.0;
    for (size_t i = 0; i <= 128; ++i) {
        if (cagd_bspline_eval(spl, ts[i], pb, 16, &need) != CAGD_OK) return;
        worst = fmax(worst, diff_norm(pa + i * dim, pb, dim));
    }
    if (worst > bound * (1.0 + 1e-9) + 1e-12 * scale + 1e-300) {
        fz_fail("measured distance %.17g at 129 parameters exceeds the certified bound %.17g",
                worst, bound);
    }
}

static void op_cagd_curve_reduce_to_tolerance(void) {
    IN_H(FZ_CURVE, CagdCurve, c);
    const CagdReduceOptions *o = gen_opts();
    OUT_H(CagdBSpline, out);
    OUT_H(CagdReport, rep);
    CagdStatus st = fz_status(cagd_curve_reduce_to_tolerance(c, o, HP(out), HP(rep)));
    if (st == CAGD_OK) check_tolerance_spline(c, out, rep, o, 0);
    KEEP(FZ_BSPLINE, out);
    keep_report(st, rep, rep_n);
}

static void op_cagd_curve_reduce_to_tolerance_stepwise(void) {
    IN_H(FZ_CURVE, CagdCurve, c);
    const CagdReduceOptions *o = gen_opts();
    /* Random options almost never meet the algorithm's preconditions (method
     * CAGD_METHOD_PERTURB, continuity 0, 0 < target < n, a tolerance): 1 CAGD_OK in 17 000
     * calls. Now and then options that can succeed. */
    size_t n = curve_degree(c, 0);
    if (o != NULL && n >= 2 && fz_r(3) == 0) {
        CagdReduceOptions *w = &opts_store.o;
        w->method = CAGD_METHOD_PERTURB;
        w->continuity = 0;
        w->target = 1 + fz_r(n - 1 < 8 ? n - 1 : 8);
        w->tolerance = fz_r(4) ? pow(10.0, -1.0 - 4.0 * fz_unit()) : fz_tol();
    }
    OUT_H(CagdBSpline, out);
    OUT_H(CagdReport, rep);
    CagdStatus st =
        fz_status(cagd_curve_reduce_to_tolerance_stepwise(c, o, HP(out), HP(rep)));
    if (st == CAGD_OK) check_tolerance_spline(c, out, rep, o, 1);
    KEEP(FZ_BSPLINE, out);
    keep_report(st, rep, rep_n);
}

static void op_cagd_reduce_operator(void) {
    const CagdReduceOptions *o = gen_opts();
    size_t deg = fz_deg();
    FzOb ob;
    CagdStatus st;
    OUTCALL(ob, cagd_reduce_operator(o, deg, ob.p, ob.cap, ob.needed_p));
}

static void op_cagd_reduce_options_init(void) {
    CagdReduceOptions o;
    int n = fz_r(48) == 0;
    fz.call_null |= n;
    CagdStatus st = fz_status(cagd_reduce_options_init(n ? NULL : &o));
    if (st == CAGD_OK && o.struct_size != sizeof o) fz_fail("struct_size %zu", o.struct_size);
}

/* ---------------------------------------------------------------- curve lists */

static void op_cagd_curvelist_free(void) {
    cagd_curvelist_free((struct CagdCurveList *)fz_take(FZ_CURVELIST));
    fz_status(CAGD_OK);
}

static size_t list_count(FzType t, const void *l) {
    size_t n = 0;
    if (l == NULL) return 0;
    switch (t) {
    case FZ_CURVELIST: (void)cagd_curvelist_count(l, &n); break;
    case FZ_PPLIST: (void)cagd_patchpiecelist_count(l, &n); break;
    case FZ_TENSORLIST: (void)cagd_tensorpatchlist_count(l, &n); break;
    case FZ_TRILIST: (void)cagd_tripatchlist_count(l, &n); break;
    case FZ_WSGBLIST: (void)cagd_wsgblist_count(l, &n); break;
    default: break;
    }
    return n;
}

static void op_cagd_curvelist_count(void) {
    IN_H(FZ_CURVELIST, CagdCurveList, l);
    OUT_S(size_t, n);
    CagdStatus st = fz_status(cagd_curvelist_count(l, SP(n)));
    (void)st;
}

static void op_cagd_curvelist_get(void) {
    IN_H(FZ_CURVELIST, CagdCurveList, l);
    size_t i = fz_index(list_count(FZ_CURVELIST, l));
    OUT_H(CagdCurve, c);
    CagdStatus st = fz_status(cagd_curvelist_get(l, i, HP(c)));
    KEEP(FZ_CURVE, c);
}

static void op_cagd_curvelist_interval(void) {
    IN_H(FZ_CURVELIST, CagdCurveList, l);
    size_t i = fz_index(list_count(FZ_CURVELIST, l));
    OUT_S(double, a);
    OUT_S(double, b);
    CagdStatus st = fz_status(cagd_curvelist_interval(l, i, SP(a), SP(b)));
    FIN(a);
    FIN(b);
    if (st == CAGD_OK && !(a < b)) fz_fail("interval [%g, %g] is empty", a, b);
}

static void op_cagd_curvelist_bound(void) {
    IN_H(FZ_CURVELIST, CagdCurveList, l);
    size_t i = fz_index(list_count(FZ_CURVELIST, l));
    OUT_S(double, b);
    CagdStatus st = fz_status(cagd_curvelist_bound(l, i, SP(b)));
    FIN(b);
    if (st == CAGD_OK && b < 0.0) fz_fail("negative bound %g", b);
}

static void op_cagd_curvelist_to_bspline(void) {
    IN_H(FZ_CURVELIST, CagdCurveList, l);
    double tol = fz_tol();
    OUT_H(CagdBSpline, s);
    CagdStatus st = fz_status(cagd_curvelist_to_bspline(l, tol, HP(s)));
    KEEP(FZ_BSPLINE, s);
}

/* ---------------------------------------------------------------- B-splines */

static void op_cagd_bspline_new(void) {
    size_t deg = fz_deg(), dim = fz_dim(), n = fz_count(fz_add(deg, 1 + fz_r(4)));
    size_t nk = fz_count(fz_add(fz_add(n, deg), 1));
    const double *knots = fz_knots(nk, deg);
    const double *pts = fz_in(fz_mul(n, dim), FZ_VALUES);
    SKIP_IF_NEEDED;
    OUT_H(CagdBSpline, s);
    CagdStatus st = fz_status(cagd_bspline_new(deg, knots, nk, pts, n, dim, HP(s)));
    KEEP(FZ_BSPLINE, s);
}

static void op_cagd_bspline_new_rational(void) {
    size_t deg = fz_deg(), dim = fz_dim(), n = fz_count(fz_add(deg, 1 + fz_r(4)));
    size_t nk = fz_count(fz_add(fz_add(n, deg), 1));
    const double *knots = fz_knots(nk, deg);
    const double *pts = fz_in(fz_mul(n, dim), FZ_VALUES);
    const double *w = fz_in(n, FZ_WEIGHTS);
    SKIP_IF_NEEDED;
    OUT_H(CagdBSpline, s);
    CagdStatus st =
        fz_status(cagd_bspline_new_rational(deg, knots, nk, pts, w, n, dim, HP(s)));
    KEEP(FZ_BSPLINE, s);
}

static void op_cagd_bspline_free(void) {
    cagd_bspline_free((struct CagdBSpline *)fz_take(FZ_BSPLINE));
    fz_status(CAGD_OK);
}

static void op_cagd_bspline_degree(void) {
    IN_H(FZ_BSPLINE, CagdBSpline, s);
    OUT_S(size_t, d);
    CagdStatus st = fz_status(cagd_bspline_degree(s, SP(d)));
    (void)st;
}

static void op_cagd_bspline_dim(void) {
    IN_H(FZ_BSPLINE, CagdBSpline, s);
    OUT_S(size_t, d);
    CagdStatus st = fz_status(cagd_bspline_dim(s, SP(d)));
    if (st == CAGD_OK && d == 0) fz_fail("dim 0");
}

static void op_cagd_bspline_n_points(void) {
    IN_H(FZ_BSPLINE, CagdBSpline, s);
    OUT_S(size_t, n);
    CagdStatus st = fz_status(cagd_bspline_n_points(s, SP(n)));
    (void)st;
}

static void op_cagd_bspline_is_rational(void) {
    IN_H(FZ_BSPLINE, CagdBSpline, s);
    OUT_S(bool, r);
    CagdStatus st = fz_status(cagd_bspline_is_rational(s, SP(r)));
    (void)st;
}

static void op_cagd_bspline_domain(void) {
    IN_H(FZ_BSPLINE, CagdBSpline, s);
    OUT_S(double, a);
    OUT_S(double, b);
    CagdStatus st = fz_status(cagd_bspline_domain(s, SP(a), SP(b)));
    FIN(a);
    FIN(b);
    if (st == CAGD_OK && !(a < b)) fz_fail("domain [%g, %g] is empty", a, b);
}

static void op_cagd_bspline_knots(void) {
    IN_H(FZ_BSPLINE, CagdBSpline, s);
    FzOb ob;
    CagdStatus st;
    OUTCALL(ob, cagd_bspline_knots(s, ob.p, ob.cap, ob.needed_p));
}

static void op_cagd_bspline_points(void) {
    IN_H(FZ_BSPLINE, CagdBSpline, s);
    FzOb ob;
    CagdStatus st;
    OUTCALL(ob, cagd_bspline_points(s, ob.p, ob.cap, ob.needed_p));
}

static void op_cagd_bspline_weights(void) {
    IN_H(FZ_BSPLINE, CagdBSpline, s);
    FzOb ob;
    CagdStatus st;
    OUTCALL(ob, cagd_bspline_weights(s, ob.p, ob.cap, ob.needed_p));
}

static void op_cagd_bspline_from_beziers(void) {
    const struct CagdCurve *segs[8];
    struct CagdCurve *tmp[9];
    size_t n_tmp = 0;
    size_t good = 1 + fz_r(4);
    size_t count = fz_r(16) == 0 ? (fz_r(2) ? 0 : (size_t)1 << 61) : good;
    for (size_t i = 0; i < 8; ++i) segs[i] = fz_pick(FZ_CURVE);
    if (fz_r(2)) {
        /* segments that join: the pieces of one curve cut at increasing parameters (kept
         * out of the pools until after the call, so that no pool eviction frees them) */
        const struct CagdCurve *c = fz_pick(FZ_CURVE);
        struct CagdCurve *rest = NULL;
        if (c != NULL && cagd_curve_segment(c, 0.0, 1.0, &rest) == CAGD_OK) {
            for (size_t i = 0; i < good; ++i) {
                struct CagdCurve *l = NULL, *r = NULL;
                double t = 1.0 / (double)(good - i);
                if (t < 1.0 && cagd_curve_subdivide(rest, t, &l, &r) == CAGD_OK) {
                    tmp[n_tmp++] = l;
                    segs[i] = l;
                    cagd_curve_free(rest);
                    rest = r;
                } else {
                    segs[i] = rest;
                }
            }
            tmp[n_tmp++] = rest;
        }
    }
    int segs_null = fz_r(48) == 0;
    for (size_t i = 0; i < good && i < count; ++i) fz.call_null |= segs[i] == NULL;
    fz.call_null |= segs_null;
    const double *breaks = fz_in_opt(count == good ? count + 1 : 2, FZ_SORTED);
    size_t k = fz_r(4);
    double tol = fz_r(4) ? 1e-9 : fz_tol();
    if (!fz.skip) {
        OUT_H(CagdBSpline, s);
        CagdStatus st = fz_status(cagd_bspline_from_beziers(segs_null ? NULL : segs, count,
                                                            breaks, k, tol, HP(s)));
        KEEP(FZ_BSPLINE, s);
    }
    for (size_t i = 0; i < n_tmp; ++i) fz_put(FZ_CURVE, tmp[i]);
}

static void op_cagd_bspline_eval(void) {
    IN_H(FZ_BSPLINE, CagdBSpline, s);
    double t = fz_param();
    FzOb ob;
    CagdStatus st;
    OUTCALL(ob, cagd_bspline_eval(s, t, ob.p, ob.cap, ob.needed_p));
}

static void op_cagd_bspline_derivatives(void) {
    IN_H(FZ_BSPLINE, CagdBSpline, s);
    double t = fz_param();
    size_t order = fz_small_deg();
    FzOb ob;
    CagdStatus st;
    OUTCALL(ob, cagd_bspline_derivatives(s, t, order, ob.p, ob.cap, ob.needed_p));
}

static void op_cagd_bspline_insert_knot(void) {
    IN_H(FZ_BSPLINE, CagdBSpline, s);
    double t = fz_param();
    size_t times = fz_small_deg();
    OUT_H(CagdBSpline, o);
    CagdStatus st = fz_status(cagd_bspline_insert_knot(s, t, times, HP(o)));
    KEEP(FZ_BSPLINE, o);
}

static void op_cagd_bspline_to_beziers(void) {
    IN_H(FZ_BSPLINE, CagdBSpline, s);
    OUT_H(CagdCurveList, l);
    CagdStatus st = fz_status(cagd_bspline_to_beziers(s, HP(l)));
    KEEP(FZ_CURVELIST, l);
}

static void op_cagd_bspline_to_bezier_pieces(void) {
    IN_H(FZ_BSPLINE, CagdBSpline, s);
    OUT_H(CagdCurveList, l);
    CagdStatus st = fz_status(cagd_bspline_to_bezier_pieces(s, HP(l)));
    KEEP(FZ_CURVELIST, l);
}

static void op_cagd_bspline_reduce(void) {
    IN_H(FZ_BSPLINE, CagdBSpline, s);
    const CagdReduceOptions *o = gen_opts();
    OUT_H(CagdBSpline, out);
    OUT_H(CagdReport, rep);
    CagdStatus st = fz_status(cagd_bspline_reduce(s, o, HP(out), HP(rep)));
    KEEP(FZ_BSPLINE, out);
    keep_report(st, rep, rep_n);
}

static void op_cagd_bspline_reduce_uniform(void) {
    IN_H(FZ_BSPLINE, CagdBSpline, s);
    const CagdReduceOptions *o = gen_opts();
    OUT_H(CagdBSpline, out);
    OUT_H(CagdReport, rep);
    CagdStatus st = fz_status(cagd_bspline_reduce_uniform(s, o, HP(out), HP(rep)));
    KEEP(FZ_BSPLINE, out);
    keep_report(st, rep, rep_n);
}

static void op_cagd_bspline_to_polynomial(void) {
    IN_H(FZ_BSPLINE, CagdBSpline, s);
    size_t target = fz_small_deg();
    double tol = fz_tol();
    OUT_H(CagdBSpline, out);
    OUT_H(CagdReport, rep);
    CagdStatus st = fz_status(cagd_bspline_to_polynomial(s, target, tol, HP(out), HP(rep)));
    KEEP(FZ_BSPLINE, out);
    keep_report(st, rep, rep_n);
}

/* ---------------------------------------------------------------- B-spline surfaces */

static void op_cagd_bsplinesurface_new(void) {
    size_t p = fz_small_deg(), q = fz_small_deg(), dim = fz_dim();
    size_t nu = fz_count(fz_add(p, 1 + fz_r(3))), nv = fz_count(fz_add(q, 1 + fz_r(3)));
    size_t nku = fz_count(fz_add(fz_add(nu, p), 1)), nkv = fz_count(fz_add(fz_add(nv, q), 1));
    const double *ku = fz_knots(nku, p);
    const double *kv = fz_knots(nkv, q);
    const double *pts = fz_in(fz_mul(fz_mul(nu, nv), dim), FZ_VALUES);
    const double *w = fz_in_opt(fz_mul(nu, nv), FZ_WEIGHTS);
    SKIP_IF_NEEDED;
    OUT_H(CagdBSplineSurface, s);
    CagdStatus st = fz_status(
        cagd_bsplinesurface_new(p, q, ku, nku, kv, nkv, pts, w, nu, nv, dim, HP(s)));
    KEEP(FZ_BSURF, s);
}

static void op_cagd_bsplinesurface_free(void) {
    cagd_bsplinesurface_free((struct CagdBSplineSurface *)fz_take(FZ_BSURF));
    fz_status(CAGD_OK);
}

static void op_cagd_bsplinesurface_shape(void) {
    IN_H(FZ_BSURF, CagdBSplineSurface, s);
    size_t shape[5];
    int shape_n = fz_r(48) == 0;
    fz.call_null |= shape_n;
    OUT_S(bool, r);
    CagdStatus st = fz_status(cagd_bsplinesurface_shape(s, shape_n ? NULL : shape, SP(r)));
    (void)st;
}

static void op_cagd_bsplinesurface_array(void) {
    IN_H(FZ_BSURF, CagdBSplineSurface, s);
    int32_t part = fz_enum(4);
    FzOb ob;
    CagdStatus st;
    OUTCALL(ob, cagd_bsplinesurface_array(s, part, ob.p, ob.cap, ob.needed_p));
}

static void op_cagd_bsplinesurface_eval(void) {
    IN_H(FZ_BSURF, CagdBSplineSurface, s);
    double u = fz_param(), v = fz_param();
    FzOb ob;
    CagdStatus st;
    OUTCALL(ob, cagd_bsplinesurface_eval(s, u, v, ob.p, ob.cap, ob.needed_p));
}

static void op_cagd_bsplinesurface_reduce(void) {
    IN_H(FZ_BSURF, CagdBSplineSurface, s);
    const CagdReduceOptions *o = gen_opts();
    OUT_H(CagdBSplineSurface, out);
    OUT_H(CagdReport, rep);
    CagdStatus st = fz_status(cagd_bsplinesurface_reduce(s, o, HP(out), HP(rep)));
    KEEP(FZ_BSURF, out);
    keep_report(st, rep, rep_n);
}

static void op_cagd_bsplinesurface_reduce_to_tolerance(void) {
    IN_H(FZ_BSURF, CagdBSplineSurface, s);
    const CagdReduceOptions *o = gen_opts();
    OUT_H(CagdBSplineSurface, out);
    OUT_H(CagdReport, rep);
    CagdStatus st =
        fz_status(cagd_bsplinesurface_reduce_to_tolerance(s, o, HP(out), HP(rep)));
    KEEP(FZ_BSURF, out);
    keep_report(st, rep, rep_n);
}

static void op_cagd_bsplinesurface_to_polynomial(void) {
    IN_H(FZ_BSURF, CagdBSplineSurface, s);
    size_t tu = fz_small_deg(), tv = fz_small_deg();
    double tol = fz_tol();
    OUT_H(CagdBSplineSurface, out);
    OUT_H(CagdReport, rep);
    clock_t t0 = clock();
    CagdStatus st =
        fz_status(cagd_bsplinesurface_to_polynomial(s, tu, tv, tol, HP(out), HP(rep)));
    if ((double)(clock() - t0) / CLOCKS_PER_SEC > 1.0 && s != NULL) {
        size_t sh[5] = {0, 0, 0, 0, 0};
        bool rat = 0;
        (void)cagd_bsplinesurface_shape(s, sh, &rat);
        fprintf(stderr, "  slow surface: deg %zu x %zu, %zu x %zu points, dim %zu, rational %d,"
                " targets %zu %zu, tol %g, status %d\n", sh[0], sh[1], sh[2], sh[3], sh[4],
                (int)rat, tu, tv, tol, (int)st);
    }
    KEEP(FZ_BSURF, out);
    keep_report(st, rep, rep_n);
}

/* ---------------------------------------------------------------- NURBS span conversions */

static void op_cagd_nurbs_span_to_bezier(void) {
    size_t deg = fz_r(8) ? 2 + fz_r(2) : fz_deg(), dim = fz_dim();
    const double *knots = fz_in(fz_mul(2, deg), FZ_SORTED);
    const double *pts = fz_in(fz_mul(fz_add(deg, 1), dim), FZ_VALUES);
    const double *w = fz_in_opt(fz_add(deg, 1), FZ_WEIGHTS);
    SKIP_IF_NEEDED;
    OUT_H(CagdCurve, c);
    CagdStatus st = fz_status(cagd_nurbs_span_to_bezier(deg, knots, pts, w, dim, HP(c)));
    KEEP(FZ_CURVE, c);
}

static void op_cagd_bezier_to_nurbs_span(void) {
    IN_H(FZ_CURVE, CagdCurve, c);
    size_t deg = curve_degree(c, 3);
    const double *knots = fz_in(fz_mul(2, deg), FZ_SORTED);
    SKIP_IF_NEEDED;
    OUT_H(CagdBSpline, s);
    OUT_SO(double, x);
    CagdStatus st = fz_status(cagd_bezier_to_nurbs_span(c, knots, HP(s), SP(x)));
    FIN(x);
    KEEP(FZ_BSPLINE, s);
}

static void op_cagd_nurbs22_span_to_bezier(void) {
    size_t dim = fz_r(8) ? 1 + fz_r(3) : fz_dim();
    const double *uk = fz_in(4, FZ_SORTED);
    const double *vk = fz_in(4, FZ_SORTED);
    const double *pts = fz_in(fz_mul(9, dim), FZ_VALUES);
    const double *w = fz_in_opt(9, FZ_WEIGHTS);
    SKIP_IF_NEEDED;
    size_t np = fz_mul(9, dim);
    if (np > 4096) np = 4096; /* not written for such dims: refused before */
    double *po = fz_out_buf, *wo = fz_out_buf + 4200;
    if (fz_r(24) == 0) po = NULL, fz.call_null = 1;
    if (fz_r(24) == 0) wo = NULL, fz.call_null = 1;
    if (fz_r(32) == 0) wo = fz_out_buf + 1; /* overlapping outputs */
    CagdStatus st = fz_status(cagd_nurbs22_span_to_bezier(uk, vk, pts, w, dim, po, wo));
    if (st == CAGD_OK) {
        for (size_t i = 0; i < np; ++i) fz_finite(po[i], "points_out[i]");
        for (size_t i = 0; i < 9; ++i) fz_finite(wo[i], "weights_out[i]");
        if (wo == fz_out_buf + 1) fz_fail("CAGD_OK with overlapping outputs");
    }
}

static void op_cagd_bezier22_to_nurbs22_span(void) {
    size_t dim = fz_r(8) ? 1 + fz_r(3) : fz_dim();
    const double *uk = fz_in(4, FZ_SORTED);
    const double *vk = fz_in(4, FZ_SORTED);
    const double *pts = fz_in(fz_mul(9, dim), FZ_VALUES);
    const double *w = fz_in_opt(9, FZ_WEIGHTS);
    SKIP_IF_NEEDED;
    size_t np = fz_mul(9, dim);
    if (np > 4096) np = 4096;
    double *po = fz_out_buf, *wo = fz_out_buf + 4200;
    if (fz_r(24) == 0) po = NULL, fz.call_null = 1;
    if (fz_r(24) == 0) wo = NULL, fz.call_null = 1;
    if (fz_r(32) == 0) wo = fz_out_buf + 1;
    OUT_SO(double, x);
    CagdStatus st =
        fz_status(cagd_bezier22_to_nurbs22_span(uk, vk, pts, w, dim, po, wo, SP(x)));
    FIN(x);
    if (st == CAGD_OK) {
        for (size_t i = 0; i < np; ++i) fz_finite(po[i], "points_out[i]");
        for (size_t i = 0; i < 9; ++i) fz_finite(wo[i], "weights_out[i]");
        if (wo == fz_out_buf + 1) fz_fail("CAGD_OK with overlapping outputs");
    }
}

/* ---------------------------------------------------------------- patch piece lists */

static void op_cagd_patchpiecelist_free(void) {
    cagd_patchpiecelist_free((struct CagdPatchPieceList *)fz_take(FZ_PPLIST));
    fz_status(CAGD_OK);
}

static void op_cagd_patchpiecelist_count(void) {
    IN_H(FZ_PPLIST, CagdPatchPieceList, l);
    OUT_S(size_t, n);
    CagdStatus st = fz_status(cagd_patchpiecelist_count(l, SP(n)));
    (void)st;
}

static void op_cagd_patchpiecelist_info(void) {
    IN_H(FZ_PPLIST, CagdPatchPieceList, l);
    size_t i = fz_index(list_count(FZ_PPLIST, l));
    OUT_S(int32_t, kind);
    OUT_S(size_t, du);
    OUT_S(size_t, dv);
    OUT_S(size_t, dim);
    OUT_S(int32_t, rat);
    OUT_S(int32_t, dk);
    CagdStatus st = fz_status(
        cagd_patchpiecelist_info(l, i, SP(kind), SP(du), SP(dv), SP(dim), SP(rat), SP(dk)));
    if (st == CAGD_OK && kind != CAGD_PIECE_TENSOR && kind != CAGD_PIECE_TRIANGLE)
        fz_fail("piece kind %d", (int)kind);
}

static void op_cagd_patchpiecelist_points(void) {
    IN_H(FZ_PPLIST, CagdPatchPieceList, l);
    size_t i = fz_index(list_count(FZ_PPLIST, l));
    FzOb ob;
    CagdStatus st;
    OUTCALL(ob, cagd_patchpiecelist_points(l, i, ob.p, ob.cap, ob.needed_p));
}

static void op_cagd_patchpiecelist_weights(void) {
    IN_H(FZ_PPLIST, CagdPatchPieceList, l);
    size_t i = fz_index(list_count(FZ_PPLIST, l));
    FzOb ob;
    CagdStatus st;
    OUTCALL(ob, cagd_patchpiecelist_weights(l, i, ob.p, ob.cap, ob.needed_p));
}

static void op_cagd_patchpiecelist_domain(void) {
    IN_H(FZ_PPLIST, CagdPatchPieceList, l);
    size_t i = fz_index(list_count(FZ_PPLIST, l));
    FzOb ob;
    CagdStatus st;
    OUTCALL(ob, cagd_patchpiecelist_domain(l, i, ob.p, ob.cap, ob.needed_p));
}

static const double *tensor_weights(const struct CagdTensorPatch *p) {
    size_t m, n;
    tensor_shape(p, &m, &n);
    return fz_in_opt(fz_mul(fz_add(m, 1), fz_add(n, 1)), FZ_WEIGHTS);
}

static const double *tri_weights(const struct CagdTriPatch *p) {
    return fz_in_opt(fz_tri(tri_degree(p)), FZ_WEIGHTS);
}

static void op_cagd_tensorpatch_to_triangles(void) {
    IN_H(FZ_TENSOR, CagdTensorPatch, p);
    const double *w = tensor_weights(p);
    SKIP_IF_NEEDED;
    OUT_H(CagdPatchPieceList, l);
    CagdStatus st = fz_status(cagd_tensorpatch_to_triangles(p, w, HP(l)));
    KEEP(FZ_PPLIST, l);
}

static void op_cagd_tensorpatch_split_line(void) {
    IN_H(FZ_TENSOR, CagdTensorPatch, p);
    const double *w = tensor_weights(p);
    SKIP_IF_NEEDED;
    double f1 = fz_param(), f0 = fz_param();
    OUT_H(CagdPatchPieceList, l);
    CagdStatus st = fz_status(cagd_tensorpatch_split_line(p, w, f1, f0, HP(l)));
    KEEP(FZ_PPLIST, l);
}

static void op_cagd_tensorpatch_split_curve(void) {
    IN_H(FZ_TENSOR, CagdTensorPatch, p);
    const double *w = tensor_weights(p);
    size_t nc = fz_count(1 + fz_r(4));
    const double *coeffs = fz_in(nc, FZ_PARAMS);
    SKIP_IF_NEEDED;
    OUT_H(CagdPatchPieceList, l);
    CagdStatus st = fz_status(cagd_tensorpatch_split_curve(p, w, coeffs, nc, HP(l)));
    KEEP(FZ_PPLIST, l);
}

static void op_cagd_tensorpatch_trim(void) {
    IN_H(FZ_TENSOR, CagdTensorPatch, p);
    const double *w = tensor_weights(p);
    size_t ns = fz_r(16) ? 1 + fz_r(3) : (fz_r(2) ? 0 : fz_huge());
    const double *iv = fz_in(fz_mul(2, ns), FZ_PARAMS);
    SKIP_IF_NEEDED;
    static size_t counts[8];
    size_t sum = 0;
    for (size_t s = 0; s < 8; ++s) {
        counts[s] = fz_r(16) ? 1 + fz_r(4) : (fz_r(2) ? 0 : fz_huge());
    }
    if (ns <= 8) {
        for (size_t s = 0; s < ns; ++s) sum = fz_add(sum, counts[s]);
        if (fz_r(2) && ns > 0 && iv != NULL && ((uintptr_t)iv % 8) == 0) {
            /* a chain across [0, 1]: consecutive intervals */
            double *ivw = (double *)(uintptr_t)iv;
            for (size_t s = 0; s < ns; ++s) {
                ivw[2 * s] = (double)s / (double)ns;
                ivw[2 * s + 1] = (double)(s + 1) / (double)ns;
            }
        }
    } else {
        sum = 4;
    }
    const size_t *counts_p = fz_r(48) == 0 ? (fz.call_null = 1, (const size_t *)NULL) : counts;
    const double *coeffs = fz_in(sum, FZ_PARAMS);
    SKIP_IF_NEEDED;
    int32_t dir = fz_enum(2), keep = fz_enum(2);
    OUT_H(CagdPatchPieceList, l);
    CagdStatus st =
        fz_status(cagd_tensorpatch_trim(p, w, dir, keep, iv, counts_p, coeffs, ns, HP(l)));
    KEEP(FZ_PPLIST, l);
}

static void op_cagd_tripatch_to_rect(void) {
    IN_H(FZ_TRI, CagdTriPatch, p);
    const double *w = tri_weights(p);
    SKIP_IF_NEEDED;
    size_t m = fz_small_deg();
    OUT_H(CagdPatchPieceList, l);
    CagdStatus st = fz_status(cagd_tripatch_to_rect(p, w, m, HP(l)));
    KEEP(FZ_PPLIST, l);
}

static void op_cagd_tripatch_to_quad(void) {
    IN_H(FZ_TRI, CagdTriPatch, p);
    const double *w = tri_weights(p);
    const double *corners = fz_in(8, FZ_PARAMS);
    SKIP_IF_NEEDED;
    OUT_H(CagdPatchPieceList, l);
    CagdStatus st = fz_status(cagd_tripatch_to_quad(p, w, corners, HP(l)));
    KEEP(FZ_PPLIST, l);
}

static void op_cagd_tripatch_to_three_rects(void) {
    IN_H(FZ_TRI, CagdTriPatch, p);
    const double *w = tri_weights(p);
    SKIP_IF_NEEDED;
    double iu = fz_r(2) ? 1.0 / 3.0 : fz_param(), iv = fz_r(2) ? 1.0 / 3.0 : fz_param();
    double g = fz_param(), k = fz_param(), h = fz_param();
    OUT_H(CagdPatchPieceList, l);
    CagdStatus st = fz_status(cagd_tripatch_to_three_rects(p, w, iu, iv, g, k, h, HP(l)));
    KEEP(FZ_PPLIST, l);
}

static void op_cagd_tensorpatch_to_triangle(void) {
    IN_H(FZ_TENSOR, CagdTensorPatch, p);
    const double *w = tensor_weights(p);
    SKIP_IF_NEEDED;
    double tol = fz_tol();
    OUT_H(CagdPatchPieceList, l);
    CagdStatus st = fz_status(cagd_tensorpatch_to_triangle(p, w, tol, HP(l)));
    KEEP(FZ_PPLIST, l);
}

/* ---------------------------------------------------------------- implicit forms */

static void op_cagd_implicit_free(void) {
    cagd_implicit_free((struct CagdImplicit *)fz_take(FZ_IMPLICIT));
    fz_status(CAGD_OK);
}

static void op_cagd_implicit_report(void) {
    IN_H(FZ_IMPLICIT, CagdImplicit, im);
    OUT_S(size_t, d);
    OUT_S(size_t, bp);
    OUT_S(size_t, pw);
    CagdStatus st = fz_status(cagd_implicit_report(im, SP(d), SP(bp), SP(pw)));
    (void)st;
}

static void op_cagd_implicit_coefficients(void) {
    IN_H(FZ_IMPLICIT, CagdImplicit, im);
    FzOb ob;
    CagdStatus st;
    OUTCALL(ob, cagd_implicit_coefficients(im, ob.p, ob.cap, ob.needed_p));
}

static void op_cagd_implicit_bezout(void) {
    IN_H(FZ_IMPLICIT, CagdImplicit, im);
    FzOb ob;
    CagdStatus st;
    OUTCALL(ob, cagd_implicit_bezout(im, ob.p, ob.cap, ob.needed_p));
}

static void op_cagd_implicit_classify(void) {
    IN_H(FZ_IMPLICIT, CagdImplicit, im);
    double x = fz_double(), y = fz_double();
    OUT_S(double, v);
    OUT_S(int32_t, s);
    OUT_S(double, d);
    CagdStatus st = fz_status(cagd_implicit_classify(im, x, y, SP(v), SP(s), SP(d)));
    FIN(v);
    /* the distance is documented as +-infinity where the gradient vanishes */
    if (st == CAGD_OK && (isnan(d) || s < -1 || s > 1)) fz_fail("distance %g sign %d", d, s);
}

static void op_cagd_implicit_invert(void) {
    IN_H(FZ_IMPLICIT, CagdImplicit, im);
    double x = fz_double(), y = fz_double();
    OUT_S(double, t);
    CagdStatus st = fz_status(cagd_implicit_invert(im, x, y, SP(t)));
    FIN(t);
}

static void op_cagd_implicit_subdivision_matrix(void) {
    size_t n = fz_small_deg();
    double alpha = fz_param();
    FzOb ob;
    CagdStatus st;
    OUTCALL(ob, cagd_implicit_subdivision_matrix(n, alpha, ob.p, ob.cap, ob.needed_p));
}

/* ---------------------------------------------------------------- interval patches */

static void op_cagd_intervaltri_new(void) {
    size_t deg = fz_small_deg(), dim = fz_dim();
    size_t need = fz_mul(fz_tri(deg), dim);
    const double *lo = fz_in(need, FZ_VALUES);
    double *hi = NULL;
    const double *hi_c = NULL;
    if (lo != NULL && !fz.call_impossible && need <= FZ_IN_CAP / 2 && fz_r(2) &&
        ((uintptr_t)lo % 8) == 0) {
        /* a valid box net: hi = lo + a non-negative width */
        hi_c = fz_in(need, FZ_VALUES);
        if (hi_c != NULL && ((uintptr_t)hi_c % 8) == 0) {
            hi = (double *)(uintptr_t)hi_c;
            for (size_t i = 0; i < need; ++i) hi[i] = lo[i] + fabs(hi[i]) * 1e-3;
        }
    } else {
        hi_c = fz_in(need, FZ_VALUES);
    }
    SKIP_IF_NEEDED;
    OUT_H(CagdIntervalTriPatch, p);
    CagdStatus st = fz_status(cagd_intervaltri_new(lo, hi_c, deg, dim, HP(p)));
    KEEP(FZ_ITRI, p);
}

static void op_cagd_intervaltri_free(void) {
    cagd_intervaltri_free((struct CagdIntervalTriPatch *)fz_take(FZ_ITRI));
    fz_status(CAGD_OK);
}

static void op_cagd_intervaltri_shape(void) {
    IN_H(FZ_ITRI, CagdIntervalTriPatch, p);
    OUT_S(size_t, d);
    OUT_S(size_t, dim);
    OUT_S(double, th);
    CagdStatus st = fz_status(cagd_intervaltri_shape(p, SP(d), SP(dim), SP(th)));
    FIN(th);
}

static void op_cagd_intervaltri_net(void) {
    IN_H(FZ_ITRI, CagdIntervalTriPatch, p);
    bool upper = fz_r(2);
    FzOb ob;
    CagdStatus st;
    OUTCALL(ob, cagd_intervaltri_net(p, upper, ob.p, ob.cap, ob.needed_p));
}

static void op_cagd_intervaltri_contains(void) {
    IN_H(FZ_ITRI, CagdIntervalTriPatch, a);
    IN_H(FZ_ITRI, CagdIntervalTriPatch, b);
    size_t cd = fz_small_deg();
    OUT_S(bool, c);
    CagdStatus st = fz_status(cagd_intervaltri_contains(a, b, cd, SP(c)));
    (void)st;
}

static void op_cagd_intervaltri_reduce(void) {
    IN_H(FZ_ITRI, CagdIntervalTriPatch, p);
    size_t target = fz_small_deg(), cd = fz_small_deg();
    OUT_H(CagdIntervalTriPatch, o);
    CagdIntervalReport rep;
    int rep_n = fz_r(4) == 0;
    CagdStatus st = fz_status(cagd_intervaltri_reduce(p, target, cd, HP(o), rep_n ? NULL : &rep));
    if (st == CAGD_OK && !rep_n) {
        fz_finite(rep.thickness_in, "thickness_in");
        fz_finite(rep.thickness_out, "thickness_out");
        fz_finite(rep.repair, "repair");
        fz_finite(rep.max_violation, "max_violation");
        fz_finite(rep.objective, "objective");
    }
    KEEP(FZ_ITRI, o);
}

/* ---------------------------------------------------------------- matrices, invariants */

static void op_cagd_triangle_elevation_matrix(void) {
    size_t m = fz_small_deg(), n = fz_small_deg();
    FzOb ob;
    CagdStatus st;
    OUTCALL(ob, cagd_triangle_elevation_matrix(m, n, ob.p, ob.cap, ob.needed_p));
}

static void op_cagd_uniform_bspline_matrix(void) {
    size_t n = fz_small_deg();
    bool inv = fz_r(2);
    FzOb ob;
    CagdStatus st;
    OUTCALL(ob, cagd_uniform_bspline_matrix(n, inv, ob.p, ob.cap, ob.needed_p));
}

static void op_cagd_basis_matrix(void) {
    int32_t basis = fz_enum(6);
    size_t l = fz_small_deg(), n = fz_small_deg();
    bool to_b = fz_r(2);
    FzOb ob;
    CagdStatus st;
    OUTCALL(ob, cagd_basis_matrix(basis, l, n, to_b, ob.p, ob.cap, ob.needed_p));
}

static void op_cagd_perturbation_error_factor(void) {
    size_t n = fz_deg();
    OUT_S(double, f);
    CagdStatus st = fz_status(cagd_perturbation_error_factor(n, SP(f)));
    FIN(f);
}

static void op_cagd_subdivision_levels(void) {
    size_t n = fz_deg();
    double nf = fz_r(2) ? fz_unit() * 10.0 : fz_double(), delta = fz_tol();
    OUT_S(size_t, lv);
    CagdStatus st = fz_status(cagd_subdivision_levels(n, nf, delta, SP(lv)));
    (void)st;
}

static void op_cagd_tensorpatch_degeneracy(void) {
    IN_H(FZ_TENSOR, CagdTensorPatch, p);
    FzOb f, g;
    fz.out_used = 0;
    fz_ob_init(&f);
    fz.out_used = FZ_OUT_CAP / 2;
    fz_ob_init(&g);
    if (f.mode == FZ_OB_EXACT) f.mode = FZ_OB_QUERY;
    if (g.mode == FZ_OB_EXACT) g.mode = FZ_OB_QUERY;
    CagdStatus st = fz_status(
        cagd_tensorpatch_degeneracy(p, f.p, f.cap, f.needed_p, g.p, g.cap, g.needed_p));
    if (st == CAGD_OK || st == CAGD_ERR_BUFFER_TOO_SMALL) {
        if (st == CAGD_ERR_BUFFER_TOO_SMALL && f.needed_p && g.needed_p &&
            f.needed <= f.cap && g.needed <= g.cap)
            fz_fail("CAGD_ERR_BUFFER_TOO_SMALL but both buffers are large enough");
        if (st == CAGD_OK) {
            fz_ob_check(&f, st, 1);
            fz_ob_check(&g, st, 1);
        }
    }
}

static void op_cagd_tripatch_degeneracy(void) {
    IN_H(FZ_TRI, CagdTriPatch, p);
    FzOb ob;
    CagdStatus st;
    OUTCALL(ob, cagd_tripatch_degeneracy(p, ob.p, ob.cap, ob.needed_p));
}

static void op_cagd_tensorpatch_distance(void) {
    IN_H(FZ_TENSOR, CagdTensorPatch, a);
    IN_H(FZ_TENSOR, CagdTensorPatch, b);
    OUT_S(double, d);
    CagdStatus st = fz_status(cagd_tensorpatch_distance(a, b, SP(d)));
    FIN(d);
}

static void op_cagd_tripatch_distance(void) {
    IN_H(FZ_TRI, CagdTriPatch, a);
    IN_H(FZ_TRI, CagdTriPatch, b);
    OUT_S(double, d);
    CagdStatus st = fz_status(cagd_tripatch_distance(a, b, SP(d)));
    FIN(d);
}

static void op_cagd_last_error_message(void) {
    const char *m = cagd_last_error_message();
    if (m == NULL) fz_fail("cagd_last_error_message returned NULL");
    fz_status(CAGD_OK);
}

static void op_cagd_status_name(void) {
    int32_t s = fz_r(2) ? (int32_t)fz_r(100) : (int32_t)fz_u64();
    const char *m = cagd_status_name(s);
    if (m == NULL || m[0] == '\0') fz_fail("cagd_status_name(%d) is NULL or empty", (int)s);
    fz_status(CAGD_OK);
}

/* ---------------------------------------------------------------- tensor patches */

static void op_cagd_tensorpatch_new(void) {
    size_t m = fz_small_deg(), n = fz_small_deg(), dim = fz_dim();
    const double *pts = fz_in(fz_mul(fz_mul(fz_add(m, 1), fz_add(n, 1)), dim), FZ_VALUES);
    SKIP_IF_NEEDED;
    OUT_H(CagdTensorPatch, p);
    CagdStatus st = fz_status(cagd_tensorpatch_new(pts, m, n, dim, HP(p)));
    KEEP(FZ_TENSOR, p);
}

static void op_cagd_tensorpatch_free(void) {
    cagd_tensorpatch_free((struct CagdTensorPatch *)fz_take(FZ_TENSOR));
    fz_status(CAGD_OK);
}

static void op_cagd_tensorpatch_shape(void) {
    IN_H(FZ_TENSOR, CagdTensorPatch, p);
    OUT_S(size_t, m);
    OUT_S(size_t, n);
    OUT_S(size_t, d);
    CagdStatus st = fz_status(cagd_tensorpatch_shape(p, SP(m), SP(n), SP(d)));
    (void)st;
}

static void op_cagd_tensorpatch_points(void) {
    IN_H(FZ_TENSOR, CagdTensorPatch, p);
    FzOb ob;
    CagdStatus st;
    OUTCALL(ob, cagd_tensorpatch_points(p, ob.p, ob.cap, ob.needed_p));
}

static void op_cagd_tensorpatch_eval(void) {
    IN_H(FZ_TENSOR, CagdTensorPatch, p);
    double u = fz_param(), v = fz_param();
    FzOb ob;
    CagdStatus st;
    OUTCALL(ob, cagd_tensorpatch_eval(p, u, v, ob.p, ob.cap, ob.needed_p));
}

static void op_cagd_tensorpatch_elevate(void) {
    IN_H(FZ_TENSOR, CagdTensorPatch, p);
    size_t ru = fz_small_deg(), rv = fz_small_deg();
    OUT_H(CagdTensorPatch, o);
    CagdStatus st = fz_status(cagd_tensorpatch_elevate(p, ru, rv, HP(o)));
    KEEP(FZ_TENSOR, o);
}

static void op_cagd_tensorpatch_subdivide_u(void) {
    IN_H(FZ_TENSOR, CagdTensorPatch, p);
    double s = fz_param();
    OUT_H(CagdTensorPatch, a);
    OUT_H(CagdTensorPatch, b);
    CagdStatus st = fz_status(cagd_tensorpatch_subdivide_u(p, s, HP(a), HP(b)));
    KEEP(FZ_TENSOR, a);
    KEEP(FZ_TENSOR, b);
}

static void op_cagd_tensorpatch_subdivide_v(void) {
    IN_H(FZ_TENSOR, CagdTensorPatch, p);
    double s = fz_param();
    OUT_H(CagdTensorPatch, a);
    OUT_H(CagdTensorPatch, b);
    CagdStatus st = fz_status(cagd_tensorpatch_subdivide_v(p, s, HP(a), HP(b)));
    KEEP(FZ_TENSOR, a);
    KEEP(FZ_TENSOR, b);
}

static void op_cagd_tensorpatch_reduce(void) {
    IN_H(FZ_TENSOR, CagdTensorPatch, p);
    const CagdReduceOptions *o = gen_opts();
    OUT_H(CagdTensorPatch, out);
    OUT_H(CagdReport, rep);
    CagdStatus st = fz_status(cagd_tensorpatch_reduce(p, o, HP(out), HP(rep)));
    KEEP(FZ_TENSOR, out);
    keep_report(st, rep, rep_n);
}

static void op_cagd_tensorpatch_reduce_to_tolerance(void) {
    IN_H(FZ_TENSOR, CagdTensorPatch, p);
    const CagdReduceOptions *o = gen_opts();
    OUT_H(CagdTensorPatchList, out);
    OUT_H(CagdReport, rep);
    CagdStatus st = fz_status(cagd_tensorpatch_reduce_to_tolerance(p, o, HP(out), HP(rep)));
    KEEP(FZ_TENSORLIST, out);
    keep_report(st, rep, rep_n);
}

static void op_cagd_tensorpatchlist_free(void) {
    cagd_tensorpatchlist_free((struct CagdTensorPatchList *)fz_take(FZ_TENSORLIST));
    fz_status(CAGD_OK);
}

static void op_cagd_tensorpatchlist_count(void) {
    IN_H(FZ_TENSORLIST, CagdTensorPatchList, l);
    OUT_S(size_t, n);
    CagdStatus st = fz_status(cagd_tensorpatchlist_count(l, SP(n)));
    (void)st;
}

static void op_cagd_tensorpatchlist_get(void) {
    IN_H(FZ_TENSORLIST, CagdTensorPatchList, l);
    size_t i = fz_index(list_count(FZ_TENSORLIST, l));
    OUT_H(CagdTensorPatch, p);
    double dom[4];
    int dom_n = fz_r(48) == 0;
    fz.call_null |= dom_n;
    OUT_S(double, b);
    CagdStatus st = fz_status(cagd_tensorpatchlist_get(l, i, HP(p), dom_n ? NULL : dom, SP(b)));
    if (st == CAGD_OK) {
        for (int k = 0; k < 4; ++k) fz_finite(dom[k], "domain_out[k]");
    }
    FIN(b);
    KEEP(FZ_TENSOR, p);
}

/* ---------------------------------------------------------------- triangular patches */

static void op_cagd_tripatch_new(void) {
    size_t n = fz_deg(), dim = fz_dim();
    const double *pts = fz_in(fz_mul(fz_tri(n), dim), FZ_VALUES);
    SKIP_IF_NEEDED;
    OUT_H(CagdTriPatch, p);
    CagdStatus st = fz_status(cagd_tripatch_new(pts, n, dim, HP(p)));
    KEEP(FZ_TRI, p);
}

static void op_cagd_tripatch_free(void) {
    cagd_tripatch_free((struct CagdTriPatch *)fz_take(FZ_TRI));
    fz_status(CAGD_OK);
}

static void op_cagd_tripatch_shape(void) {
    IN_H(FZ_TRI, CagdTriPatch, p);
    OUT_S(size_t, n);
    OUT_S(size_t, d);
    CagdStatus st = fz_status(cagd_tripatch_shape(p, SP(n), SP(d)));
    (void)st;
}

static void op_cagd_tripatch_points(void) {
    IN_H(FZ_TRI, CagdTriPatch, p);
    FzOb ob;
    CagdStatus st;
    OUTCALL(ob, cagd_tripatch_points(p, ob.p, ob.cap, ob.needed_p));
}

static void op_cagd_tripatch_eval(void) {
    IN_H(FZ_TRI, CagdTriPatch, p);
    double u = fz_param(), v = fz_param();
    FzOb ob;
    CagdStatus st;
    OUTCALL(ob, cagd_tripatch_eval(p, u, v, ob.p, ob.cap, ob.needed_p));
}

static void op_cagd_tripatch_elevate(void) {
    IN_H(FZ_TRI, CagdTriPatch, p);
    size_t r = fz_small_deg();
    OUT_H(CagdTriPatch, o);
    CagdStatus st = fz_status(cagd_tripatch_elevate(p, r, HP(o)));
    KEEP(FZ_TRI, o);
}

static void op_cagd_tripatch_subdivide_midpoint(void) {
    IN_H(FZ_TRI, CagdTriPatch, p);
    struct CagdTriPatch *pieces[4] = {NULL, NULL, NULL, NULL};
    int pieces_n = fz_r(48) == 0;
    fz.call_null |= pieces_n;
    CagdStatus st = fz_status(cagd_tripatch_subdivide_midpoint(p, pieces_n ? NULL : pieces));
    for (int k = 0; k < 4; ++k) fz_handle_out(FZ_TRI, st, pieces[k], pieces_n);
}

static void op_cagd_tripatch_reduce(void) {
    IN_H(FZ_TRI, CagdTriPatch, p);
    const CagdReduceOptions *o = gen_opts();
    OUT_H(CagdTriPatch, out);
    OUT_H(CagdReport, rep);
    CagdStatus st = fz_status(cagd_tripatch_reduce(p, o, HP(out), HP(rep)));
    KEEP(FZ_TRI, out);
    keep_report(st, rep, rep_n);
}

static void op_cagd_tripatch_reduce_to_tolerance(void) {
    IN_H(FZ_TRI, CagdTriPatch, p);
    const CagdReduceOptions *o = gen_opts();
    OUT_H(CagdTriPatchList, out);
    OUT_H(CagdReport, rep);
    CagdStatus st = fz_status(cagd_tripatch_reduce_to_tolerance(p, o, HP(out), HP(rep)));
    KEEP(FZ_TRILIST, out);
    keep_report(st, rep, rep_n);
}

static void op_cagd_tripatchlist_free(void) {
    cagd_tripatchlist_free((struct CagdTriPatchList *)fz_take(FZ_TRILIST));
    fz_status(CAGD_OK);
}

static void op_cagd_tripatchlist_count(void) {
    IN_H(FZ_TRILIST, CagdTriPatchList, l);
    OUT_S(size_t, n);
    CagdStatus st = fz_status(cagd_tripatchlist_count(l, SP(n)));
    (void)st;
}

static void op_cagd_tripatchlist_get(void) {
    IN_H(FZ_TRILIST, CagdTriPatchList, l);
    size_t i = fz_index(list_count(FZ_TRILIST, l));
    OUT_H(CagdTriPatch, p);
    double vert[6];
    int vert_n = fz_r(48) == 0;
    fz.call_null |= vert_n;
    OUT_S(double, b);
    CagdStatus st = fz_status(cagd_tripatchlist_get(l, i, HP(p), vert_n ? NULL : vert, SP(b)));
    if (st == CAGD_OK) {
        for (int k = 0; k < 6; ++k) fz_finite(vert[k], "vertices_out[k]");
    }
    FIN(b);
    KEEP(FZ_TRI, p);
}

/* ---------------------------------------------------------------- reports */

static void op_cagd_report_free(void) {
    cagd_report_free((struct CagdReport *)fz_take(FZ_REPORT));
    fz_status(CAGD_OK);
}

static void op_cagd_report_patch(void) {
    IN_H(FZ_REPORT, CagdReport, r);
    OUT_S(int32_t, pm);
    size_t degs[4];
    int degs_n = fz_r(48) == 0;
    fz.call_null |= degs_n;
    OUT_S(size_t, np);
    CagdStatus st = fz_status(cagd_report_patch(r, SP(pm), degs_n ? NULL : degs, SP(np)));
    (void)st;
}

static void op_cagd_report_method_params(void) {
    IN_H(FZ_REPORT, CagdReport, r);
    OUT_S(int32_t, m);
    OUT_S(int32_t, rr);
    OUT_S(int32_t, p);
    OUT_S(double, l1);
    OUT_S(double, l2);
    CagdStatus st =
        fz_status(cagd_report_method_params(r, SP(m), SP(rr), SP(p), SP(l1), SP(l2)));
    FIN(l1);
    FIN(l2);
}

static void op_cagd_report_method(void) {
    IN_H(FZ_REPORT, CagdReport, r);
    OUT_S(int32_t, m);
    OUT_S(size_t, df);
    OUT_S(size_t, dt);
    CagdStatus st = fz_status(cagd_report_method(r, SP(m), SP(df), SP(dt)));
    (void)st;
}

static void op_cagd_report_bound(void) {
    IN_H(FZ_REPORT, CagdReport, r);
    OUT_S(double, b);
    CagdStatus st = fz_status(cagd_report_bound(r, SP(b)));
    FIN(b);
}

static void op_cagd_report_max_error(void) {
    IN_H(FZ_REPORT, CagdReport, r);
    OUT_S(double, e);
    CagdStatus st = fz_status(cagd_report_max_error(r, SP(e)));
    FIN(e);
}

static void op_cagd_report_space(void) {
    IN_H(FZ_REPORT, CagdReport, r);
    OUT_S(int32_t, s);
    OUT_S(double, hb);
    CagdStatus st = fz_status(cagd_report_space(r, SP(s), SP(hb)));
    FIN(hb);
}

static void op_cagd_report_piecewise(void) {
    IN_H(FZ_REPORT, CagdReport, r);
    OUT_S(size_t, np);
    OUT_S(size_t, depth);
    OUT_S(size_t, cont);
    OUT_S(double, pb);
    CagdStatus st =
        fz_status(cagd_report_piecewise(r, SP(np), SP(depth), SP(cont), SP(pb)));
    FIN(pb);
}

static void op_cagd_report_pieces(void) {
    IN_H(FZ_REPORT, CagdReport, r);
    OUT_H(CagdCurveList, l);
    CagdStatus st = fz_status(cagd_report_pieces(r, HP(l)));
    KEEP(FZ_CURVELIST, l);
}

static void op_cagd_report_step_bounds(void) {
    IN_H(FZ_REPORT, CagdReport, r);
    FzOb ob;
    CagdStatus st;
    OUTCALL(ob, cagd_report_step_bounds(r, ob.p, ob.cap, ob.needed_p));
}

static void op_cagd_report_spline(void) {
    IN_H(FZ_REPORT, CagdReport, r);
    OUT_S(double, sb);
    OUT_S(size_t, pieces);
    OUT_S(size_t, si);
    OUT_S(size_t, so);
    CagdStatus st = fz_status(cagd_report_spline(r, SP(sb), SP(pieces), SP(si), SP(so)));
    FIN(sb);
}

static void op_cagd_report_spline_strategy(void) {
    IN_H(FZ_REPORT, CagdReport, r);
    OUT_S(int32_t, s);
    CagdStatus st = fz_status(cagd_report_spline_strategy(r, SP(s)));
    (void)st;
}

static void op_cagd_report_spline_continuity(void) {
    IN_H(FZ_REPORT, CagdReport, r);
    static int32_t orders[64];
    size_t cap = fz_r(4) ? 64 : fz_r(4);
    double *knots = fz_out_buf;
    int32_t *ords = orders;
    switch (fz_r(16)) {
    case 0: knots = NULL; ords = NULL; cap = 0; break;
    case 1: knots = NULL; fz.call_null |= cap > 0; break;
    case 2: ords = NULL; fz.call_null |= cap > 0; break;
    default: break;
    }
    size_t needed = (size_t)-7;
    int needed_n = fz_r(48) == 0;
    fz.call_null |= needed_n;
    for (size_t i = 0; i < 72; ++i) fz_out_buf[i] = -12345.0;
    CagdStatus st = fz_status(
        cagd_report_spline_continuity(r, knots, ords, cap, needed_n ? NULL : &needed));
    if (st == CAGD_OK) {
        if (needed > cap) fz_fail("*out_needed %zu > out_cap %zu", needed, cap);
        for (size_t i = 0; knots != NULL && i < needed; ++i) {
            fz_finite(knots[i], "knots_out[i]");
            if (knots[i] == -12345.0) fz_fail("knots_out[%zu] not written", i);
        }
    }
    if (st == CAGD_ERR_BUFFER_TOO_SMALL && needed <= cap)
        fz_fail("CAGD_ERR_BUFFER_TOO_SMALL with needed %zu <= cap %zu", needed, cap);
}

/* ---------------------------------------------------------------- WSGB curves */

static void op_cagd_wsgb_new(void) {
    size_t deg = fz_deg(), dim = fz_dim(), n = fz_count(fz_add(deg, 1));
    size_t order = fz_r(8) ? fz_r(4) : fz_small_deg();
    const double *pts = fz_in(fz_mul(n, dim), FZ_VALUES);
    SKIP_IF_NEEDED;
    OUT_H(CagdWsgbCurve, c);
    CagdStatus st = fz_status(cagd_wsgb_new(pts, n, dim, order, HP(c)));
    KEEP(FZ_WSGB, c);
}

static void op_cagd_wsgb_free(void) {
    cagd_wsgb_free((struct CagdWsgbCurve *)fz_take(FZ_WSGB));
    fz_status(CAGD_OK);
}

static void op_cagd_wsgb_shape(void) {
    IN_H(FZ_WSGB, CagdWsgbCurve, c);
    OUT_S(size_t, d);
    OUT_S(size_t, o);
    OUT_S(size_t, dim);
    CagdStatus st = fz_status(cagd_wsgb_shape(c, SP(d), SP(o), SP(dim)));
    (void)st;
}

static void op_cagd_wsgb_points(void) {
    IN_H(FZ_WSGB, CagdWsgbCurve, c);
    FzOb ob;
    CagdStatus st;
    OUTCALL(ob, cagd_wsgb_points(c, ob.p, ob.cap, ob.needed_p));
}

static void op_cagd_wsgb_eval(void) {
    IN_H(FZ_WSGB, CagdWsgbCurve, c);
    double u = fz_param();
    FzOb ob;
    CagdStatus st;
    OUTCALL(ob, cagd_wsgb_eval(c, u, ob.p, ob.cap, ob.needed_p));
}

static void op_cagd_wsgb_to_bezier(void) {
    IN_H(FZ_WSGB, CagdWsgbCurve, c);
    OUT_H(CagdCurve, b);
    CagdStatus st = fz_status(cagd_wsgb_to_bezier(c, HP(b)));
    KEEP(FZ_CURVE, b);
}

static void op_cagd_wsgb_from_bezier(void) {
    IN_H(FZ_CURVE, CagdCurve, b);
    size_t order = fz_r(8) ? fz_r(4) : fz_small_deg();
    OUT_H(CagdWsgbCurve, c);
    CagdStatus st = fz_status(cagd_wsgb_from_bezier(b, order, HP(c)));
    KEEP(FZ_WSGB, c);
}

static void op_cagd_wsgb_elevate(void) {
    IN_H(FZ_WSGB, CagdWsgbCurve, c);
    size_t order = fz_r(8) ? fz_r(4) : fz_small_deg();
    OUT_H(CagdWsgbCurve, o);
    CagdStatus st = fz_status(cagd_wsgb_elevate(c, order, HP(o)));
    KEEP(FZ_WSGB, o);
}

static void op_cagd_wsgb_leading_coefficient(void) {
    IN_H(FZ_WSGB, CagdWsgbCurve, c);
    OUT_S(bool, deg);
    FzOb ob;
    CagdStatus st;
    OUTCALL(ob, cagd_wsgb_leading_coefficient(c, ob.p, ob.cap, ob.needed_p, SP(deg)));
}

static void op_cagd_wsgb_reduce_to_tolerance(void) {
    IN_H(FZ_WSGB, CagdWsgbCurve, c);
    int32_t method = fz_enum(3);
    const CagdReduceOptions *o = gen_opts();
    OUT_H(CagdWsgbCurveList, l);
    CagdStatus st = fz_status(cagd_wsgb_reduce_to_tolerance(c, method, o, HP(l)));
    KEEP(FZ_WSGBLIST, l);
}

static void op_cagd_wsgb_reduce(void) {
    IN_H(FZ_WSGB, CagdWsgbCurve, c);
    int32_t method = fz_enum(3);
    const CagdReduceOptions *o = gen_opts();
    OUT_H(CagdWsgbCurve, out);
    CagdWsgbReport rep;
    memset(&rep, 0, sizeof rep);
    rep.struct_size = fz_r(16) ? sizeof rep : fz_r(sizeof rep);
    int rep_n = fz_r(4) == 0;
    CagdStatus st = fz_status(cagd_wsgb_reduce(c, method, o, HP(out), rep_n ? NULL : &rep));
    if (st == CAGD_OK && !rep_n && rep.struct_size == sizeof rep) {
        fz_finite(rep.error_bound, "report.error_bound");
        /* max_error is NaN exactly when opts->measure is false (documented) */
        if (o->measure) fz_finite(rep.max_error, "report.max_error");
        if (!o->measure && !isnan(rep.max_error)) fz_fail("max_error measured without measure");
        if (rep.max_error > rep.error_bound * (1.0 + 1e-12))
            fz_fail("WSGB max_error %.17g above error_bound %.17g", rep.max_error,
                    rep.error_bound);
    }
    KEEP(FZ_WSGB, out);
}

static void op_cagd_wsgblist_free(void) {
    cagd_wsgblist_free((struct CagdWsgbCurveList *)fz_take(FZ_WSGBLIST));
    fz_status(CAGD_OK);
}

static void op_cagd_wsgblist_count(void) {
    IN_H(FZ_WSGBLIST, CagdWsgbCurveList, l);
    OUT_S(size_t, n);
    CagdStatus st = fz_status(cagd_wsgblist_count(l, SP(n)));
    (void)st;
}

static void op_cagd_wsgblist_get(void) {
    IN_H(FZ_WSGBLIST, CagdWsgbCurveList, l);
    size_t i = fz_index(list_count(FZ_WSGBLIST, l));
    OUT_H(CagdWsgbCurve, c);
    OUT_S(double, a);
    OUT_S(double, b);
    OUT_S(double, bd);
    CagdStatus st = fz_status(cagd_wsgblist_get(l, i, HP(c), SP(a), SP(b), SP(bd)));
    FIN(a);
    FIN(b);
    FIN(bd);
    KEEP(FZ_WSGB, c);
}

/* ---------------------------------------------------------------- handle-free Bézier */

/* n_threads: 0..3 mostly; now and then a count above the limit (256) or huge. */
static size_t gen_threads(void) {
    switch (fz_r(32)) {
    case 0: return 300;
    case 1: return fz_huge();
    case 2: return 4 + fz_r(5);
    default: return fz_r(4);
    }
}

/* Curves per batch: a few mostly, sometimes enough (>= 1024) to use the worker pool. */
static size_t gen_batch_count(size_t deg, size_t dim) {
    if (fz_r(24) == 0 && deg <= 8 && dim <= 3) return 1024 + fz_r(64);
    return fz_count(1 + fz_r(4));
}

static void op_cagd_bezier_elevate_batch(void) {
    size_t deg = fz_deg(), dim = fz_dim(), nc = gen_batch_count(deg, dim);
    const double *pts = fz_in(fz_mul(fz_mul(nc, fz_add(deg, 1)), dim), FZ_VALUES);
    SKIP_IF_NEEDED;
    int32_t layout = fz_enum(2);
    size_t r = fz_small_deg();
    size_t nt = gen_threads();
    FzOb ob;
    CagdStatus st;
    OUTCALL(ob, cagd_bezier_elevate_batch(pts, nc, deg, dim, layout, r, nt, ob.p, ob.cap,
                                          ob.needed_p));
    if (st == CAGD_OK && ob.needed != fz_mul(fz_mul(nc, fz_add(fz_add(deg, r), 1)), dim)) {
        fz_fail("out_needed %zu is not n_curves (n + r + 1) dim", ob.needed);
    }
}

static void op_cagd_bezier_reduce_batch(void) {
    size_t deg = fz_deg(), dim = fz_dim(), nc = gen_batch_count(deg, dim);
    const double *pts = fz_in(fz_mul(fz_mul(nc, fz_add(deg, 1)), dim), FZ_VALUES);
    SKIP_IF_NEEDED;
    int32_t layout = fz_enum(2);
    const CagdReduceOptions *o = gen_opts();
    size_t nt = gen_threads();
    FzOb ob;
    CagdStatus st;
    OUTCALL(ob, cagd_bezier_reduce_batch(pts, nc, deg, dim, layout, o, nt, ob.p, ob.cap,
                                         ob.needed_p));
    if (st == CAGD_OK && ob.needed != fz_mul(fz_mul(nc, fz_add(o->target, 1)), dim)) {
        fz_fail("out_needed %zu is not n_curves (target + 1) dim", ob.needed);
    }
}

/* The weights output of cagd_bezier_elevate / cagd_bezier_reduce (rational curves). */
static double wout_store[MB_STRIDE + 16];

typedef struct Wout {
    double *p;
    size_t cap;
    int roomy;
} Wout;

static void wout_draw(Wout *w, int rational, int exact) {
    for (size_t i = 0; i < MB_STRIDE + 16; ++i) wout_store[i] = mb_poison();
    uint32_t k = exact ? 9 : fz_r(10);
    w->roomy = 0;
    if (k == 0) {
        w->p = NULL;
        w->cap = fz_r(2) ? 0 : 1 + fz_r(8);
        fz.call_null |= rational;
    } else if (k == 1) {
        w->p = wout_store;
        w->cap = fz_r(8);
    } else {
        w->p = wout_store;
        w->cap = MB_STRIDE;
        w->roomy = 1;
    }
}

static void wout_check(const Wout *w, CagdStatus st, int rational, size_t len) {
    if (w->p == NULL) return;
    if (st != CAGD_OK || !rational) {
        for (size_t i = 0; i < w->cap + 8 && i < MB_STRIDE + 16; ++i) {
            if (!mb_is_poison(wout_store[i])) {
                fz_fail("weights_out[%zu] written (failure or polynomial curve)", i);
            }
        }
        return;
    }
    if (len > w->cap) fz_fail("CAGD_OK but weights_out cap %zu < %zu", w->cap, len);
    for (size_t i = 0; i < len; ++i) {
        if (mb_is_poison(wout_store[i])) fz_fail("weights_out[%zu] not written", i);
        if (!isfinite(wout_store[i]) || !(wout_store[i] > 0.0)) {
            fz_fail("CAGD_OK but weights_out[%zu] = %g", i, wout_store[i]);
        }
    }
    if (!mb_is_poison(wout_store[len])) fz_fail("weights_out written beyond %zu", len);
}

/* The buffer call with a second (weights) output: the exact mode gets roomy weights;
 * CAGD_ERR_BUFFER_TOO_SMALL may come from a short weights buffer alone. */
#define OUTCALL_W(ob, w, rational, expr)                                                   \
    do {                                                                                   \
        fz_ob_init(&ob);                                                                   \
        wout_draw(&w, rational, ob.mode == FZ_OB_EXACT);                                   \
        for (;;) {                                                                         \
            st = fz_status(expr);                                                          \
            if (!fz_ob_again(&ob, st)) break;                                              \
        }                                                                                  \
        if (!(st == CAGD_ERR_BUFFER_TOO_SMALL && rational && !w.roomy &&                   \
              ob.needed != (size_t)-7 && ob.needed <= ob.cap))                             \
            fz_ob_check(&ob, st, 1);                                                       \
    } while (0)

/* The documented equivalence of a handle-free call and its handle form: the same
 * control points (and weights) bit for bit. `out` holds `n_out` points of `dim`. */
static void check_same_as_handle(const struct CagdCurve *h, const double *out,
                                 const double *wout, size_t n_out, size_t dim,
                                 const char *what) {
    static double hp[MB_STRIDE], hw[MB_STRIDE];
    size_t need = 0;
    if (h == NULL || n_out * dim > MB_STRIDE) return;
    if (cagd_curve_points(h, hp, MB_STRIDE, &need) != CAGD_OK) return;
    if (need != n_out * dim || memcmp(hp, out, need * sizeof(double)) != 0) {
        fz_fail("points differ from those of %s", what);
    }
    if (wout != NULL && cagd_curve_weights(h, hw, MB_STRIDE, &need) == CAGD_OK &&
        (need != n_out || memcmp(hw, wout, need * sizeof(double)) != 0)) {
        fz_fail("weights differ from those of %s", what);
    }
}

/* A handle curve of the same input (NULL when it cannot be made). */
static struct CagdCurve *same_curve(const double *pts, const double *w, size_t n, size_t dim) {
    struct CagdCurve *c = NULL;
    CagdStatus st = w != NULL ? cagd_curve_new_rational(pts, w, n, dim, &c)
                              : cagd_curve_new(pts, n, dim, &c);
    return st == CAGD_OK ? c : NULL;
}

static void op_cagd_bezier_elevate(void) {
    size_t deg = fz_deg(), dim = fz_dim(), n = fz_count(fz_add(deg, 1));
    const double *pts = fz_in(fz_mul(n, dim), FZ_VALUES);
    const double *w = fz_r(2) ? fz_in_opt(n, FZ_WEIGHTS) : NULL;
    SKIP_IF_NEEDED;
    size_t r = fz_small_deg();
    int rational = w != NULL;
    Wout wo;
    FzOb ob;
    CagdStatus st;
    OUTCALL_W(ob, wo, rational,
              cagd_bezier_elevate(pts, n, dim, w, r, ob.p, ob.cap, ob.needed_p, wo.p, wo.cap));
    if (st == CAGD_OK && ob.needed != fz_mul(fz_add(n, r), dim)) {
        fz_fail("out_needed %zu is not (n_points + r) dim", ob.needed);
    }
    wout_check(&wo, st, rational, st == CAGD_OK ? n + r : 0);
    if (st == CAGD_OK && ob.p != NULL) {
        struct CagdCurve *c = same_curve(pts, w, n, dim), *e = NULL;
        if (c != NULL && cagd_curve_elevate(c, r, &e) == CAGD_OK) {
            check_same_as_handle(e, ob.p, rational ? wo.p : NULL, n + r, dim,
                                 "cagd_curve_elevate");
        }
        cagd_curve_free(e);
        cagd_curve_free(c);
    }
}

static void op_cagd_bezier_reduce(void) {
    size_t deg = fz_deg(), dim = fz_dim(), n = fz_count(fz_add(deg, 1));
    const double *pts = fz_in(fz_mul(n, dim), FZ_VALUES);
    const double *w = fz_r(2) ? fz_in_opt(n, FZ_WEIGHTS) : NULL;
    SKIP_IF_NEEDED;
    const CagdReduceOptions *o = gen_opts();
    int rational = w != NULL;
    CagdBezierReport rep;
    memset(&rep, 0xFF, sizeof rep);
    rep.struct_size = fz_r(16) ? sizeof rep : fz_r(sizeof rep);
    int rep_n = fz_r(3) == 0;
    Wout wo;
    FzOb ob;
    CagdStatus st;
    OUTCALL_W(ob, wo, rational,
              cagd_bezier_reduce(pts, n, dim, w, o, ob.p, ob.cap, ob.needed_p, wo.p, wo.cap,
                                 rep_n ? NULL : &rep));
    if (st == CAGD_OK && ob.needed != fz_mul(fz_add(o->target, 1), dim)) {
        fz_fail("out_needed %zu is not (target + 1) dim", ob.needed);
    }
    wout_check(&wo, st, rational, st == CAGD_OK ? o->target + 1 : 0);
    if (st == CAGD_OK && ob.p != NULL && fz_r(2)) {
        struct CagdCurve *c = same_curve(pts, w, n, dim), *e = NULL;
        struct CagdReport *hr = NULL;
        if (c != NULL && cagd_curve_reduce(c, o, &e, &hr) == CAGD_OK) {
            check_same_as_handle(e, ob.p, rational ? wo.p : NULL, o->target + 1, dim,
                                 "cagd_curve_reduce");
        }
        cagd_report_free(hr);
        cagd_curve_free(e);
        cagd_curve_free(c);
    }
    if (st == CAGD_OK && !rep_n) {
        if (rep.struct_size < sizeof rep) fz_fail("CAGD_OK with report struct_size %zu", rep.struct_size);
        if (rep.degree_from != n - 1 || rep.degree_to != o->target) {
            fz_fail("report degrees %zu -> %zu, expected %zu -> %zu", rep.degree_from,
                    rep.degree_to, n - 1, o->target);
        }
        if (!isnan(rep.bound) && (!isfinite(rep.bound) || rep.bound < 0.0)) {
            fz_fail("report bound %g is not finite and >= 0", rep.bound);
        }
        if (!isnan(rep.homogeneous_bound) &&
            (!isfinite(rep.homogeneous_bound) || rep.homogeneous_bound < 0.0)) {
            fz_fail("report homogeneous_bound %g is not finite and >= 0", rep.homogeneous_bound);
        }
        if (!isnan(rep.max_error)) {
            if (!isfinite(rep.max_error) || rep.max_error < 0.0)
                fz_fail("report max_error %g is not finite and >= 0", rep.max_error);
            if (!isnan(rep.bound) && rep.max_error > rep.bound * (1.0 + 1e-12))
                fz_fail("measured error %.17g exceeds the certified bound %.17g",
                        rep.max_error, rep.bound);
        }
    }
    if (st != CAGD_OK && !rep_n && rep.degree_from != (size_t)-1) {
        fz_fail("report written on failure");
    }
}

/* ---------------------------------------------------------------- B-spline conversions */

static void op_cagd_bspline_outer_knots(void) {
    IN_H(FZ_BSPLINE, CagdBSpline, s);
    int32_t side = fz_enum(2);
    FzOb ob;
    CagdStatus st;
    OUTCALL(ob, cagd_bspline_outer_knots(s, side, ob.p, ob.cap, ob.needed_p));
    if (st == CAGD_OK) {
        size_t d = 0;
        if (cagd_bspline_degree(s, &d) == CAGD_OK && ob.needed < d) {
            fz_fail("%zu outer knots, below the degree %zu", ob.needed, d);
        }
        for (size_t i = 1; ob.p != NULL && i < ob.needed && i < 16384; ++i) {
            if (ob.p[i] < ob.p[i - 1]) fz_fail("outer knots decrease at %zu", i);
        }
    }
}

static void op_cagd_curvelist_to_bspline_unclamped(void) {
    static double lk[512], rk[512];
    const struct CagdCurveList *l = NULL;
    struct CagdCurveList *tmp = NULL;
    const double *left = NULL, *right = NULL;
    size_t nl = 0, nr = 0;
    if (fz_r(2)) {
        /* the pieces of a spline from the pool, with its own outer knots */
        const struct CagdBSpline *s = fz_pick(FZ_BSPLINE);
        size_t a = 0, b = 0;
        if (s != NULL && cagd_bspline_to_bezier_pieces(s, &tmp) == CAGD_OK &&
            cagd_bspline_outer_knots(s, CAGD_SIDE_LEFT, lk, 512, &a) == CAGD_OK &&
            cagd_bspline_outer_knots(s, CAGD_SIDE_RIGHT, rk, 512, &b) == CAGD_OK) {
            l = tmp;
            left = lk;
            right = rk;
            nl = a;
            nr = b;
            if (fz_r(8) == 0) nl = fz_count(nl);
            if (fz_r(8) == 0) nr = fz_count(nr);
            if (nl > 512 || nr > 512) {
                left = fz_in(nl, FZ_SORTED);
                right = fz_in(nr, FZ_SORTED);
            } else {
                for (size_t i = a; i < 512; ++i) lk[i] = a > 0 ? lk[a - 1] : 0.0;
                for (size_t i = b; i < 512; ++i) rk[i] = b > 0 ? rk[b - 1] : 0.0;
                if (fz_r(8) == 0 && nl > 0) lk[fz_r((uint32_t)nl)] = fz_double();
            }
            if (fz_r(48) == 0) left = NULL;
            if (fz_r(48) == 0) right = NULL;
        }
    }
    if (l == NULL) {
        l = fz_pick(FZ_CURVELIST);
        size_t d = 3;
        struct CagdCurve *c0 = NULL;
        if (l != NULL && cagd_curvelist_get(l, 0, &c0) == CAGD_OK) {
            d = curve_degree(c0, 3);
            cagd_curve_free(c0);
        }
        nl = fz_count(d);
        nr = fz_count(d);
        left = fz_in(nl, FZ_SORTED);
        right = fz_in(nr, FZ_SORTED);
    }
    fz.call_null |= l == NULL || left == NULL || right == NULL;
    double tol = fz_r(4) ? 0.0 : fz_tol();
    if (!fz.skip) {
        OUT_H(CagdBSpline, s);
        CagdStatus st =
            fz_status(cagd_curvelist_to_bspline_unclamped(l, tol, left, nl, right, nr, HP(s)));
        KEEP(FZ_BSPLINE, s);
    }
    if (tmp != NULL) fz_put(FZ_CURVELIST, tmp);
}

static void op_cagd_bsplinesurface_to_bezier_patches(void) {
    IN_H(FZ_BSURF, CagdBSplineSurface, s);
    OUT_H(CagdPatchPieceList, l);
    CagdStatus st = fz_status(cagd_bsplinesurface_to_bezier_patches(s, HP(l)));
    KEEP(FZ_PPLIST, l);
}

static void op_cagd_patchpiecelist_to_bsplinesurface(void) {
    IN_H(FZ_PPLIST, CagdPatchPieceList, l);
    double tol = fz_r(4) ? 0.0 : fz_tol();
    OUT_H(CagdBSplineSurface, s);
    OUT_SO(double, bound);
    CagdStatus st = fz_status(cagd_patchpiecelist_to_bsplinesurface(l, tol, HP(s), SP(bound)));
    FIN(bound);
    if (st == CAGD_OK && !bound_n && bound < 0.0) fz_fail("negative bound %g", bound);
    KEEP(FZ_BSURF, s);
}

static void op_cagd_report_bound_level(void) {
    IN_H(FZ_REPORT, CagdReport, r);
    OUT_S(int32_t, level);
    CagdStatus st = fz_status(cagd_report_bound_level(r, SP(level)));
    if (st == CAGD_OK && (level < CAGD_BOUND_NONE || level > CAGD_BOUND_TIGHT)) {
        fz_fail("bound level %d is not a CagdBoundLevel", (int)level);
    }
}

/* ---------------------------------------------------------------- copies */

static CagdStatus call_bspline_copy(Mb *b, void *sz) {
    return cagd_bspline_copy(mb_h, MB_D(0), MB_D(1), MB_D(2), sz);
}
static void lens_bspline(const void *p, size_t *len) {
    const CagdBSplineSizes *s = p;
    len[0] = s->knots_len;
    len[1] = s->points_len;
    len[2] = s->weights_len;
}

static void op_cagd_bspline_copy(void) {
    IN_H(FZ_BSPLINE, CagdBSpline, s);
    static const int dbl[] = {1, 1, 1};
    static const char *const names[] = {"knots_out", "points_out", "weights_out"};
    Mb b[3];
    size_t len[3];
    CagdBSplineSizes sz;
    mb_h = s;
    CagdStatus st = mb_run(3, dbl, names, call_bspline_copy, lens_bspline, &sz, sizeof sz, len, b);
    if (st == CAGD_OK && (sz.knots_len != sz.n_points + sz.degree + 1 ||
                          sz.points_len != sz.n_points * sz.dim ||
                          sz.weights_len != (sz.rational ? sz.n_points : 0))) {
        fz_fail("inconsistent CagdBSplineSizes");
    }
    if (st == CAGD_OK && b[0].p != NULL) {
        for (size_t i = 1; i < len[0]; ++i) {
            if (mb_store[0][i] < mb_store[0][i - 1]) fz_fail("knots_out decrease at %zu", i);
        }
    }
    if (st == CAGD_OK && b[2].p != NULL) {
        for (size_t i = 0; i < len[2]; ++i) {
            if (!(mb_store[2][i] > 0.0)) fz_fail("weights_out[%zu] = %g", i, mb_store[2][i]);
        }
    }
}

static CagdStatus call_curvelist_copy(Mb *b, void *sz) {
    return cagd_curvelist_copy(mb_h, MB_SZ(0), MB_D(1), MB_D(2), MB_D(3), MB_D(4), sz);
}
static void lens_curvelist(const void *p, size_t *len) {
    const CagdCurveListSizes *s = p;
    len[0] = s->n_pieces;
    len[1] = s->intervals_len;
    len[2] = s->points_len;
    len[3] = s->weights_len;
    len[4] = s->bounds_len;
}

static void op_cagd_curvelist_copy(void) {
    IN_H(FZ_CURVELIST, CagdCurveList, l);
    static const int dbl[] = {0, 1, 1, 1, 1};
    static const char *const names[] = {"degrees_out", "intervals_out", "points_out",
                                        "weights_out", "bounds_out"};
    Mb b[5];
    size_t len[5];
    CagdCurveListSizes sz;
    mb_h = l;
    CagdStatus st =
        mb_run(5, dbl, names, call_curvelist_copy, lens_curvelist, &sz, sizeof sz, len, b);
    if (st != CAGD_OK) return;
    if (sz.intervals_len != 2 * sz.n_pieces ||
        (sz.bounds_len != 0 && sz.bounds_len != sz.n_pieces) ||
        (sz.rational != (sz.weights_len > 0)) || sz.n_pieces != list_count(FZ_CURVELIST, l)) {
        fz_fail("inconsistent CagdCurveListSizes");
    }
    if (b[0].p != NULL) {
        size_t pts = 0, ws = 0;
        for (size_t i = 0; i < sz.n_pieces; ++i) {
            pts += (mb_sz(0, i) + 1) * sz.dim;
            ws += mb_sz(0, i) + 1;
        }
        if (pts != sz.points_len || (sz.rational && ws != sz.weights_len)) {
            fz_fail("points_len / weights_len do not match the degrees");
        }
    }
    if (b[1].p != NULL) {
        for (size_t i = 0; i < sz.n_pieces; ++i) {
            if (!(mb_store[1][2 * i] < mb_store[1][2 * i + 1])) fz_fail("empty interval %zu", i);
        }
    }
    for (size_t i = 0; b[3].p != NULL && i < sz.weights_len; ++i) {
        if (!(mb_store[3][i] > 0.0)) fz_fail("weights_out[%zu] = %g", i, mb_store[3][i]);
    }
    for (size_t i = 0; b[4].p != NULL && i < sz.bounds_len; ++i) {
        if (mb_store[4][i] < 0.0) fz_fail("bounds_out[%zu] = %g", i, mb_store[4][i]);
    }
}

static CagdStatus call_tensorlist_copy(Mb *b, void *sz) {
    return cagd_tensorpatchlist_copy(mb_h, MB_SZ(0), MB_D(1), MB_D(2), MB_D(3), sz);
}
static CagdStatus call_trilist_copy(Mb *b, void *sz) {
    return cagd_tripatchlist_copy(mb_h, MB_SZ(0), MB_D(1), MB_D(2), MB_D(3), sz);
}
static void lens_patchlist(const void *p, size_t *len) {
    const CagdPatchListSizes *s = p;
    len[0] = s->degrees_len;
    len[1] = s->domains_len;
    len[2] = s->points_len;
    len[3] = s->bounds_len;
}

/* The list pools fill slowly (the to-tolerance reductions seldom succeed on random
 * options): now and then a list of a small random source reduced with good options, so
 * that the copies run on real lists. */
static void seed_list(FzType t) {
    if (fz_r(2) || fz.pools[t].n >= 2) return;
    double p[64];
    for (size_t i = 0; i < 64; ++i) p[i] = 2.0 * fz_unit() - 1.0;
    CagdReduceOptions o;
    (void)cagd_reduce_options_init(&o);
    o.target = 2;
    o.target_v = 2;
    o.tolerance = 0.01 + 0.5 * fz_unit();
    struct CagdReport *rep = NULL;
    CagdStatus st = CAGD_OK;
    if (t == FZ_TENSORLIST) {
        struct CagdTensorPatch *src = NULL;
        struct CagdTensorPatchList *l = NULL;
        if (cagd_tensorpatch_new(p, 3, 1 + fz_r(3), 1 + fz_r(3), &src) == CAGD_OK) {
            st = SIDE(cagd_tensorpatch_reduce_to_tolerance,
                      cagd_tensorpatch_reduce_to_tolerance(src, &o, &l, &rep));
            if (st == CAGD_OK) fz_put(t, l);
        }
        cagd_tensorpatch_free(src);
    } else if (t == FZ_TRILIST) {
        struct CagdTriPatch *src = NULL;
        struct CagdTriPatchList *l = NULL;
        if (cagd_tripatch_new(p, 3 + fz_r(2), 1 + fz_r(3), &src) == CAGD_OK) {
            st = SIDE(cagd_tripatch_reduce_to_tolerance,
                      cagd_tripatch_reduce_to_tolerance(src, &o, &l, &rep));
            if (st == CAGD_OK) fz_put(t, l);
        }
        cagd_tripatch_free(src);
    } else {
        struct CagdWsgbCurve *src = NULL;
        struct CagdWsgbCurveList *l = NULL;
        o.target = 3 + fz_r(2);
        if (cagd_wsgb_new(p, 6 + fz_r(3), 1 + fz_r(3), fz_r(2), &src) == CAGD_OK) {
            st = SIDE(cagd_wsgb_reduce_to_tolerance,
                      cagd_wsgb_reduce_to_tolerance(src, (int32_t)fz_r(3), &o, &l));
            if (st == CAGD_OK) fz_put(t, l);
        }
        cagd_wsgb_free(src);
    }
    cagd_report_free(rep);
}

static void patchlist_copy(FzType t) {
    seed_list(t);
    const void *l = fz_pick(t);
    fz.call_null |= l == NULL;
    static const int dbl[] = {0, 1, 1, 1};
    static const char *const names[] = {"degrees_out", "domains_out", "points_out",
                                        "bounds_out"};
    Mb b[4];
    size_t len[4];
    CagdPatchListSizes sz;
    mb_h = l;
    int tensor = t == FZ_TENSORLIST;
    CagdStatus st = mb_run(4, dbl, names, tensor ? call_tensorlist_copy : call_trilist_copy,
                           lens_patchlist, &sz, sizeof sz, len, b);
    if (st != CAGD_OK) return;
    size_t n = sz.n_pieces;
    if (sz.degrees_len != (tensor ? 2 : 1) * n || sz.domains_len != (tensor ? 4 : 6) * n ||
        sz.bounds_len != n || n != list_count(t, l)) {
        fz_fail("inconsistent CagdPatchListSizes");
    }
    if (b[0].p != NULL) {
        size_t pts = 0;
        for (size_t i = 0; i < n; ++i) {
            pts += tensor ? (mb_sz(0, 2 * i) + 1) * (mb_sz(0, 2 * i + 1) + 1) * sz.dim
                          : fz_tri(mb_sz(0, i)) * sz.dim;
        }
        if (pts != sz.points_len) fz_fail("points_len %zu does not match the degrees", pts);
    }
    for (size_t i = 0; b[3].p != NULL && i < n; ++i) {
        if (mb_store[3][i] < 0.0) fz_fail("bounds_out[%zu] = %g", i, mb_store[3][i]);
    }
}

static void op_cagd_tensorpatchlist_copy(void) { patchlist_copy(FZ_TENSORLIST); }

static void op_cagd_tripatchlist_copy(void) { patchlist_copy(FZ_TRILIST); }

static CagdStatus call_wsgblist_copy(Mb *b, void *sz) {
    return cagd_wsgblist_copy(mb_h, MB_SZ(0), MB_SZ(1), MB_D(2), MB_D(3), MB_D(4), sz);
}
static void lens_wsgblist(const void *p, size_t *len) {
    const CagdWsgbListSizes *s = p;
    len[0] = s->n_pieces;
    len[1] = s->n_pieces;
    len[2] = s->intervals_len;
    len[3] = s->points_len;
    len[4] = s->n_pieces;
}

static void op_cagd_wsgblist_copy(void) {
    seed_list(FZ_WSGBLIST);
    IN_H(FZ_WSGBLIST, CagdWsgbCurveList, l);
    static const int dbl[] = {0, 0, 1, 1, 1};
    static const char *const names[] = {"degrees_out", "orders_out", "intervals_out",
                                        "points_out", "bounds_out"};
    Mb b[5];
    size_t len[5];
    CagdWsgbListSizes sz;
    mb_h = l;
    CagdStatus st = mb_run(5, dbl, names, call_wsgblist_copy, lens_wsgblist, &sz, sizeof sz, len, b);
    if (st != CAGD_OK) return;
    if (sz.intervals_len != 2 * sz.n_pieces || sz.n_pieces != list_count(FZ_WSGBLIST, l)) {
        fz_fail("inconsistent CagdWsgbListSizes");
    }
    if (b[0].p != NULL) {
        size_t pts = 0;
        for (size_t i = 0; i < sz.n_pieces; ++i) pts += (mb_sz(0, i) + 1) * sz.dim;
        if (pts != sz.points_len) fz_fail("points_len does not match the degrees");
    }
    for (size_t i = 0; b[4].p != NULL && i < sz.n_pieces; ++i) {
        if (mb_store[4][i] < 0.0) fz_fail("bounds_out[%zu] = %g", i, mb_store[4][i]);
    }
}

/* ---------------------------------------------------------------- the table */

#define X(name) #name,
static const char *const NAMES[] = {FZ_FUNCS};
#undef X
#define X(name) op_##name,
static void (*const OPS[])(void) = {FZ_FUNCS};
#undef X

size_t fz_n_ops(void) { return FN_COUNT; }

const char *fz_fn_name(int index) { return NAMES[index]; }

/* Operations that take milliseconds on the larger inputs: drawn 16 times less often so
 * that a long run makes its 10^7 calls in minutes (they still run thousands of times). */
static int heavy(int i) {
    switch (i) {
    case FN_cagd_bspline_to_polynomial:
    case FN_cagd_bsplinesurface_to_polynomial:
    case FN_cagd_tensorpatch_distance:
    case FN_cagd_tripatch_distance:
    case FN_cagd_curve_reduce_exact:
    case FN_cagd_curve_distance:
    case FN_cagd_wsgb_reduce_to_tolerance:
        return 1;
    default:
        return 0;
    }
}

static uint64_t ticks(void);
static void time_call(int op, uint64_t dt);

static int only = -2; /* CAGD_FUZZ_ONLY=<function>: run that operation alone */
static int trace = -1; /* CAGD_FUZZ_TRACE=1: name every call on stderr (to read a replay) */

void fz_op_random(void) {
    if (only == -2) {
        only = -1;
        const char *o = getenv("CAGD_FUZZ_ONLY");
        for (int k = 0; o != NULL && k < FN_COUNT; ++k) {
            if (strcmp(o, NAMES[k]) == 0) only = k;
        }
    }
    int i = (int)fz_r(FN_COUNT);
    if (only >= 0) i = only;
    while ((heavy(i) && fz_r(16) != 0) ||
           (i == FN_cagd_bsplinesurface_to_polynomial && fz_r(16) != 0)) {
        i = (int)fz_r(FN_COUNT);
    }
    if (trace < 0) {
        const char *t = getenv("CAGD_FUZZ_TRACE");
        trace = t != NULL && t[0] == '1';
    }
    if (trace) {
        fprintf(stderr, "call %llu: %s\n", (unsigned long long)fz.session_call, NAMES[i]);
    }
    fz_begin(i);
    uint64_t t0 = ticks();
    OPS[i]();
    time_call(i, ticks() - t0);
}

/* CPU time per operation without a system call per call: clock() (a system call of about
 * 1.3 us here; two per call were 14 % of a run's CPU) is read once per window of about
 * 4 ms of cycle counter (rdtsc, a few ns), and the window's CPU time is shared among its
 * calls in proportion to their cycles. A call of 1 s CPU takes at least 1 s / cores of
 * wall time, so it closes its window nearly alone and its share is its own CPU time
 * (within the window's other few ms): the `slow call` report stays a CPU figure. Without
 * a cycle counter every call is its own window (one clock() per call). */
#if defined(__x86_64__) || defined(__i386__)
#include <x86intrin.h>
static uint64_t ticks(void) { return __rdtsc(); }
#define WINDOW_TICKS 4000000ull
#else
static uint64_t ticks(void) { return 0; }
#define WINDOW_TICKS 0ull
#endif

static struct {
    clock_t clk;           /* clock() at the window's start; (clock_t)-1 before the first */
    uint64_t total;        /* cycles of the window's calls */
    uint64_t op_ticks[FN_COUNT];
    int touched[FN_COUNT]; /* the operations with cycles in the window */
    int n_touched;
    int last_op;           /* the call that closed the window */
    uint64_t last_ticks;
} win = {.clk = (clock_t)-1};

void fz_time_flush(void) {
    if (win.clk == (clock_t)-1 || win.n_touched == 0) return;
    clock_t now = clock();
    double cpu = (double)(now - win.clk) / CLOCKS_PER_SEC;
    double total = win.total > 0 ? (double)win.total : 1.0;
    for (int k = 0; k < win.n_touched; ++k) {
        int op = win.touched[k];
        double share = win.total > 0 ? (double)win.op_ticks[op] / total : 1.0 / win.n_touched;
        fz.stats[op].secs += cpu * share;
        win.op_ticks[op] = 0;
    }
    double own = win.total > 0 ? cpu * ((double)win.last_ticks / total) : cpu;
    if (own > 1.0) {
        fprintf(stderr, "slow call: %s took %.1f s CPU (session seed 0x%016llx, call %llu)\n",
                NAMES[win.last_op], own, (unsigned long long)fz.session_seed,
                (unsigned long long)fz.session_call);
    }
    win.clk = now;
    win.total = 0;
    win.n_touched = 0;
}

static void time_call(int op, uint64_t dt) {
    if (win.clk == (clock_t)-1) win.clk = clock();
    if (win.op_ticks[op] == 0) win.touched[win.n_touched++] = op;
    win.op_ticks[op] += dt > 0 ? dt : 1;
    win.total += dt;
    win.last_op = op;
    win.last_ticks = dt;
    if (win.total >= WINDOW_TICKS) fz_time_flush();
}
