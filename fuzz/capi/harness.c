/* The cagd C ABI fuzz harness: infrastructure (decision source, generators, handle pools,
 * the oracle). The per-function operations are in ops.c. See fuzz/capi/README.md. */
#include "harness_impl.h"
#include "statuses.h"

#include <float.h>
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

Fz fz;

double fz_in_buf[FZ_IN_CAP];
double fz_out_buf[FZ_OUT_CAP];

/* ---------------------------------------------------------------- decision source */

static uint64_t splitmix(uint64_t *x) {
    uint64_t z = (*x += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

uint64_t fz_u64(void) {
    if (fz.data == NULL) {
        uint64_t x = fz.state;
        x ^= x << 13;
        x ^= x >> 7;
        x ^= x << 17;
        fz.state = x;
        return x;
    }
    uint64_t v = 0;
    for (int i = 0; i < 8; ++i) {
        if (fz.pos >= fz.len) {
            fz.exhausted = 1;
            break;
        }
        v = (v << 8) | fz.data[fz.pos++];
    }
    return v;
}

uint32_t fz_r(uint32_t bound) {
    if (bound <= 1) {
        return 0;
    }
    if (fz.data != NULL && bound <= 256) {
        if (fz.pos >= fz.len) {
            fz.exhausted = 1;
            return 0;
        }
        return fz.data[fz.pos++] % bound;
    }
    return (uint32_t)(fz_u64() % bound);
}

double fz_unit(void) { return (double)(fz_u64() >> 11) * (1.0 / 9007199254740992.0); }

/* ---------------------------------------------------------------- generators */

static const double EXTREME[] = {
    0.0,     -0.0,    1.0,     -1.0,   0.5,      1e308,     -1e308, 1e-320,
    -1e-320, DBL_MAX, DBL_MIN, 1e-300, 1e300,    1e16,      -1e16,  2.220446049250313e-16,
    NAN,     -NAN,    INFINITY, -INFINITY, 1e-8, 1.0 + 1e-15, 3.0,  100.0,
};
#define N_EXTREME (sizeof EXTREME / sizeof EXTREME[0])

double fz_extreme(void) { return EXTREME[fz_r((uint32_t)N_EXTREME)]; }

double fz_double(void) {
    switch (fz_r(16)) {
    case 0:
        return fz_extreme();
    case 1:
        return (double)((int)fz_r(21) - 10);
    case 2:
        return fz_unit();
    default:
        return 2.0 * fz_unit() - 1.0;
    }
}

double fz_param(void) {
    switch (fz_r(16)) {
    case 0:
        return fz_extreme();
    case 1:
        return (double)fz_r(3) * 0.5;
    case 2:
        return 2.0 * fz_unit() - 0.5;
    default:
        return fz_unit();
    }
}

double fz_tol(void) {
    switch (fz_r(16)) {
    case 0:
        return fz_extreme();
    case 1:
        return 0.0;
    case 2:
        return 1e-12;
    default:
        return pow(10.0, -1.0 - 6.0 * fz_unit());
    }
}

static const size_t HUGE_SIZES[] = {SIZE_MAX, SIZE_MAX - 1, SIZE_MAX / 2,
                                    (size_t)1 << 61, ((size_t)1 << 62) + 3};
#define N_HUGE (sizeof HUGE_SIZES / sizeof HUGE_SIZES[0])

size_t fz_huge(void) { return HUGE_SIZES[fz_r((uint32_t)N_HUGE)]; }

size_t fz_deg(void) {
    switch (fz_r(64)) {
    case 0:
        return fz_huge();
    case 1:
    case 2:
        return fz_r(101);
    case 3:
        return 60 + fz_r(10);
    default:
        return fz_r(7);
    }
}

size_t fz_small_deg(void) {
    switch (fz_r(64)) {
    case 0:
        return fz_huge();
    case 1:
        return fz_r(101);
    case 2:
    case 3:
        return 6 + fz_r(10);
    default:
        return fz_r(6);
    }
}

size_t fz_dim(void) {
    switch (fz_r(48)) {
    case 0:
        return 0;
    case 1:
        return fz_huge();
    case 2:
        return 4 + fz_r(5);
    default:
        return 1 + fz_r(3);
    }
}

size_t fz_count(size_t good) {
    switch (fz_r(32)) {
    case 0:
        return 0;
    case 1:
        return fz_huge();
    case 2:
        return fz_r(64);
    case 3:
        return good + 1;
    case 4:
        return good > 0 ? good - 1 : 0;
    default:
        return good;
    }
}

size_t fz_index(size_t count) {
    switch (fz_r(16)) {
    case 0:
        return count;
    case 1:
        return fz_huge();
    default:
        return count > 0 ? fz_r((uint32_t)(count < 64 ? count : 64)) : 0;
    }
}

int32_t fz_enum(int32_t n_valid) {
    switch (fz_r(16)) {
    case 0:
        return (int32_t)fz_u64();
    case 1:
        return -1;
    case 2:
        return n_valid;
    default:
        return (int32_t)fz_r((uint32_t)n_valid);
    }
}

size_t fz_mul(size_t a, size_t b) {
    if (a != 0 && b > SIZE_MAX / a) {
        return SIZE_MAX;
    }
    return a * b;
}

size_t fz_add(size_t a, size_t b) { return a > SIZE_MAX - b ? SIZE_MAX : a + b; }

size_t fz_tri(size_t n) { /* (n + 1)(n + 2) / 2, saturated */
    size_t a = fz_add(n, 1), b = fz_add(n, 2);
    if (a == SIZE_MAX || b == SIZE_MAX) {
        return SIZE_MAX;
    }
    return (a % 2 == 0) ? fz_mul(a / 2, b) : fz_mul(a, b / 2);
}

/* ---------------------------------------------------------------- input arrays */

/* Reserves `need` doubles of the input buffer (8-byte aligned, one spare double after
 * them). Returns NULL and sets fz.skip when `need` is possible memory the buffer cannot
 * hold (the call is then not made); for an impossible length (more than a Rust slice
 * can hold) returns an unfilled pointer: cagd must refuse it before reading. */
static double *reserve(size_t need, int *impossible) {
    *impossible = 0;
    if (need > (size_t)PTRDIFF_MAX / sizeof(double)) {
        *impossible = 1;
        fz.call_impossible = 1;
        return fz_in_buf;
    }
    if (need > FZ_IN_CAP - 2 || fz.in_used + need + 2 > FZ_IN_CAP) {
        fz.skip = 1;
        return NULL;
    }
    double *p = fz_in_buf + fz.in_used;
    fz.in_used += need + 2;
    return p;
}

/* Maybe NULL (1/40) or misaligned (1/80, when not empty) instead of `p`. */
static const double *mangle(double *p, size_t need, int nullable_ok) {
    uint32_t k = fz_r(80);
    if (k < 2 && !nullable_ok) {
        fz.call_null = 1;
        return NULL;
    }
    if (k == 2 && need > 0) {
        fz.call_misaligned = 1;
        return (const double *)(const void *)((char *)p + 4);
    }
    return p;
}

static void fill_values(double *p, size_t n) {
    uint32_t mode = fz_r(20);
    double scale = 1.0, shift = 0.0;
    if (mode == 0) {
        for (size_t i = 0; i < n; ++i) {
            p[i] = fz_extreme();
        }
        return;
    }
    if (mode == 1) {
        double c = fz_double();
        for (size_t i = 0; i < n; ++i) {
            p[i] = c;
        }
        return;
    }
    if (mode == 2) {
        static const double SCALES[] = {1e-6, 1e6, 1e8, 1e-3, 1e150};
        scale = SCALES[fz_r(5)];
        shift = (fz_r(2) ? 1e8 : 1e-6) * fz_double();
    }
    for (size_t i = 0; i < n; ++i) {
        p[i] = shift + scale * (2.0 * fz_unit() - 1.0);
    }
    if (mode == 3 && n > 0) {
        p[fz_r(n < 4096 ? (uint32_t)n : 4096)] = fz_extreme();
    }
}

const double *fz_in(size_t need, FzKind kind) {
    int impossible;
    double *p = reserve(need, &impossible);
    if (p == NULL) {
        return NULL;
    }
    if (!impossible) {
        fz_fill(p, need, kind);
    }
    return mangle(p, need, 0);
}

const double *fz_in_opt(size_t need, FzKind kind) {
    if (fz_r(4) == 0) {
        return NULL;
    }
    int impossible;
    double *p = reserve(need, &impossible);
    if (p == NULL) {
        return NULL;
    }
    if (!impossible) {
        fz_fill(p, need, kind);
    }
    return mangle(p, need, 1);
}

void fz_fill(double *p, size_t n, FzKind kind) {
    switch (kind) {
    case FZ_VALUES:
        fill_values(p, n);
        return;
    case FZ_PARAMS:
        for (size_t i = 0; i < n; ++i) {
            p[i] = fz_param();
        }
        return;
    case FZ_WEIGHTS: {
        uint32_t mode = fz_r(16);
        for (size_t i = 0; i < n; ++i) {
            p[i] = mode == 0 ? fz_double() : (mode == 1 ? 1.0 : 0.2 + 4.8 * fz_unit());
        }
        if (mode == 2 && n > 0) {
            p[fz_r(n < 4096 ? (uint32_t)n : 4096)] = fz_extreme();
        }
        return;
    }
    case FZ_SORTED: {
        /* Non-decreasing knots; clamped ends (multiplicity from the caller's degree) are
         * made by fz_knots; here a plain sorted set, sometimes broken. */
        double t = fz_r(8) == 0 ? fz_double() : 0.0;
        for (size_t i = 0; i < n; ++i) {
            p[i] = t;
            if (fz_r(4) != 0) {
                t += fz_r(8) == 0 ? fz_extreme() : fz_unit();
            }
        }
        if (fz_r(16) == 0 && n > 1) {
            p[fz_r(n < 4096 ? (uint32_t)n : 4096)] = fz_extreme();
        }
        return;
    }
    }
}

const double *fz_knots(size_t n_knots, size_t degree) {
    int impossible;
    double *p = reserve(n_knots, &impossible);
    if (p == NULL) {
        return NULL;
    }
    if (!impossible) {
        if (fz_r(4) == 0 || degree >= n_knots) {
            fz_fill(p, n_knots, FZ_SORTED);
        } else if (fz_r(4) == 0) {
            /* Uniform, unclamped (seed 001's uniform B-splines, the only input
             * cagd_bspline_reduce_uniform accepts): a + i h, sometimes far from zero or
             * with an extreme spacing. */
            double a = fz_r(2) == 0 ? 0.0 : fz_double() * 1e3;
            double h = fz_r(4) == 0 ? fz_extreme() : 0.25 * (double)(1 + fz_r(4));
            for (size_t i = 0; i < n_knots; ++i) {
                p[i] = a + h * (double)i;
            }
        } else {
            /* Clamped: degree + 1 equal ends, interior increasing (with some repeats). */
            size_t m = degree + 1;
            double a = fz_r(4) == 0 ? fz_double() * 1e3 : 0.0;
            double len = fz_r(4) == 0 ? fz_extreme() : 1.0 + (double)fz_r(4);
            size_t n_in = n_knots >= 2 * m ? n_knots - 2 * m : 0;
            for (size_t i = 0; i < n_knots; ++i) {
                if (i < m || n_knots < 2 * m) {
                    p[i] = a;
                } else if (i >= n_knots - m) {
                    p[i] = a + len;
                } else {
                    size_t j = i - m + 1;
                    if (fz_r(8) == 0 && i > m) {
                        p[i] = p[i - 1];
                    } else {
                        p[i] = a + len * (double)j / (double)(n_in + 1);
                    }
                }
            }
        }
    }
    return mangle(p, n_knots, 0);
}

/* ---------------------------------------------------------------- output buffers */

static const uint64_t POISON_BITS = 0x7FF4DEADBEEF0001ull;

static double poison(void) {
    double d;
    memcpy(&d, &POISON_BITS, sizeof d);
    return d;
}

static int is_poison(double d) {
    uint64_t b;
    memcpy(&b, &d, sizeof b);
    return b == POISON_BITS;
}

#define POISON_LIMIT 16384

static void poison_prefix(double *p, size_t n) {
    if (n > POISON_LIMIT) {
        n = POISON_LIMIT;
    }
    double q = poison();
    for (size_t i = 0; i < n; ++i) {
        p[i] = q;
    }
}

void fz_ob_init(FzOb *ob) {
    memset(ob, 0, sizeof *ob);
    ob->needed = (size_t)-7;
    ob->needed_p = &ob->needed;
    ob->base = fz_out_buf + fz.out_used;
    size_t room = FZ_OUT_CAP - fz.out_used - 2;
    switch (fz_r(16)) {
    case 0:
        ob->mode = FZ_OB_QUERY;
        ob->p = NULL;
        ob->cap = 0;
        break;
    case 1:
        ob->mode = FZ_OB_NULL_WITH_CAP;
        ob->p = NULL;
        ob->cap = 1 + fz_r(8);
        break;
    case 2:
        ob->mode = FZ_OB_SMALL;
        ob->p = ob->base;
        ob->cap = fz_r(8);
        break;
    case 3:
        ob->mode = FZ_OB_MISALIGNED;
        ob->p = (double *)(void *)((char *)ob->base + 4);
        ob->cap = fz_r(64) < room ? fz_r(64) : 0;
        break;
    case 4:
        ob->mode = FZ_OB_NULL_NEEDED;
        ob->p = ob->base;
        ob->cap = room < 64 ? room : 64;
        ob->needed_p = NULL;
        break;
    case 5:
    case 6:
        ob->mode = FZ_OB_ROOMY;
        ob->p = ob->base;
        ob->cap = room < POISON_LIMIT ? room : POISON_LIMIT;
        break;
    default:
        ob->mode = FZ_OB_EXACT;
        ob->p = NULL;
        ob->cap = 0;
        break;
    }
    if (ob->p != NULL && ob->mode != FZ_OB_MISALIGNED) {
        poison_prefix(ob->p, ob->cap + 8);
    }
}

int fz_ob_again(FzOb *ob, CagdStatus st) {
    if (ob->mode != FZ_OB_EXACT || ob->phase != 0) {
        if (ob->mode == FZ_OB_EXACT && st == CAGD_ERR_BUFFER_TOO_SMALL) {
            fz_fail("size query said %zu doubles, but a buffer of exactly that is too small"
                    " (now %zu)",
                    ob->cap, ob->needed);
        }
        return 0;
    }
    if (st != CAGD_ERR_BUFFER_TOO_SMALL) {
        return 0;
    }
    size_t room = FZ_OUT_CAP - fz.out_used - 16;
    if (ob->needed == (size_t)-7) {
        fz_fail("CAGD_ERR_BUFFER_TOO_SMALL without writing *out_needed");
    }
    if (ob->needed == 0) {
        fz_fail("CAGD_ERR_BUFFER_TOO_SMALL with capacity 0 and *out_needed = 0");
    }
    if (ob->needed > room || ob->needed > POISON_LIMIT - 16) {
        return 0;
    }
    ob->phase = 1;
    ob->p = ob->base;
    ob->cap = ob->needed;
    poison_prefix(ob->p, ob->cap + 8);
    ob->needed = (size_t)-7;
    return 1;
}

void fz_ob_check(FzOb *ob, CagdStatus st, int finite) {
    if (st == CAGD_ERR_BUFFER_TOO_SMALL) {
        if (ob->needed_p == NULL) {
            fz_fail("CAGD_ERR_BUFFER_TOO_SMALL with out_needed = NULL");
        }
        if (ob->needed <= ob->cap) {
            fz_fail("CAGD_ERR_BUFFER_TOO_SMALL but *out_needed = %zu <= out_cap = %zu",
                    ob->needed, ob->cap);
        }
    }
    if (st != CAGD_OK) {
        return;
    }
    if (ob->mode == FZ_OB_NULL_NEEDED) {
        fz_fail("CAGD_OK with out_needed = NULL");
    }
    if (ob->mode == FZ_OB_NULL_WITH_CAP) {
        fz_fail("CAGD_OK with out = NULL and out_cap = %zu", ob->cap);
    }
    if (ob->mode == FZ_OB_MISALIGNED) {
        fz_fail("CAGD_OK with a misaligned out buffer");
    }
    if (ob->needed > ob->cap) {
        fz_fail("CAGD_OK but *out_needed = %zu > out_cap = %zu", ob->needed, ob->cap);
    }
    if (ob->p == NULL) {
        return;
    }
    size_t n = ob->needed < POISON_LIMIT ? ob->needed : POISON_LIMIT;
    for (size_t i = 0; i < n; ++i) {
        if (is_poison(ob->p[i])) {
            fz_fail("CAGD_OK but out[%zu] of %zu was not written", i, ob->needed);
        }
        if (finite && !isfinite(ob->p[i])) {
            fz_fail("CAGD_OK but out[%zu] = %g is not finite", i, ob->p[i]);
        }
    }
    size_t poisoned = ob->cap + 8 < POISON_LIMIT ? ob->cap + 8 : POISON_LIMIT;
    for (size_t i = n; i < poisoned && i < n + 8; ++i) {
        if (!is_poison(ob->p[i])) {
            fz_fail("out[%zu] written beyond *out_needed = %zu", i, ob->needed);
        }
    }
}

/* ---------------------------------------------------------------- pools */

static void (*const FREE_FN[FZ_N_TYPES])(void *) = {
    [FZ_CURVE] = (void (*)(void *))cagd_curve_free,
    [FZ_CURVELIST] = (void (*)(void *))cagd_curvelist_free,
    [FZ_BSPLINE] = (void (*)(void *))cagd_bspline_free,
    [FZ_BSURF] = (void (*)(void *))cagd_bsplinesurface_free,
    [FZ_IMPLICIT] = (void (*)(void *))cagd_implicit_free,
    [FZ_ITRI] = (void (*)(void *))cagd_intervaltri_free,
    [FZ_PPLIST] = (void (*)(void *))cagd_patchpiecelist_free,
    [FZ_TENSOR] = (void (*)(void *))cagd_tensorpatch_free,
    [FZ_TENSORLIST] = (void (*)(void *))cagd_tensorpatchlist_free,
    [FZ_TRI] = (void (*)(void *))cagd_tripatch_free,
    [FZ_TRILIST] = (void (*)(void *))cagd_tripatchlist_free,
    [FZ_REPORT] = (void (*)(void *))cagd_report_free,
    [FZ_WSGB] = (void (*)(void *))cagd_wsgb_free,
    [FZ_WSGBLIST] = (void (*)(void *))cagd_wsgblist_free,
};

void fz_put(FzType t, void *h) {
    FzPool *pool = &fz.pools[t];
    if (pool->n == FZ_POOL) {
        uint32_t k = fz_r(FZ_POOL);
        FREE_FN[t](pool->h[k]);
        pool->h[k] = h;
        pool->maker[k] = fz.fn_index;
        return;
    }
    pool->maker[pool->n] = fz.fn_index;
    pool->h[pool->n++] = h;
}

void *fz_pick(FzType t) {
    FzPool *pool = &fz.pools[t];
    if (pool->n == 0 || fz_r(24) == 0) {
        return NULL;
    }
    uint32_t k = fz_r((uint32_t)pool->n);
    fz.last_maker = pool->maker[k];
    return pool->h[k];
}

void *fz_take(FzType t) {
    FzPool *pool = &fz.pools[t];
    if (pool->n == 0 || fz_r(8) == 0) {
        return NULL;
    }
    uint32_t k = fz_r((uint32_t)pool->n);
    void *h = pool->h[k];
    --pool->n;
    pool->h[k] = pool->h[pool->n];
    pool->maker[k] = pool->maker[pool->n];
    return h;
}

static void free_all(void) {
    for (int t = 0; t < FZ_N_TYPES; ++t) {
        while (fz.pools[t].n > 0) {
            FREE_FN[t](fz.pools[t].h[--fz.pools[t].n]);
        }
    }
}

/* ---------------------------------------------------------------- the oracle */

/* Keep-going mode (CAGD_FUZZ_KEEP_GOING=1, diagnostics only): a violation is printed once
 * per (function, kind), counted, and the session goes on (the failed call's handles may
 * leak). */
static jmp_buf keep_going_jmp;
static int keep_going_armed;
static struct {
    const char *fn;
    const char *fmt;
    int code; /* the status of a status-oracle violation, -1 for the others */
    uint64_t count;
} seen[256];
static int fail_code = -1;
static const char *fail_fn; /* the function of a status-oracle violation (maybe a side call) */
static size_t n_seen;
uint64_t fz_violations; /* violations seen in keep-going mode */

void fz_fail(const char *fmt, ...) {
    fflush(stdout);
    if (keep_going_armed) {
        const char *fn = fail_fn != NULL ? fail_fn : fz.fn;
        ++fz_violations;
        for (size_t i = 0; i < n_seen; ++i) {
            if (seen[i].fn == fn && seen[i].fmt == fmt && seen[i].code == fail_code) {
                seen[i].count++;
                longjmp(keep_going_jmp, 1);
            }
        }
        if (n_seen < 256) {
            seen[n_seen].fn = fn;
            seen[n_seen].fmt = fmt;
            seen[n_seen].code = fail_code;
            seen[n_seen].count = 1;
            ++n_seen;
        }
    }
    fprintf(stderr, "\ncagd C ABI fuzz: ORACLE VIOLATION in %s (session seed 0x%016llx, call %llu"
            " of the session, %llu in all)\n  ",
            fz.fn ? fz.fn : "?", (unsigned long long)fz.session_seed,
            (unsigned long long)fz.session_call, (unsigned long long)fz.total_calls);
    va_list ap;
    va_start(ap, fmt);
    vfprintf(stderr, fmt, ap);
    va_end(ap);
    fprintf(stderr, "\n  last error message: %s\n", cagd_last_error_message());
    if (fz.last_maker >= 0) {
        fprintf(stderr, "  the last input handle picked was made by %s\n",
                fz_fn_name(fz.last_maker));
    }
    fflush(stderr);
    if (keep_going_armed) {
        longjmp(keep_going_jmp, 1);
    }
    abort();
}

/* The per-function status oracle: bit `code` of doc_mask[i] is set when the doc comment
 * of operation i's function lists status `code` (statuses.h, generated from the doc
 * comments of include/cagd.h). doc_listed[i] is 0 for a function that returns no
 * CagdStatus. Filled once, by name, before the first call. */
static uint64_t doc_mask[FZ_MAX_OPS][2];
static int doc_listed[FZ_MAX_OPS];
static int doc_ready;

static void doc_init(void) {
    if (doc_ready) {
        return;
    }
    size_t n_rows = sizeof FZ_DOC_STATUSES / sizeof FZ_DOC_STATUSES[0];
    for (size_t i = 0; i < fz_n_ops(); ++i) {
        const char *name = fz_fn_name((int)i);
        for (size_t r = 0; r < n_rows; ++r) {
            if (strcmp(FZ_DOC_STATUSES[r].fn, name) != 0) {
                continue;
            }
            doc_listed[i] = 1;
            for (size_t k = 0; k < FZ_DOC_STATUSES[r].n; ++k) {
                int code = (int)FZ_DOC_STATUSES[r].statuses[k];
                doc_mask[i][code >> 6] |= (uint64_t)1 << (code & 63);
            }
        }
    }
    doc_ready = 1;
}

static int doc_lists(int fn_index, CagdStatus st) {
    int code = (int)st;
    return code >= 0 && code < 128 && ((doc_mask[fn_index][code >> 6] >> (code & 63)) & 1);
}

/* The status checks every call gets: never CAGD_ERR_PANIC, and a status the function's
 * doc comment lists. */
static void check_status(int fn_index, CagdStatus st) {
    if (st == CAGD_ERR_PANIC) {
        fz_fail("CAGD_ERR_PANIC from %s (a caught Rust panic is a bug)", fz_fn_name(fn_index));
    }
    if (!doc_listed[fn_index]) {
        /* a function that returns no CagdStatus (the operation counts it as CAGD_OK) */
        if (st != CAGD_OK) {
            fz_fail("%s returns no CagdStatus (statuses.h) but the harness saw %d",
                    fz_fn_name(fn_index), (int)st);
        }
        return;
    }
    if (!doc_lists(fn_index, st)) {
        fail_code = (int)st;
        fail_fn = fz_fn_name(fn_index);
        fz_fail("status %d (%s) of %s is not listed in its doc comment", (int)st,
                cagd_status_name(st), fz_fn_name(fn_index));
    }
}

CagdStatus fz_status_of(int fn_index, CagdStatus st) {
    check_status(fn_index, st);
    return st;
}

void fz_begin(int fn_index) {
    fail_code = -1;
    fail_fn = NULL;
    fz.last_maker = -1;
    fz.fn_index = fn_index;
    fz.fn = fz_fn_name(fn_index);
    fz.call_null = 0;
    fz.call_misaligned = 0;
    fz.call_impossible = 0;
}

CagdStatus fz_status(CagdStatus st) {
    fz.stats[fz.fn_index].calls++;
    fz.total_calls++;
    fz.session_call++;
    check_status(fz.fn_index, st);
    if (st == CAGD_OK) {
        fz.stats[fz.fn_index].ok++;
        if (fz.call_null) {
            fz_fail("CAGD_OK although a required pointer was NULL");
        }
        if (fz.call_misaligned) {
            fz_fail("CAGD_OK although an input pointer was misaligned");
        }
        if (fz.call_impossible) {
            fz_fail("CAGD_OK although an input length exceeds any possible buffer");
        }
    } else {
        const char *msg = cagd_last_error_message();
        if (msg == NULL || msg[0] == '\0') {
            fz_fail("status %d (%s) with an empty cagd_last_error_message", (int)st,
                    cagd_status_name(st));
        }
    }
    return st;
}

void fz_finite(double v, const char *what) {
    if (!isfinite(v)) {
        fz_fail("CAGD_OK but %s = %g is not finite", what, v);
    }
}

void *fz_handle_out(FzType t, CagdStatus st, void *h, int out_was_null) {
    if (st == CAGD_OK) {
        if (out_was_null) {
            fz_fail("CAGD_OK with a NULL handle output");
        }
        if (h == NULL) {
            fz_fail("CAGD_OK but the handle output is NULL");
        }
        fz_put(t, h);
        return h;
    }
    if (h != NULL) {
        FREE_FN[t](h);
        fz_fail("status %d but a handle output was written", (int)st);
    }
    return NULL;
}

/* ---------------------------------------------------------------- drivers */

static void run_session(uint64_t max_calls) {
    uint64_t start = fz.total_calls;
    fz.session_call = 0;
    while (fz.total_calls - start < max_calls && !fz.exhausted) {
        fz.in_used = 0;
        fz.out_used = 0;
        fz.skip = 0;
        if (keep_going_armed) {
            if (setjmp(keep_going_jmp) != 0) {
                continue;
            }
        }
        fz_op_random();
    }
    free_all();
}

static void print_stats(void) {
    size_t n = fz_n_ops();
    size_t never_ok = 0;
    printf("%-48s %12s %12s %10s\n", "function", "calls", "CAGD_OK", "cpu s");
    for (size_t i = 0; i < n; ++i) {
        printf("%-48s %12llu %12llu %10.3f\n", fz_fn_name((int)i),
               (unsigned long long)fz.stats[i].calls, (unsigned long long)fz.stats[i].ok,
               fz.stats[i].secs);
        never_ok += fz.stats[i].ok == 0;
    }
    printf("functions: %zu, never CAGD_OK: %zu, calls: %llu\n", n, never_ok,
           (unsigned long long)fz.total_calls);
}

uint64_t cagd_fuzz_run_seed(uint64_t seed, uint64_t calls, uint64_t session_calls,
                            int verbose) {
    memset(&fz, 0, sizeof fz);
    doc_init();
    const char *kg = getenv("CAGD_FUZZ_KEEP_GOING");
    keep_going_armed = kg != NULL && kg[0] == '1';
    uint64_t sm = seed;
    if (session_calls == 0) {
        session_calls = 1;
    }
    /* CAGD_FUZZ_SECONDS: a wall-time budget; the run stops after the session that
     * exceeds it (the call count reached is printed). */
    const char *budget_s = getenv("CAGD_FUZZ_SECONDS");
    double budget = budget_s != NULL ? atof(budget_s) : 0.0;
    time_t t0 = time(NULL);
    /* CAGD_FUZZ_REPLAY=<session seed>: replays that one session (the seed a violation
     * report prints), `session_calls` calls long. */
    const char *replay_s = getenv("CAGD_FUZZ_REPLAY");
    if (replay_s != NULL) {
        fz.session_seed = strtoull(replay_s, NULL, 0);
        fz.state = fz.session_seed | 1;
        run_session(session_calls);
        return fz.total_calls;
    }
    while (fz.total_calls < calls) {
        if (budget > 0.0 && difftime(time(NULL), t0) > budget) {
            break;
        }
        fz.session_seed = splitmix(&sm);
        fz.state = fz.session_seed | 1;
        uint64_t left = calls - fz.total_calls;
        uint64_t before = fz.total_calls;
        run_session(left < session_calls ? left : session_calls);
        if (verbose && before / 1000000 != fz.total_calls / 1000000) {
            fprintf(stderr, "cagd C ABI fuzz: %llu calls, %.0f s\n",
                    (unsigned long long)fz.total_calls, difftime(time(NULL), t0));
        }
    }
    fz_time_flush();
    if (verbose) {
        print_stats();
    }
    if (fz_violations > 0) {
        fprintf(stderr, "cagd C ABI fuzz: %llu oracle violations (keep-going mode)\n",
                (unsigned long long)fz_violations);
    }
    for (size_t i = 0; i < n_seen; ++i) {
        if (seen[i].code >= 0) {
            fprintf(stderr, "violation x%llu in %s: status %d (%s) not in its doc comment\n",
                    (unsigned long long)seen[i].count, seen[i].fn, seen[i].code,
                    cagd_status_name((CagdStatus)seen[i].code));
        } else {
            fprintf(stderr, "violation x%llu in %s: %s\n", (unsigned long long)seen[i].count,
                    seen[i].fn, seen[i].fmt);
        }
    }
    return fz.total_calls;
}

uint64_t cagd_fuzz_run_bytes(const uint8_t *data, size_t len) {
    memset(&fz, 0, sizeof fz);
    doc_init();
    fz.data = data;
    fz.len = len;
    run_session(100000);
    return fz.total_calls;
}

size_t cagd_fuzz_n_functions(void) { return fz_n_ops(); }
