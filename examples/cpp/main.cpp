// Example: a kernel that only accepts cubics receives a degree-7 curve and reduces it,
// keeping position and tangent at both ends (so joints stay C1), with a certified bound;
// then the same curve to a C1 cubic B-spline within a tolerance, and a NURBS circle.
// Exits 0 when every check holds. Built and run by .ci/capi-checks.sh against
// target/release/libcagd_capi.a.
#include <cmath>
#include <cstdio>

#include "cagd.hpp"

int main() {
    try {
        // The degree-7 curve of the spec vector hermite-n7-m3.
        const std::vector<double> p7 = {0, 0, 1, 3, 3, 4, 5, 1, 6, 5, 8, 2, 9, 6, 11, 0};
        const cagd::Curve input = cagd::Curve::polynomial(p7, 2);

        CagdReduceOptions opts = cagd::default_options();
        opts.method = CAGD_METHOD_CONSTRAINED_CHEBYSHEV;
        opts.target = 3;
        opts.r = 1;  // keep position and first derivative at t = 0
        opts.p = 1;  // and at t = 1
        opts.measure = true;
        auto [cubic, report] = input.reduce(opts);

        const std::vector<double> q = cubic.points();
        std::printf("reduced degree %zu -> %zu:", input.degree(), cubic.degree());
        for (std::size_t i = 0; i < q.size(); i += 2) std::printf(" (%g, %g)", q[i], q[i + 1]);
        double measured = 0.0;
        const bool have = report.max_error(measured);
        std::printf("\ncertified bound %.6g, measured error %.6g\n", report.bound(), measured);

        // hermite-n7-m3: Q = (0,0) (7/3,7) (19/3,14) (11,0); spec tolerance 1e-12 * 14.
        const double expected[8] = {0, 0, 7.0 / 3, 7, 19.0 / 3, 14, 11, 0};
        for (std::size_t k = 0; k < 8; ++k) {
            if (std::fabs(q[k] - expected[k]) > 1e-12 * 14) {
                std::fprintf(stderr, "Q[%zu] = %.17g, expected %.17g\n", k, q[k], expected[k]);
                return 1;
            }
        }
        if (!have || measured > report.bound()) {
            std::fprintf(stderr, "measured error above the certified bound\n");
            return 1;
        }

        // A rational curve survives elevation and reduction back.
        const double s = std::sqrt(0.5);
        const cagd::Curve arc = cagd::Curve::rational({1, 0, 1, 1, 0, 1}, {1, s, 1}, 2);
        CagdReduceOptions back = cagd::default_options();
        back.target = 2;
        auto [arc2, arc_report] = arc.elevate(4).reduce(back);
        const std::vector<double> m = arc2.eval(0.5);
        if (std::fabs(std::hypot(m[0], m[1]) - 1.0) > 1e-13) {
            std::fprintf(stderr, "arc left the unit circle\n");
            return 1;
        }

        // A NURBS full circle (9 points, quadratic): evaluate, split into Bézier pieces,
        // refine; every point stays on the unit circle.
        const std::vector<double> knots = {0, 0, 0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1, 1, 1};
        const std::vector<double> ring = {1, 0, 1, 1, 0, 1, -1, 1, -1, 0, -1, -1, 0, -1, 1, -1, 1, 0};
        const std::vector<double> rw = {1, s, 1, s, 1, s, 1, s, 1};
        const cagd::BSpline circle = cagd::BSpline::rational(2, knots, ring, rw, 2);
        const cagd::BSpline finer = circle.insert_knot(0.1, 2);
        const cagd::CurveList quarters = circle.to_beziers();
        if (quarters.size() != 4 || finer.knots().size() != knots.size() + 2) {
            std::fprintf(stderr, "unexpected circle structure\n");
            return 1;
        }
        for (int i = 0; i <= 16; ++i) {
            const double t = i / 16.0;
            const std::vector<double> a = circle.eval(t), b = finer.eval(t);
            const std::vector<double> d = circle.derivatives(t, 1);
            if (std::fabs(std::hypot(a[0], a[1]) - 1.0) > 1e-14 ||
                std::fabs(std::hypot(b[0], b[1]) - 1.0) > 1e-14 ||
                std::fabs(a[0] * d[2] + a[1] * d[3]) > 1e-13) {
                std::fprintf(stderr, "circle: t = %g off the circle or not tangent\n", t);
                return 1;
            }
        }
        const auto [qa, qb] = quarters.interval(1);
        const std::vector<double> mid = quarters[1].eval(0.5);
        std::printf("NURBS circle: %zu Bezier quarters, quarter 1 on [%g, %g] has (%.6f, %.6f) "
                    "at its middle\n",
                    quarters.size(), qa, qb, mid[0], mid[1]);

        // The NURBS circle as a polyline within 1e-3 (degree 1, certified).
        CagdReduceOptions lin = cagd::default_options();
        lin.target = 1;
        lin.tolerance = 1e-3;
        auto [polyline, poly_report] = circle.reduce(lin);
        std::printf("circle as a polyline within 1e-3: %zu vertices, bound %.3g\n",
                    polyline.points().size() / 2, poly_report.bound());
        for (int i = 0; i <= 100; ++i) {
            const std::vector<double> a = polyline.eval(i / 100.0);
            if (std::fabs(std::hypot(a[0], a[1]) - 1.0) > poly_report.bound()) {
                std::fprintf(stderr, "polyline farther from the circle than its bound\n");
                return 1;
            }
        }

        // The degree-7 curve to cubics within 1e-3 with C1 joins: a B-spline.
        CagdReduceOptions tol = cagd::default_options();
        tol.target = 3;
        tol.r = tol.p = 1;
        tol.continuity = 1;
        tol.tolerance = 1e-3;
        auto [spline, spline_report] = input.reduce_to_tolerance(tol);
        std::printf("to 1e-3 with C1 joins: %zu cubic pieces, %zu control points, bound %.3g\n",
                    spline_report.pieces(), spline.points().size() / 2, spline_report.bound());
        if (spline.degree() != 3 || spline_report.bound() > 1e-3) {
            std::fprintf(stderr, "tolerance reduction out of spec\n");
            return 1;
        }
        for (int i = 0; i <= 50; ++i) {
            const std::vector<double> a = input.eval(i / 50.0), b = spline.eval(i / 50.0);
            if (std::hypot(a[0] - b[0], a[1] - b[1]) > spline_report.bound()) {
                std::fprintf(stderr, "spline farther than its bound\n");
                return 1;
            }
        }

        // Bad knots are reported, not crashed on.
        try {
            (void)cagd::BSpline::polynomial(2, {0, 0, 0, 0.6, 0.4, 1, 1, 1},
                                            {0, 0, 1, 1, 2, 0, 3, 1, 4, 0}, 2);
            std::fprintf(stderr, "decreasing knots were accepted\n");
            return 1;
        } catch (const cagd::Error &e) {
            if (e.status() != CAGD_ERR_BAD_KNOTS) throw;
            std::printf("expected failure: %s\n", e.what());
        }

        // Errors arrive as exceptions with the status and the message.
        try {
            opts.target = 7;
            (void)input.reduce(opts);
            std::fprintf(stderr, "reducing to the same degree did not fail\n");
            return 1;
        } catch (const cagd::Error &e) {
            if (e.status() != CAGD_ERR_BAD_DEGREE_PAIR) throw;
            std::printf("expected failure: %s\n", e.what());
        }
        std::printf("ok (cagd %d.%d.%d)\n", CAGD_VERSION_MAJOR, CAGD_VERSION_MINOR,
                    CAGD_VERSION_PATCH);
        return 0;
    } catch (const std::exception &e) {
        std::fprintf(stderr, "error: %s\n", e.what());
        return 1;
    }
}
