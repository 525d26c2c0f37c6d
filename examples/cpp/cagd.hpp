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

  private:
    std::unique_ptr<CagdReport, ReportDeleter> r_;
};

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

  private:
    explicit Curve(CagdCurve *c) : c_(c) {}
    std::unique_ptr<CagdCurve, CurveDeleter> c_;
};

inline CagdReduceOptions default_options() {
    CagdReduceOptions o;
    check(cagd_reduce_options_init(&o), "cagd_reduce_options_init");
    return o;
}

}  // namespace cagd

#endif  // CAGD_HPP
