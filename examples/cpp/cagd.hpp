// cagd.hpp — a small C++17 RAII layer over the cagd C ABI (include/cagd.h), the way a
// kernel would wrap it: handles in std::unique_ptr with cagd's free functions as deleters,
// failures as exceptions carrying the CagdStatus and cagd_last_error_message(), and buffer
// read-back through the size query (capacity 0) of the C API.
#ifndef CAGD_HPP
#define CAGD_HPP

#include <cstddef>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "cagd.h"

namespace cagd {

// A failed cagd call: the status and the thread's last error message.
class Error : public std::runtime_error {
  public:
    Error(CagdStatus status, const std::string &what)
        : std::runtime_error(what + ": " + cagd_status_name(status) + ": " +
                             cagd_last_error_message()),
          status_(status) {}
    CagdStatus status() const noexcept { return status_; }

  private:
    CagdStatus status_;
};

inline void check(CagdStatus status, const char *what) {
    if (status != CAGD_OK) throw Error(status, what);
}

struct CurveDeleter {
    void operator()(CagdCurve *c) const noexcept { cagd_curve_free(c); }
};
struct ReportDeleter {
    void operator()(CagdReport *r) const noexcept { cagd_report_free(r); }
};
struct BSplineDeleter {
    void operator()(CagdBSpline *s) const noexcept { cagd_bspline_free(s); }
};
struct CurveListDeleter {
    void operator()(CagdCurveList *l) const noexcept { cagd_curvelist_free(l); }
};

// Reads a variable-length array with one size query and one copy.
template <typename Handle, typename Fn>
std::vector<double> read_all(const Handle *h, Fn fn, const char *what) {
    std::size_t needed = 0;
    CagdStatus s = fn(h, nullptr, 0, &needed);
    if (s != CAGD_ERR_BUFFER_TOO_SMALL && s != CAGD_OK) throw Error(s, what);
    std::vector<double> out(needed);
    check(fn(h, out.data(), out.size(), &needed), what);
    return out;
}

// The outcome of a reduction: its method, degrees and error numbers.
class Report {
  public:
    explicit Report(CagdReport *r) : r_(r) {}
    double bound() const {
        double b = 0.0;
        check(cagd_report_bound(r_.get(), &b), "cagd_report_bound");
        return b;
    }
    // The sampled error, if the reduction was asked to measure it.
    bool max_error(double &e) const {
        CagdStatus s = cagd_report_max_error(r_.get(), &e);
        if (s == CAGD_ERR_NOT_AVAILABLE) return false;
        check(s, "cagd_report_max_error");
        return true;
    }

    // For a reduction to a tolerance: the number of pieces.
    std::size_t pieces() const {
        std::size_t n = 0, depth = 0, k = 0;
        double worst = 0.0;
        check(cagd_report_piecewise(r_.get(), &n, &depth, &k, &worst), "cagd_report_piecewise");
        return n;
    }

  private:
    std::unique_ptr<CagdReport, ReportDeleter> r_;
};

class BSpline;

// An immutable Bézier curve (polynomial or rational).
class Curve {
  public:
    static Curve polynomial(const std::vector<double> &points, std::size_t dim) {
        CagdCurve *c = nullptr;
        check(cagd_curve_new(points.data(), dim ? points.size() / dim : 0, dim, &c),
              "cagd_curve_new");
        return Curve(c);
    }
    static Curve rational(const std::vector<double> &points, const std::vector<double> &weights,
                          std::size_t dim) {
        if (dim == 0 || points.size() != weights.size() * dim)
            throw std::invalid_argument("points.size() must be weights.size() * dim");
        CagdCurve *c = nullptr;
        check(cagd_curve_new_rational(points.data(), weights.data(), weights.size(), dim, &c),
              "cagd_curve_new_rational");
        return Curve(c);
    }

    std::size_t degree() const {
        std::size_t n = 0;
        check(cagd_curve_degree(c_.get(), &n), "cagd_curve_degree");
        return n;
    }
    std::size_t dim() const {
        std::size_t d = 0;
        check(cagd_curve_dim(c_.get(), &d), "cagd_curve_dim");
        return d;
    }
    std::vector<double> points() const {
        return read_all(c_.get(), cagd_curve_points, "cagd_curve_points");
    }
    std::vector<double> weights() const {
        return read_all(c_.get(), cagd_curve_weights, "cagd_curve_weights");
    }
    std::vector<double> eval(double t) const {
        std::vector<double> p(dim());
        std::size_t needed = 0;
        check(cagd_curve_eval(c_.get(), t, p.data(), p.size(), &needed), "cagd_curve_eval");
        return p;
    }
    std::pair<Curve, Report> reduce(const CagdReduceOptions &opts) const {
        CagdCurve *q = nullptr;
        CagdReport *r = nullptr;
        check(cagd_curve_reduce(c_.get(), &opts, &q, &r), "cagd_curve_reduce");
        return {Curve(q), Report(r)};
    }
    Curve elevate(std::size_t r) const {
        CagdCurve *e = nullptr;
        check(cagd_curve_elevate(c_.get(), r, &e), "cagd_curve_elevate");
        return Curve(e);
    }
    // Reduction to opts.tolerance with C^opts.continuity joins: a B-spline and a report.
    inline std::pair<BSpline, Report> reduce_to_tolerance(const CagdReduceOptions &opts) const;

    // Takes ownership of a handle returned by the C API.
    static Curve adopt(CagdCurve *c) { return Curve(c); }

  private:
    explicit Curve(CagdCurve *c) : c_(c) {}
    std::unique_ptr<CagdCurve, CurveDeleter> c_;
};

// The Bézier pieces of a spline, each with its parameter interval.
class CurveList {
  public:
    explicit CurveList(CagdCurveList *l) : l_(l) {}
    std::size_t size() const {
        std::size_t n = 0;
        check(cagd_curvelist_count(l_.get(), &n), "cagd_curvelist_count");
        return n;
    }
    Curve operator[](std::size_t i) const {
        CagdCurve *c = nullptr;
        check(cagd_curvelist_get(l_.get(), i, &c), "cagd_curvelist_get");
        return Curve::adopt(c);
    }
    std::pair<double, double> interval(std::size_t i) const {
        double a = 0.0, b = 0.0;
        check(cagd_curvelist_interval(l_.get(), i, &a, &b), "cagd_curvelist_interval");
        return {a, b};
    }

  private:
    std::unique_ptr<CagdCurveList, CurveListDeleter> l_;
};

// An immutable B-spline or NURBS curve.
class BSpline {
  public:
    static BSpline polynomial(std::size_t degree, const std::vector<double> &knots,
                              const std::vector<double> &points, std::size_t dim) {
        CagdBSpline *s = nullptr;
        check(cagd_bspline_new(degree, knots.data(), knots.size(), points.data(),
                               dim ? points.size() / dim : 0, dim, &s),
              "cagd_bspline_new");
        return BSpline(s);
    }
    static BSpline rational(std::size_t degree, const std::vector<double> &knots,
                            const std::vector<double> &points, const std::vector<double> &weights,
                            std::size_t dim) {
        if (dim == 0 || points.size() != weights.size() * dim)
            throw std::invalid_argument("points.size() must be weights.size() * dim");
        CagdBSpline *s = nullptr;
        check(cagd_bspline_new_rational(degree, knots.data(), knots.size(), points.data(),
                                        weights.data(), weights.size(), dim, &s),
              "cagd_bspline_new_rational");
        return BSpline(s);
    }
    static BSpline adopt(CagdBSpline *s) { return BSpline(s); }

    std::size_t degree() const {
        std::size_t p = 0;
        check(cagd_bspline_degree(s_.get(), &p), "cagd_bspline_degree");
        return p;
    }
    std::size_t dim() const {
        std::size_t d = 0;
        check(cagd_bspline_dim(s_.get(), &d), "cagd_bspline_dim");
        return d;
    }
    std::vector<double> knots() const {
        return read_all(s_.get(), cagd_bspline_knots, "cagd_bspline_knots");
    }
    std::vector<double> points() const {
        return read_all(s_.get(), cagd_bspline_points, "cagd_bspline_points");
    }
    std::vector<double> eval(double t) const {
        std::vector<double> p(dim());
        std::size_t needed = 0;
        check(cagd_bspline_eval(s_.get(), t, p.data(), p.size(), &needed), "cagd_bspline_eval");
        return p;
    }
    // Derivatives of orders 0..=order at t, each dim() doubles.
    std::vector<double> derivatives(double t, std::size_t order) const {
        std::vector<double> d((order + 1) * dim());
        std::size_t needed = 0;
        check(cagd_bspline_derivatives(s_.get(), t, order, d.data(), d.size(), &needed),
              "cagd_bspline_derivatives");
        return d;
    }
    BSpline insert_knot(double t, std::size_t times) const {
        CagdBSpline *r = nullptr;
        check(cagd_bspline_insert_knot(s_.get(), t, times, &r), "cagd_bspline_insert_knot");
        return BSpline(r);
    }
    // Reduction to opts.target within opts.tolerance: a B-spline and a report.
    std::pair<BSpline, Report> reduce(const CagdReduceOptions &opts) const {
        CagdBSpline *r = nullptr;
        CagdReport *rep = nullptr;
        check(cagd_bspline_reduce(s_.get(), &opts, &r, &rep), "cagd_bspline_reduce");
        return {BSpline(r), Report(rep)};
    }
    CurveList to_beziers() const {
        CagdCurveList *l = nullptr;
        check(cagd_bspline_to_beziers(s_.get(), &l), "cagd_bspline_to_beziers");
        return CurveList(l);
    }

  private:
    explicit BSpline(CagdBSpline *s) : s_(s) {}
    std::unique_ptr<CagdBSpline, BSplineDeleter> s_;
};

inline std::pair<BSpline, Report> Curve::reduce_to_tolerance(const CagdReduceOptions &opts) const {
    CagdBSpline *s = nullptr;
    CagdReport *r = nullptr;
    check(cagd_curve_reduce_to_tolerance(c_.get(), &opts, &s, &r),
          "cagd_curve_reduce_to_tolerance");
    return {BSpline::adopt(s), Report(r)};
}

inline CagdReduceOptions default_options() {
    CagdReduceOptions o;
    check(cagd_reduce_options_init(&o), "cagd_reduce_options_init");
    return o;
}

}  // namespace cagd

#endif  // CAGD_HPP
