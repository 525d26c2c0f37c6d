//! Intersection of two planar rational Bézier curves through implicitization
//! (issue 12, beyond seed 002): the curve of lower degree is implicitized (base points
//! divided out), the other is substituted into its implicit polynomial in the Bernstein
//! basis ([`crate::compose`]), the degree-`n m` polynomial is solved on `[0, 1]` by
//! subdivision ([`crate::bernstein_roots`]), each root's point is inverted on the
//! implicitized curve (kernel of `F`, or, at its singular points, a nearest-point search),
//! and every pair `(s, t)` is polished by Newton on `A(s) = B(t)`.
//!
//! Both curves are first moved by one common similarity to the unit box (intersection
//! parameters are invariant), so the monomial coefficients stay well scaled.

use cagd_core::{BezierCurve, Error, Result};

use crate::ImplicitCurve;
use crate::bernstein_roots::bernstein_roots;
use crate::compose::compose;
use crate::planar::{HomCurve, check_planar, weight};

/// One intersection point of two curves.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Intersection {
    /// Parameter on the first curve, in `[0, 1]`.
    pub s: f64,
    /// Parameter on the second curve, in `[0, 1]`.
    pub t: f64,
    /// The point (first curve evaluated at `s`).
    pub point: [f64; 2],
    /// Whether the curves are tangent there (`|A'(s) × B'(t)| <= 1e-7 |A'(s)| |B'(t)|`), or
    /// the point is a singular point of one of them.
    pub tangential: bool,
}

/// Sine of the angle under which an intersection counts as tangential.
const TANGENT_SIN: f64 = 1e-7;
/// Parameter distance under which two found intersections are the same.
const SAME_PARAM: f64 = 1e-9;

/// A curve moved by `p -> (p - centre) / scale`, in homogeneous `f64` form.
fn normalized(c: &BezierCurve, centre: [f64; 2], scale: f64) -> Result<BezierCurve> {
    let pts: Vec<f64> = (0..=c.degree())
        .flat_map(|i| {
            let p = c.point(i);
            [(p[0] - centre[0]) / scale, (p[1] - centre[1]) / scale]
        })
        .collect();
    let w: Vec<f64> = (0..=c.degree()).map(|i| weight(c, i)).collect();
    BezierCurve::new_rational(pts, w, 2)
}

/// Every intersection of `a` and `b` with both parameters in `[0, 1]`, sorted by `s`.
/// Degree up to [`crate::MAX_IMPLICIT_DEGREE`] each (tested up to 5, benchmarked at 3 and 5).
///
/// # Errors
/// [`Error::NotPlanar`], [`Error::NotEnoughPoints`], [`Error::DegreeOutOfRange`];
/// [`Error::BasePoint`] when a curve is a
/// single point; [`Error::DegreeOutOfRange`] when `deg a * deg b` exceeds
/// [`cagd_core::MAX_BINOMIAL_N`]; [`Error::Coincident`] when the curves overlap along an arc;
/// [`Error::ConditionNotMet`] when an implicit coefficient overflows `f64`.
///
/// ```
/// use cagd_core::BezierCurve;
/// // A parabola arc and the horizontal line y = 0.5 meet twice.
/// let a = BezierCurve::new(vec![0.0, 0.0, 1.0, 2.0, 2.0, 0.0], 2)?;
/// let b = BezierCurve::new(vec![-1.0, 0.5, 3.0, 0.5], 2)?;
/// let hits = cagd_implicit::intersect(&a, &b)?;
/// assert_eq!(hits.len(), 2);
/// for h in &hits {
///     let (p, q) = (a.eval(h.s), b.eval(h.t));
///     assert!((p[0] - q[0]).abs() < 1e-14 && (p[1] - q[1]).abs() < 1e-14);
///     assert!(!h.tangential);
/// }
/// # Ok::<(), cagd_core::Error>(())
/// ```
pub fn intersect(a: &BezierCurve, b: &BezierCurve) -> Result<Vec<Intersection>> {
    check_planar(a)?;
    check_planar(b)?;
    // The substituted polynomial has degree `deg a * deg b`; its Bernstein binomials are
    // exact only up to MAX_BINOMIAL_N (beyond the seed; found by the C ABI fuzz harness,
    // issue 18: two degree-16 curves panicked in the binomial table).
    let product = a.degree().saturating_mul(b.degree());
    if product > cagd_core::MAX_BINOMIAL_N {
        return Err(Error::DegreeOutOfRange {
            degree: product,
            max: cagd_core::MAX_BINOMIAL_N,
        });
    }
    // Common similarity to the unit box.
    let (mut lo, mut hi) = ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]);
    for c in [a, b] {
        for i in 0..=c.degree() {
            let p = c.point(i);
            for k in 0..2 {
                lo[k] = lo[k].min(p[k]);
                hi[k] = hi[k].max(p[k]);
            }
        }
    }
    let centre = [0.5 * (lo[0] + hi[0]), 0.5 * (lo[1] + hi[1])];
    let half = (0.5 * (hi[0] - lo[0])).max(0.5 * (hi[1] - lo[1]));
    let scale = if half > 0.0 { half } else { 1.0 };
    let (na, nb) = (normalized(a, centre, scale)?, normalized(b, centre, scale)?);
    // Implicitize the curve of lower degree; `swap` = the implicit one is b.
    let swap = b.degree() < a.degree();
    let (imp_src, par_src) = if swap { (&nb, &na) } else { (&na, &nb) };
    let imp = ImplicitCurve::new(imp_src)?;
    let par = HomCurve::new(par_src);
    let (g, err) = compose(&imp.polynomial, &par.hom);
    let roots = match bernstein_roots(&g, &err) {
        Ok(r) => r,
        Err(Error::Coincident { .. }) => return overlap(&imp, &par, swap, a),
        Err(e) => return Err(e),
    };
    let mut found: Vec<(f64, f64)> = Vec::new(); // (s on imp, t on par)
    for r in roots {
        let q = par.point(r.t);
        for s in parameters_on(&imp, q) {
            found.push(polish(&imp.curve, &par, s, r.t));
        }
    }
    Ok(finish(found, &imp.curve, &par, swap, a))
}

/// The parameters on `imp` of the point `q` (kernel inversion, or a nearest-point search
/// at singular points, improper parametrizations and inaccurate points).
fn parameters_on(imp: &ImplicitCurve, q: [f64; 2]) -> Vec<f64> {
    if let Ok(s) = imp.invert(q[0], q[1]) {
        return vec![s];
    }
    nearest_parameters(&imp.curve, q, 1e-6)
}

/// Local minima of `|P(s) - q|` on `[0, 1]` within `tol` (relative to the unit box).
fn nearest_parameters(imp: &HomCurve, q: [f64; 2], tol: f64) -> Vec<f64> {
    let n = imp.degree();
    let samples = 32 * (n + 1);
    let d = |s: f64| {
        let p = imp.point(s);
        (p[0] - q[0]).hypot(p[1] - q[1])
    };
    let vals: Vec<f64> = (0..=samples)
        .map(|k| d(k as f64 / samples as f64))
        .collect();
    let mut out = Vec::new();
    for k in 0..=samples {
        let left = if k > 0 { vals[k - 1] } else { f64::INFINITY };
        let right = if k < samples {
            vals[k + 1]
        } else {
            f64::INFINITY
        };
        if vals[k] <= left && vals[k] <= right {
            let (s_raw, dist) = imp.polish(q[0], q[1], k as f64 / samples as f64);
            let s = s_raw.clamp(0.0, 1.0);
            if d(s).min(if (0.0..=1.0).contains(&s_raw) {
                dist
            } else {
                f64::INFINITY
            }) <= tol
                && !out.iter().any(|o: &f64| (o - s).abs() < 1e-7)
            {
                out.push(s);
            }
        }
    }
    out
}

/// Newton on `A(s) - B(t) = 0` from `(s, t)`; keeps the start when Newton does not improve
/// it or wanders off (tangential intersections have a singular Jacobian).
fn polish(a: &HomCurve, b: &HomCurve, s0: f64, t0: f64) -> (f64, f64) {
    let resid = |s: f64, t: f64| {
        let (p, q) = (a.point(s), b.point(t));
        (p[0] - q[0]).hypot(p[1] - q[1])
    };
    let (mut s, mut t) = (s0, t0);
    let mut best = (s0, t0, resid(s0, t0));
    for _ in 0..12 {
        let (p, dp) = a.point_and_tangent(s);
        let (q, dq) = b.point_and_tangent(t);
        let r = [p[0] - q[0], p[1] - q[1]];
        // [dp, -dq] [ds, dt]^T = -r
        let det = -dp[0] * dq[1] + dq[0] * dp[1];
        let size = dp[0].hypot(dp[1]) * dq[0].hypot(dq[1]);
        if !det.is_finite() || det.abs() <= 1e-12 * size {
            break;
        }
        let ds = (-r[0] * -dq[1] + dq[0] * -r[1]) / det;
        let dt = (dp[0] * -r[1] - dp[1] * -r[0]) / det;
        s += ds;
        t += dt;
        if (s - s0).abs() > 1e-4 || (t - t0).abs() > 1e-4 || !s.is_finite() || !t.is_finite() {
            break;
        }
        let e = resid(s, t);
        if e < best.2 {
            best = (s, t, e);
        }
        if ds.abs().max(dt.abs()) < 1e-16 {
            break;
        }
    }
    (best.0, best.1)
}

/// Filters to `[0, 1]^2`, flags tangency, merges duplicates, maps back to `(a, b)` order
/// and sorts by `s`.
fn finish(
    found: Vec<(f64, f64)>,
    imp: &HomCurve,
    par: &HomCurve,
    swap: bool,
    a: &BezierCurve,
) -> Vec<Intersection> {
    const SLACK: f64 = 1e-9;
    let mut out: Vec<Intersection> = Vec::new();
    for (si, tp) in found {
        if !(-SLACK..=1.0 + SLACK).contains(&si) || !(-SLACK..=1.0 + SLACK).contains(&tp) {
            continue;
        }
        let (si, tp) = (si.clamp(0.0, 1.0), tp.clamp(0.0, 1.0));
        let (_, d1) = imp.point_and_tangent(si);
        let (_, d2) = par.point_and_tangent(tp);
        let cross = (d1[0] * d2[1] - d1[1] * d2[0]).abs();
        let size = d1[0].hypot(d1[1]) * d2[0].hypot(d2[1]);
        let tangential = cross.is_nan() || cross <= TANGENT_SIN * size;
        let (s, t) = if swap { (tp, si) } else { (si, tp) };
        let e = a.eval(s);
        let hit = Intersection {
            s,
            t,
            point: [e[0], e[1]],
            tangential,
        };
        match out
            .iter_mut()
            .find(|o| (o.s - s).abs() <= SAME_PARAM && (o.t - t).abs() <= SAME_PARAM)
        {
            Some(o) => o.tangential |= tangential,
            None => out.push(hit),
        }
    }
    out.sort_by(|x, y| x.s.total_cmp(&y.s).then(x.t.total_cmp(&y.t)));
    out
}

/// The curves lie on the same algebraic curve: an arc in common is [`Error::Coincident`];
/// otherwise only end points can be shared, and those are returned.
fn overlap(
    imp: &ImplicitCurve,
    par: &HomCurve,
    swap: bool,
    a: &BezierCurve,
) -> Result<Vec<Intersection>> {
    let curve = &imp.curve;
    const SAMPLES: usize = 64;
    let inside: Vec<Option<f64>> = (0..=SAMPLES)
        .map(|k| {
            let t = k as f64 / SAMPLES as f64;
            let q = par.point(t);
            nearest_parameters(curve, q, 1e-9).into_iter().next()
        })
        .collect();
    let on: Vec<f64> = inside.iter().flatten().copied().collect();
    let shared_arc = inside.windows(2).any(|w| w[0].is_some() && w[1].is_some());
    if shared_arc {
        let s0 = on.iter().copied().fold(f64::INFINITY, f64::min);
        let s1 = on.iter().copied().fold(f64::NEG_INFINITY, f64::max);
        let (s0, s1) = if swap {
            // Report the overlap on the first curve (par is a).
            let t: Vec<f64> = (0..=SAMPLES)
                .filter(|&k| inside[k].is_some())
                .map(|k| k as f64 / SAMPLES as f64)
                .collect();
            (t[0], t[t.len() - 1])
        } else {
            (s0, s1)
        };
        return Err(Error::Coincident { s0, s1 });
    }
    // End points of either curve lying on the other.
    let mut found = Vec::new();
    for t in [0.0, 1.0] {
        for s in nearest_parameters(curve, par.point(t), 1e-9) {
            found.push((s, t));
        }
    }
    for s in [0.0, 1.0] {
        for t in nearest_parameters(par, curve.point(s), 1e-9) {
            found.push((s, t));
        }
    }
    Ok(finish(found, curve, par, swap, a))
}
