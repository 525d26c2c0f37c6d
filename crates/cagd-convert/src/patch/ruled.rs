//! A tensor patch restricted to a region between two polynomial curves `u = lo(v)` and
//! `u = hi(v)`, computed exactly by the corner cutting of SPEC-convert §15.7 ("recommended
//! algorithm", Theorem 15.7.1 in stable form). It generalises §15.6.1 (lines) and §15.7
//! (`lo = 0`, D5 / D7) to two curved sides.

use cagd_core::{Error, Result, TensorPatch};

use super::blossom::{corner_cut, curve_restrict, elevate_to, pascal};
use super::{PatchPiece, PatchSurface, PieceDomain, TensorSurface};

/// The exact sub-patch `Q(s, t) = P((1 - s) lo(t) + s hi(t), v0 + t (v1 - v0))` of the
/// homogeneous net `h` (degree `(m, n)`), with `lo`, `hi` Bernstein coefficients in `t`.
///
/// `Q_i` (row `i`, in `s`) is the `u`-blossom of `P` at `(lo(t)^(m-i), hi(t)^i)`, a
/// polynomial in `t` of degree `n + i kh + (m - i) kl`: start from the `u`-rows of `P`
/// restricted to `[v0, v1]` in `v`, cut `i` times with `hi` and `m - i` times with `lo`
/// (each cut is a convex Bernstein product when the coefficients lie in `[0, 1]`), then
/// elevate to `n + m max(kl, kh)`. Output degree `(m, n + m max(kl, kh))`.
pub(crate) fn ruled_net(h: &TensorPatch, lo: &[f64], hi: &[f64], v0: f64, v1: f64) -> TensorPatch {
    let ((m, n), dim) = (h.degrees(), h.dim());
    let (kl, kh) = (lo.len() - 1, hi.len() - 1);
    let out_n = n + m * kl.max(kh);
    let rows: Vec<Vec<f64>> = (0..=m)
        .map(|p| {
            let row = &h.points()[p * (n + 1) * dim..(p + 1) * (n + 1) * dim];
            if v0 == 0.0 && v1 == 1.0 {
                row.to_vec()
            } else {
                curve_restrict(row, dim, v0, v1)
            }
        })
        .collect();
    let binom = pascal(n + m * (kl + kh));
    let mut pts = Vec::with_capacity((m + 1) * (out_n + 1) * dim);
    // One sweep of hi-cuts: after i of them, `with_hi` holds b(hi^i, ·) (m + 1 - i rows,
    // degree n + i kh); row i of the result then takes m - i lo-cuts of it.
    let mut with_hi = rows;
    for i in 0..=m {
        if i > 0 {
            with_hi = corner_cut(&with_hi, n + (i - 1) * kh, dim, hi, &binom);
        }
        let mut z = with_hi.clone();
        let mut d = n + i * kh;
        for _ in i..m {
            z = corner_cut(&z, d, dim, lo, &binom);
            d += kl;
        }
        pts.extend(elevate_to(&z[0], dim, out_n));
    }
    // Sizes are consistent by construction.
    TensorPatch::new(pts, m, out_n, dim).unwrap_or_else(|_| h.clone())
}

/// Checks that the Bernstein polynomial `c` stays in `[lo, hi]` on `[0, 1]` (up to
/// `1e-12`): true when every coefficient does; false when an end value or a value found by
/// subdividing does not; subdivision at `1/2` refines the coefficient bounds in between.
/// Returns the offending value found, if any.
pub(crate) fn range_violation(c: &[f64], lo: f64, hi: f64) -> Option<f64> {
    const SLACK: f64 = 1e-12;
    fn go(c: &[f64], lo: f64, hi: f64, depth: usize) -> Option<f64> {
        if c.iter().all(|x| *x >= lo - SLACK && *x <= hi + SLACK) {
            return None;
        }
        for end in [c[0], c[c.len() - 1]] {
            if end < lo - SLACK || end > hi + SLACK {
                return Some(end);
            }
        }
        if depth == 0 {
            // The coefficient hull still leaves the range by a tiny amount no end value
            // confirms: the excursion, if any, is below the resolution of 2^-40 in t.
            return None;
        }
        let (mut l, mut r) = (vec![0.0; c.len()], vec![0.0; c.len()]);
        cagd_core::kernel::subdivide(c, 1, 0.5, &mut l, &mut r);
        go(&l, lo, hi, depth - 1).or_else(|| go(&r, lo, hi, depth - 1))
    }
    if let Some(x) = c.iter().find(|x| !x.is_finite()) {
        return Some(*x);
    }
    go(c, lo, hi, 40)
}

/// Checks a side function: non-empty, degree `<= 64`, values in `[0, 1]`.
pub(crate) fn check_side(name: &'static str, c: &[f64]) -> Result<()> {
    if c.is_empty() {
        return Err(Error::NotEnoughPoints { got: 0, need: 1 });
    }
    cagd_core::check_degree(c.len() - 1)?;
    if let Some(value) = range_violation(c, 0.0, 1.0) {
        return Err(Error::BadParameter {
            name,
            value,
            why: "the splitting curve must stay in [0, 1] (0 <= f <= 1, SPEC-convert §15.7)",
        });
    }
    Ok(())
}

/// `hi - lo` as Bernstein coefficients of the common degree.
fn difference(lo: &[f64], hi: &[f64]) -> Vec<f64> {
    let k = (lo.len().max(hi.len())) - 1;
    let (l, h) = (elevate_to(lo, 1, k), elevate_to(hi, 1, k));
    h.iter().zip(&l).map(|(a, b)| a - b).collect()
}

/// The ruled domain of `u = (1 - s) lo(t) + s hi(t)`, `v = v0 + t (v1 - v0)`, with the
/// coordinates swapped when `transposed`.
pub(crate) fn ruled_domain(
    lo: &[f64],
    hi: &[f64],
    v0: f64,
    v1: f64,
    transposed: bool,
) -> PieceDomain {
    let k = lo.len().max(hi.len()) - 1;
    let side = |c: &[f64]| -> Vec<[f64; 2]> {
        elevate_to(c, 1, k)
            .iter()
            .enumerate()
            .map(|(j, &u)| {
                let x = if k == 0 { 0.0 } else { j as f64 / k as f64 };
                let v = (1.0 - x) * v0 + x * v1;
                if transposed { [v, u] } else { [u, v] }
            })
            .collect()
    };
    let (mut s0, mut s1) = (side(lo), side(hi));
    if k == 0 {
        // A constant side is still a segment in v: give it degree 1.
        let a = |p: [f64; 2]| if transposed { [v1, p[1]] } else { [p[0], v1] };
        s0.push(a(s0[0]));
        s1.push(a(s1[0]));
    }
    PieceDomain::Ruled { s0, s1 }
}

/// The tensor patch swapped in `u` and `v` (`P^T(v, u) = P(u, v)`).
pub(crate) fn transpose(h: &TensorPatch) -> TensorPatch {
    let ((m, n), dim) = (h.degrees(), h.dim());
    let mut pts = Vec::with_capacity(h.points().len());
    for j in 0..=n {
        for i in 0..=m {
            pts.extend_from_slice(h.point(i, j));
        }
    }
    TensorPatch::new(pts, n, m, dim).unwrap_or_else(|_| h.clone())
}

/// The exact piece of `p` between the curves `u = lo(v)` and `u = hi(v)` for
/// `v in [v0, v1]` (or, when `transposed`, between `v = lo(u)` and `v = hi(u)` for
/// `u in [v0, v1]`); `lo`, `hi` are Bernstein coefficients over the local `t in [0, 1]` of
/// that interval, any degrees. The piece has degree `(m, n + m max(kl, kh))`
/// (`(n, m + n max(..))` when transposed) and a [`PieceDomain::Ruled`] domain: its `s`
/// runs from `lo` to `hi`, its `t` along the interval (SPEC-convert §15.7, corner cutting).
///
/// # Errors
/// [`Error::BadParameter`] when `lo` or `hi` leaves `[0, 1]`, when `lo > hi` somewhere, or
/// when `0 <= v0 < v1 <= 1` fails; [`Error::DegreeOutOfRange`] when the piece's degree
/// `n + m max(kl, kh)` exceeds [`cagd_core::MAX_DEGREE`]; [`Error::NonPositiveWeight`] cannot occur for valid
/// input (convex combinations of positive weights).
pub fn ruled_subpatch(
    p: &TensorSurface,
    lo: &[f64],
    hi: &[f64],
    v0: f64,
    v1: f64,
    transposed: bool,
) -> Result<PatchPiece> {
    check_side("lo curve", lo)?;
    check_side("hi curve", hi)?;
    if let Some(value) = range_violation(&difference(lo, hi), 0.0, f64::INFINITY) {
        return Err(Error::BadParameter {
            name: "hi - lo",
            value,
            why: "the curve on the s = 1 side must not cross the one on the s = 0 side",
        });
    }
    if !(v0.is_finite() && v1.is_finite() && 0.0 <= v0 && v0 < v1 && v1 <= 1.0) {
        return Err(Error::BadParameter {
            name: "interval",
            value: if (0.0..=1.0).contains(&v0) { v1 } else { v0 },
            why: "the interval of the ruled piece needs 0 <= start < end <= 1",
        });
    }
    let mut h = p.homogeneous();
    if transposed {
        h = transpose(&h);
    }
    // The piece's degree `n + m max(kl, kh)` must be one cagd supports (its binomials are
    // exact up to MAX_DEGREE); beyond the seed, found by the C ABI fuzz harness (issue 18:
    // a degree-131 piece panicked in the binomial table).
    let ((m, n), k) = (h.degrees(), lo.len().max(hi.len()).saturating_sub(1));
    cagd_core::check_degree(m.saturating_mul(k).saturating_add(n))?;
    let net = ruled_net(&h, lo, hi, v0, v1);
    Ok(PatchPiece {
        surface: PatchSurface::Tensor(TensorSurface::from_homogeneous(net, p.weights().is_some())?),
        domain: ruled_domain(lo, hi, v0, v1, transposed),
    })
}
