/* Reduction to a tolerance: new -> reduce -> read back -> free.
 * - The stepwise Algorithm 14.2.1 against the spec vector subdiv-reduce-9to4-0.01
 *   (intervals exact, points and certified total within its tol 1e-9, spec rule).
 * - The adaptive reduction of an elevated cubic: exact in one piece (closed form).
 * - The adaptive C1 reduction of a degree-7 curve: bound <= tolerance, sampled distance
 *   <= bound, interior knots of multiplicity m - k. */
#include "ctest.h"

/* subdiv-reduce-9to4-0.01: input P (degree 9, 2D) */
static const double SUB_P[20] = {
    0.245803, 0.483574, 0.590387, 0.884901, 0.479797, 0.84465, -0.94199, -0.068755, 0.886713,
    0.297949, 0.801801, -0.773588, -0.061862, -0.506854, 0.087522, 0.147882, -0.973772,
    -0.56654, -0.441035, 0.832691,
};
/* subdiv-reduce-9to4-0.01: expected Q_pieces (6 pieces of degree 4) */
static const double SUB_Q[60] = {
    0.245803, 0.483574, 0.34507660334498547, 0.5976471074352468, 0.3924331819314544,
    0.6657776344988202, 0.3833270653863511, 0.6849407756519821, 0.35465655028146903,
    0.6718834118811113, 0.35465655028146903, 0.6718834118811113, 0.325986035176587,
    0.6588260481102407, 0.2736334792037537, 0.6119546761662359, 0.23449717893476235,
    0.5480161770354759, 0.20971360460802527, 0.4736509323088053, 0.20971360460802527,
    0.4736509323088053, 0.1582481847750044, 0.3252981969857709, 0.19282843483000678,
    0.14151849276476192, 0.27845631415201144, -0.02116844860482709, 0.28360738867187507,
    -0.1335332109375, 0.28360738867187507, -0.1335332109375, 0.2908481522194901,
    -0.24679675167740583, 0.23986855607067914, -0.3046614224497463, 0.0642844640734126,
    -0.285085052092257, -0.11995769264094547, -0.21727999920622051, -0.11995769264094547,
    -0.21727999920622051, -0.21333402600838125, -0.18315367997433626, -0.3122124788727565,
    -0.1355712952441131, -0.4086244559596953, -0.07820651603466557, -0.47984565252823375,
    0.01515316054611271, -0.47984565252823375, 0.01515316054611271, -0.5510668490967722,
    0.10851283712689098, -0.5943943226312927, 0.241640888389026, -0.5871037683908307,
    0.44074981722462414, -0.441035, 0.832691,
};
static const double SUB_BREAKS[7] = {0.0, 0.125, 0.25, 0.5, 0.75, 0.875, 1.0};
static const double SUB_TOTAL = 0.002205741959884839;

/* P of hermite-n7-m3 (degree 7, 2D). */
static const double P7[16] = {0, 0, 1, 3, 3, 4, 5, 1, 6, 5, 8, 2, 9, 6, 11, 0};

int cagd_ctest_reduce_tolerance_stepwise_spec(void) {
    int rc = 1;
    CagdCurve *c = NULL, *piece = NULL;
    CagdBSpline *s = NULL;
    CagdReport *rep = NULL;
    CagdCurveList *list = NULL;
    CagdReduceOptions o;
    double q[10] = {0}, steps[5] = {0}, a = -1, b = -1, bound = -1, pbound = -1, sum = 0;
    size_t needed = 0, count = 0, depth = 0, k = 9, degree = 0, n = 0, i, j;

    CHECK_OK(cagd_curve_new(SUB_P, 10, 2, &c));
    CHECK_OK(cagd_reduce_options_init(&o));
    o.method = CAGD_METHOD_PERTURB;
    o.target = 4;
    o.tolerance = 0.01;
    CHECK_OK(cagd_curve_reduce_to_tolerance_stepwise(c, &o, &s, &rep));
    CHECK_OK(cagd_report_piecewise(rep, &count, &depth, &k, &pbound));
    CHECK(count == 6 && k == 0);
    CHECK_OK(cagd_report_pieces(rep, &list));
    for (i = 0; i < 6; ++i) {
        double bi = -1;
        CHECK_OK(cagd_curvelist_interval(list, i, &a, &b));
        CHECK(a == SUB_BREAKS[i] && b == SUB_BREAKS[i + 1]);
        CHECK_OK(cagd_curvelist_get(list, i, &piece));
        CHECK_OK(cagd_curve_points(piece, q, 10, &needed));
        CHECK(needed == 10);
        /* spec rule: |got - expected| <= 1e-9 * max(1, max |expected|) = 1e-9 here */
        for (j = 0; j < 10; ++j) CHECK_NEAR(q[j], SUB_Q[10 * i + j], 1e-9);
        CHECK_OK(cagd_curvelist_bound(list, i, &bi));
        CHECK(bi >= 0.0 && bi <= pbound);
        cagd_curve_free(piece);
        piece = NULL;
    }
    /* the seed's certified total is the sum of the per-step maxima */
    CHECK_STATUS(cagd_report_step_bounds(rep, NULL, 0, &needed), CAGD_ERR_BUFFER_TOO_SMALL);
    CHECK(needed == 5); /* n - d = 9 - 4 steps */
    CHECK_OK(cagd_report_step_bounds(rep, steps, 5, &needed));
    for (i = 0; i < 5; ++i) sum += steps[i];
    CHECK_NEAR(sum, SUB_TOTAL, 1e-9);
    CHECK_OK(cagd_report_bound(rep, &bound));
    CHECK(bound <= 0.01);
    /* the spline: degree 4, C0 joins (interior knots of multiplicity 4) */
    CHECK_OK(cagd_bspline_degree(s, &degree));
    CHECK_OK(cagd_bspline_n_points(s, &n));
    CHECK(degree == 4 && n == 6 * 4 + 1);
    rc = 0;
cleanup:
    cagd_curve_free(piece);
    cagd_curvelist_free(list);
    cagd_report_free(rep);
    cagd_bspline_free(s);
    cagd_curve_free(c);
    return rc;
}

int cagd_ctest_reduce_tolerance_exact(void) {
    int rc = 1;
    CagdCurve *cubic = NULL, *quintic = NULL;
    CagdBSpline *s = NULL;
    CagdReport *rep = NULL;
    CagdReduceOptions o;
    const double p3[8] = {0, 0, 1, 3, 3, 4, 5, 1};
    double pts[8] = {0}, bound = -1, pb = -1;
    size_t needed = 0, count = 0, depth = 9, k = 9, i;
    int32_t method = -1;
    size_t from = 0, to = 0;

    /* an elevated cubic is reduced back exactly, in one piece, by the default method */
    CHECK_OK(cagd_curve_new(p3, 4, 2, &cubic));
    CHECK_OK(cagd_curve_elevate(cubic, 2, &quintic));
    CHECK_OK(cagd_reduce_options_init(&o));
    o.tolerance = 1e-9;
    CHECK_OK(cagd_curve_reduce_to_tolerance(quintic, &o, &s, &rep));
    CHECK_OK(cagd_report_piecewise(rep, &count, &depth, &k, &pb));
    CHECK(count == 1 && depth == 0 && k == 0);
    CHECK_OK(cagd_report_method(rep, &method, &from, &to));
    CHECK(method == CAGD_METHOD_L2 && from == 5 && to == 3);
    CHECK_OK(cagd_bspline_points(s, pts, 8, &needed));
    CHECK(needed == 8);
    /* operator entries rounded once, data of size 5: 1e-13 is ample */
    for (i = 0; i < 8; ++i) CHECK_NEAR(pts[i], p3[i], 1e-13);
    CHECK_OK(cagd_report_bound(rep, &bound));
    CHECK(bound >= 0.0 && bound < 1e-12);
    rc = 0;
cleanup:
    cagd_report_free(rep);
    cagd_bspline_free(s);
    cagd_curve_free(quintic);
    cagd_curve_free(cubic);
    return rc;
}

int cagd_ctest_reduce_tolerance_c1(void) {
    int rc = 1;
    CagdCurve *c = NULL;
    CagdBSpline *s = NULL;
    CagdReport *rep = NULL;
    CagdReduceOptions o;
    double knots[256], x[2], y[2], bound = -1, measured = -1, pb = -1, a = -1, b = -1;
    size_t needed = 0, count = 0, depth = 0, k = 9, degree = 0, n = 0, i;

    CHECK_OK(cagd_curve_new(P7, 8, 2, &c));
    CHECK_OK(cagd_reduce_options_init(&o));
    o.method = CAGD_METHOD_L2;
    o.target = 3;
    o.r = 1;
    o.p = 1;
    o.continuity = 1;
    o.tolerance = 1e-3;
    o.measure = true;
    CHECK_OK(cagd_curve_reduce_to_tolerance(c, &o, &s, &rep));
    CHECK_OK(cagd_report_piecewise(rep, &count, &depth, &k, &pb));
    CHECK(count > 1 && k == 1);
    CHECK_OK(cagd_report_bound(rep, &bound));
    CHECK_OK(cagd_report_max_error(rep, &measured));
    CHECK(pb <= bound && bound <= 1e-3 && measured <= bound);
    CHECK_OK(cagd_bspline_degree(s, &degree));
    CHECK_OK(cagd_bspline_n_points(s, &n));
    CHECK_OK(cagd_bspline_domain(s, &a, &b));
    CHECK(degree == 3 && a == 0.0 && b == 1.0);
    /* C1 cubic pieces: interior knots of multiplicity 2, so n = 4 + 2 (count - 1) */
    CHECK(n == 4 + 2 * (count - 1));
    CHECK_OK(cagd_bspline_knots(s, knots, 256, &needed));
    CHECK(needed == n + 4);
    for (i = 4; i + 4 < needed; i += 2) CHECK(knots[i] == knots[i + 1] && knots[i + 1] < knots[i + 2]);
    /* the spline stays within the bound of the curve (same parameter) */
    for (i = 0; i <= 200; ++i) {
        double t = i / 200.0;
        CHECK_OK(cagd_curve_eval(c, t, x, 2, &needed));
        CHECK_OK(cagd_bspline_eval(s, t, y, 2, &needed));
        CHECK(hypot(x[0] - y[0], x[1] - y[1]) <= bound);
    }
    rc = 0;
cleanup:
    cagd_report_free(rep);
    cagd_bspline_free(s);
    cagd_curve_free(c);
    return rc;
}

int cagd_ctest_reduce_tolerance_bad_input(void) {
    int rc = 1;
    CagdCurve *c = NULL, *rat = NULL, *q = NULL;
    CagdBSpline *s = NULL;
    CagdReport *rep = NULL, *single = NULL;
    CagdCurveList *list = NULL;
    CagdReduceOptions o;
    const double w[8] = {1, 1.25, 1, 1.25, 1, 1.25, 1, 1.25};
    double x = 0, buf[4];
    size_t n = 0, needed = 0;
    int32_t space = 0;

    CHECK_OK(cagd_curve_new(P7, 8, 2, &c));
    CHECK_OK(cagd_curve_new_rational(P7, w, 8, 2, &rat));
    CHECK_OK(cagd_reduce_options_init(&o));
    /* the default tolerance 0 must be set */
    CHECK_STATUS(cagd_curve_reduce_to_tolerance(c, &o, &s, &rep), CAGD_ERR_INVALID_ARGUMENT);
    o.tolerance = NAN;
    CHECK_STATUS(cagd_curve_reduce_to_tolerance(c, &o, &s, &rep), CAGD_ERR_INVALID_ARGUMENT);
    o.tolerance = -1e-3;
    CHECK_STATUS(cagd_curve_reduce_to_tolerance(c, &o, &s, &rep), CAGD_ERR_INVALID_ARGUMENT);
    o.tolerance = 1e-3;
    CHECK_STATUS(cagd_curve_reduce_to_tolerance(NULL, &o, &s, &rep), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_curve_reduce_to_tolerance(c, NULL, &s, &rep), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_curve_reduce_to_tolerance(c, &o, NULL, &rep), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_curve_reduce_to_tolerance(c, &o, &s, NULL), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_curve_reduce_to_tolerance(c, &o, (CagdBSpline **)(void *)&rep, &rep),
                 CAGD_ERR_INVALID_ARGUMENT);
    o.struct_size = sizeof o - 1;
    CHECK_STATUS(cagd_curve_reduce_to_tolerance(c, &o, &s, &rep), CAGD_ERR_INVALID_ARGUMENT);
    CHECK_MESSAGE_HAS("struct_size");
    o.struct_size = sizeof o;
    /* C1 joins need a method keeping first derivatives: the default r = p = 0 does not */
    o.continuity = 1;
    CHECK_STATUS(cagd_curve_reduce_to_tolerance(c, &o, &s, &rep), CAGD_ERR_INVALID_ARGUMENT);
    o.continuity = 3; /* >= target */
    o.r = o.p = 1;
    CHECK_STATUS(cagd_curve_reduce_to_tolerance(c, &o, &s, &rep), CAGD_ERR_INVALID_ARGUMENT);
    o.continuity = 0;
    o.r = o.p = 0;
    o.target = 7;
    CHECK_STATUS(cagd_curve_reduce_to_tolerance(c, &o, &s, &rep), CAGD_ERR_BAD_DEGREE_PAIR);
    o.target = 3;
    o.r = 2;
    o.p = 1;
    CHECK_STATUS(cagd_curve_reduce_to_tolerance(c, &o, &s, &rep), CAGD_ERR_TOO_MANY_CONSTRAINTS);
    o.r = o.p = 0;
    o.method = 99;
    CHECK_STATUS(cagd_curve_reduce_to_tolerance(c, &o, &s, &rep), CAGD_ERR_INVALID_ARGUMENT);
    o.method = CAGD_METHOD_L2;
    o.tolerance = 1e-6;
    o.max_depth = 1;
    CHECK_STATUS(cagd_curve_reduce_to_tolerance(c, &o, &s, &rep), CAGD_ERR_NO_CONVERGENCE);
    o.max_depth = 30;
    o.tolerance = 1e-3;
    /* the stepwise algorithm's preconditions */
    CHECK_STATUS(cagd_curve_reduce_to_tolerance_stepwise(c, &o, &s, &rep),
                 CAGD_ERR_CONDITION_NOT_MET); /* L2 is not PERTURB */
    o.method = CAGD_METHOD_PERTURB;
    CHECK_STATUS(cagd_curve_reduce_to_tolerance_stepwise(rat, &o, &s, &rep),
                 CAGD_ERR_CONDITION_NOT_MET);
    CHECK_STATUS(cagd_curve_reduce_to_tolerance_stepwise(NULL, &o, &s, &rep),
                 CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_curve_reduce_to_tolerance_stepwise(c, NULL, &s, &rep),
                 CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_curve_reduce_to_tolerance_stepwise(c, &o, NULL, &rep),
                 CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_curve_reduce_to_tolerance_stepwise(c, &o, &s, NULL),
                 CAGD_ERR_NULL_POINTER);
    CHECK(s == NULL && rep == NULL);
    /* piecewise accessors: NULLs, and NOT_AVAILABLE on a single reduction's report */
    CHECK_OK(cagd_curve_reduce_to_tolerance(rat, &o, &s, &rep)); /* rational: fine */
    CHECK_STATUS(cagd_report_piecewise(NULL, &n, &n, &n, &x), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_report_piecewise(rep, NULL, &n, &n, &x), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_report_piecewise(rep, &n, NULL, &n, &x), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_report_piecewise(rep, &n, &n, NULL, &x), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_report_piecewise(rep, &n, &n, &n, NULL), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_report_pieces(NULL, &list), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_report_pieces(rep, NULL), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_report_step_bounds(NULL, buf, 4, &needed), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_report_step_bounds(rep, NULL, 4, &needed), CAGD_ERR_NULL_POINTER);
    CHECK_STATUS(cagd_report_step_bounds(rep, buf, 4, NULL), CAGD_ERR_NULL_POINTER);
    CHECK_OK(cagd_report_step_bounds(rep, buf, 4, &needed));
    CHECK(needed == 0); /* only the stepwise algorithm has steps */
    CHECK_STATUS(cagd_report_space(rep, &space, &x), CAGD_ERR_NOT_AVAILABLE);
    o.method = CAGD_METHOD_L2;
    o.target = 3;
    CHECK_OK(cagd_curve_reduce(c, &o, &q, &single));
    CHECK_STATUS(cagd_report_piecewise(single, &n, &n, &n, &x), CAGD_ERR_NOT_AVAILABLE);
    CHECK_STATUS(cagd_report_pieces(single, &list), CAGD_ERR_NOT_AVAILABLE);
    CHECK_STATUS(cagd_report_step_bounds(single, buf, 4, &needed), CAGD_ERR_NOT_AVAILABLE);
    CHECK(list == NULL);
    rc = 0;
cleanup:
    cagd_curvelist_free(list);
    cagd_report_free(single);
    cagd_curve_free(q);
    cagd_report_free(rep);
    cagd_bspline_free(s);
    cagd_curve_free(rat);
    cagd_curve_free(c);
    return rc;
}
