/* Internal declarations shared by harness.c (infrastructure, oracle) and ops.c (one
 * operation per cagd_* function). */
#ifndef CAGD_FUZZ_HARNESS_IMPL_H
#define CAGD_FUZZ_HARNESS_IMPL_H

#include "harness.h"

#include "cagd.h"

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

/* Input and output buffers (doubles): large enough for degree 100 tensor patches. */
#define FZ_IN_CAP (1u << 18)
#define FZ_OUT_CAP (1u << 18)
/* Live handles kept per type; the oldest random one is freed when a pool is full. */
#define FZ_POOL 6
/* Upper bound on the number of operations (cagd_* functions). */
#define FZ_MAX_OPS 256

typedef enum FzType {
    FZ_CURVE,
    FZ_CURVELIST,
    FZ_BSPLINE,
    FZ_BSURF,
    FZ_IMPLICIT,
    FZ_ITRI,
    FZ_PPLIST,
    FZ_TENSOR,
    FZ_TENSORLIST,
    FZ_TRI,
    FZ_TRILIST,
    FZ_REPORT,
    FZ_WSGB,
    FZ_WSGBLIST,
    FZ_N_TYPES
} FzType;

typedef struct FzPool {
    void *h[FZ_POOL];
    int maker[FZ_POOL]; /* the operation that made each handle (for violation reports) */
    size_t n;
} FzPool;

typedef struct FzStats {
    uint64_t calls;
    uint64_t ok;
    double secs; /* CPU time spent in the operation */
} FzStats;

typedef struct Fz {
    /* decision source: bytes (libFuzzer) when data != NULL, else xorshift state */
    const uint8_t *data;
    size_t len, pos;
    int exhausted;
    uint64_t state;
    uint64_t session_seed;
    uint64_t session_call;
    uint64_t total_calls;
    /* the current call */
    int fn_index;
    const char *fn;
    int call_null;       /* a pointer cagd must not accept was NULL */
    int call_misaligned; /* an input pointer was misaligned */
    int call_impossible; /* an input length exceeds any possible buffer */
    int skip;            /* the generated arguments do not fit the buffers: no call */
    int last_maker;      /* the operation that made the last handle picked (-1: none) */
    size_t in_used, out_used;
    FzPool pools[FZ_N_TYPES];
    FzStats stats[FZ_MAX_OPS];
} Fz;

extern Fz fz;
extern double fz_in_buf[FZ_IN_CAP];
extern double fz_out_buf[FZ_OUT_CAP];

/* decisions */
uint64_t fz_u64(void);
uint32_t fz_r(uint32_t bound);
double fz_unit(void);
double fz_extreme(void);
double fz_double(void);
double fz_param(void);
double fz_tol(void);
size_t fz_huge(void);
size_t fz_deg(void);
size_t fz_small_deg(void);
size_t fz_dim(void);
size_t fz_count(size_t good);
size_t fz_index(size_t count);
int32_t fz_enum(int32_t n_valid);
size_t fz_mul(size_t a, size_t b);
size_t fz_add(size_t a, size_t b);
size_t fz_tri(size_t n);

/* input arrays */
typedef enum FzKind { FZ_VALUES, FZ_PARAMS, FZ_WEIGHTS, FZ_SORTED } FzKind;
void fz_fill(double *p, size_t n, FzKind kind);
const double *fz_in(size_t need, FzKind kind);     /* required: may be NULL/misaligned */
const double *fz_in_opt(size_t need, FzKind kind); /* NULL allowed by the contract */
const double *fz_knots(size_t n_knots, size_t degree);

/* output buffers */
typedef enum FzObMode {
    FZ_OB_QUERY,
    FZ_OB_NULL_WITH_CAP,
    FZ_OB_SMALL,
    FZ_OB_MISALIGNED,
    FZ_OB_NULL_NEEDED,
    FZ_OB_ROOMY,
    FZ_OB_EXACT
} FzObMode;

typedef struct FzOb {
    FzObMode mode;
    int phase;
    double *base;
    double *p;
    size_t cap;
    size_t needed;
    size_t *needed_p;
} FzOb;

void fz_ob_init(FzOb *ob);
int fz_ob_again(FzOb *ob, CagdStatus st);
void fz_ob_check(FzOb *ob, CagdStatus st, int finite);

/* pools */
void fz_put(FzType t, void *h);
void *fz_pick(FzType t); /* a live handle, or NULL now and then */
void *fz_take(FzType t); /* removes a live handle from its pool (to free it) */

/* oracle */
void fz_begin(int fn_index);
CagdStatus fz_status(CagdStatus st); /* the call's status, counted and checked */
/* A side call's status (a function called to check another's result): checked against
 * the doc comment of function `fn_index`, not counted. */
CagdStatus fz_status_of(int fn_index, CagdStatus st);
void fz_finite(double v, const char *what);
void *fz_handle_out(FzType t, CagdStatus st, void *h, int out_was_null);
#if defined(__GNUC__)
__attribute__((format(printf, 1, 2), noreturn))
#endif
void fz_fail(const char *fmt, ...);

/* operations (ops.c) */
size_t fz_n_ops(void);
const char *fz_fn_name(int index);
void fz_op_random(void);
void fz_time_flush(void); /* books the CPU time of the calls since the last clock() read */

#endif
