//! Triangular patch ↔ degenerate rectangular patch (SPEC-convert §15.4, eq. 15.4.2 and
//! Theorem 15.4.2 / eq. 15.4.4).

use cagd_core::{Error, Result, TensorPatch, TriPatch, check_tolerance, tri_count, tri_index};

use super::blossom::elevate_to;
use super::{PatchPiece, PatchSurface, PieceDomain, TensorSurface, TriSurface};

/// Domain of the §15.4 map `u = s, v = (1 - s) t` (the edge `s = 1` collapses to `(1, 0)`).
pub(crate) const DEGENERATE_DOMAIN: [[f64; 2]; 4] =
    [[0.0, 0.0], [1.0, 0.0], [0.0, 1.0], [1.0, 0.0]];

/// The triangle of degree `n` as a degenerate `m x n` rectangle, `m >= n` (SPEC-convert
/// §15.4, eq. 15.4.2): row `i` of the triangle elevated from degree `n - i` to `n`
/// (`A_n ⋯ A_{n-i+1}`), then the whole net elevated in `s` from `n` to `m`.
/// `P(s, t) = T(s, (1 - s) t)`; the piece's domain is the degenerate bilinear
/// `[(0,0), (1,0), (0,1), (1,0)]`. Rational patches through homogeneous points.
///
/// # Errors
/// [`Error::BadDegreePair`] when `m < n`, [`Error::DegreeOutOfRange`] when `m > 64`.
///
/// ```
/// use cagd_convert::{PatchSurface, TriSurface, degenerate_rect_to_triangle, triangle_to_degenerate_rect};
/// // T(u, v) = u + 2 v (degree 1), as a degenerate 1 x 1 rectangle and back.
/// let t = TriSurface::new(vec![0.0, 2.0, 1.0], 1, 1, None)?;
/// let piece = triangle_to_degenerate_rect(&t, 1)?;
/// let PatchSurface::Tensor(r) = &piece.surface else { unreachable!() };
/// assert_eq!(r.net().points(), &[0.0, 2.0, 1.0, 1.0]); // P(s, t) = T(s, (1 - s) t)
/// let [u, v] = piece.domain.map(0.5, 0.5);
/// assert!((r.eval(0.5, 0.5)[0] - t.eval(u, v)[0]).abs() < 1e-15);
/// assert_eq!(degenerate_rect_to_triangle(r, 1e-12)?, t);
/// # Ok::<(), cagd_core::Error>(())
/// ```
pub fn triangle_to_degenerate_rect(t: &TriSurface, m: usize) -> Result<PatchPiece> {
    let n = t.degree();
    if m < n {
        return Err(Error::BadDegreePair {
            from: n,
            to: m,
            why: "the rectangle's s-degree must be at least the triangle's degree",
        });
    }
    cagd_core::check_degree(m)?;
    let h = t.homogeneous();
    let dim = h.dim();
    let mut pts = Vec::with_capacity((n + 1) * (n + 1) * dim);
    for i in 0..=n {
        let row = &h.points()[tri_index(n, i, 0) * dim..(tri_index(n, i, n - i) + 1) * dim];
        pts.extend(elevate_to(row, dim, n));
    }
    let mut net = TensorPatch::new(pts, n, n, dim)?;
    if m > n {
        net = net.elevate_u(m - n)?;
    }
    Ok(PatchPiece {
        surface: PatchSurface::Tensor(TensorSurface::from_homogeneous(net, t.weights().is_some())?),
        domain: PieceDomain::Bilinear(DEGENERATE_DOMAIN),
    })
}

/// Exact reduction of a degree-`d` polygon that is an elevated degree-`d - 1` polygon: the
/// left recursion `Q_i = (d P_i - i Q_{i-1}) / (d - i)` for the first half and the right one
/// `Q_{i-1} = (d P_i - (d - i) Q_i) / i` for the second (SPEC-convert §15.4: "the mean of
/// the left and right reduction recursions"; each half only divides by factors >= 1/2 of
/// `d`, so rounding is not amplified).
fn reduce_once(p: &[f64], dim: usize) -> Vec<f64> {
    let d = p.len() / dim - 1;
    let mut q = vec![0.0; d * dim];
    let half = (d - 1) / 2; // indices 0..=half from the left
    let df = d as f64;
    q[..dim].copy_from_slice(&p[..dim]);
    for i in 1..=half {
        for k in 0..dim {
            q[i * dim + k] =
                (df * p[i * dim + k] - i as f64 * q[(i - 1) * dim + k]) / (df - i as f64);
        }
    }
    if d > half + 1 {
        q[(d - 1) * dim..].copy_from_slice(&p[d * dim..]);
        for i in (half + 2..d).rev() {
            // Q_{i-1} from Q_i.
            for k in 0..dim {
                q[(i - 1) * dim + k] =
                    (df * p[i * dim + k] - (df - i as f64) * q[i * dim + k]) / i as f64;
            }
        }
    }
    q
}

/// The triangle net (homogeneous) of an `n x n` net by exact row reduction, and the
/// relative residual of re-elevating it (SPEC-convert §15.4, Theorem 15.4.2).
fn reduce_rows(h: &TensorPatch) -> (Vec<f64>, f64) {
    let (n, _) = h.degrees();
    let dim = h.dim();
    let mut tri = vec![0.0; tri_count(n) * dim];
    let mut worst: f64 = 0.0;
    let scale = h
        .points()
        .iter()
        .fold(0.0_f64, |a, x| a.max(x.abs()))
        .max(f64::MIN_POSITIVE);
    for i in 0..=n {
        let row = &h.points()[i * (n + 1) * dim..(i + 1) * (n + 1) * dim];
        let mut cur = row.to_vec();
        for _ in 0..i {
            cur = reduce_once(&cur, dim);
        }
        let back = elevate_to(&cur, dim, n);
        for (a, b) in back.iter().zip(row) {
            worst = worst.max((a - b).abs());
        }
        let o = tri_index(n, i, 0) * dim;
        tri[o..o + cur.len()].copy_from_slice(&cur);
    }
    (tri, worst / scale)
}

/// The relative residual of Theorem 15.4.2 for a square net: how far the `n x n` patch is
/// from a degenerate triangle (largest coordinate difference between each row and its
/// exactly reduced-then-elevated row, divided by the largest coordinate). `0` for an exact
/// degenerate triangle. Rational patches are tested on their homogeneous points.
///
/// # Errors
/// [`Error::BadDegreePair`] when the patch is not square.
pub fn degenerate_residual(p: &TensorSurface) -> Result<f64> {
    let h = square(p)?;
    Ok(reduce_rows(&h).1)
}

/// The homogeneous net of a square patch.
fn square(p: &TensorSurface) -> Result<TensorPatch> {
    let (m, n) = p.degrees();
    if m != n {
        return Err(Error::BadDegreePair {
            from: m,
            to: n,
            why: "a degenerate triangle is an n x n rectangle",
        });
    }
    Ok(p.homogeneous())
}

/// The inverse of §15.4: an `n x n` rectangle that satisfies Theorem 15.4.2 (eq. 15.4.4,
/// row `i` has degree `<= n - i`) back to its triangle of degree `n`: row `i` reduced
/// exactly from `n` to `n - i`. `T(u, v) = P(u, v / (1 - u))`.
///
/// # Errors
/// [`Error::BadDegreePair`] (not square), [`Error::BadTolerance`], [`Error::NotDegenerate`]
/// with the relative residual when it is above `tol`, [`Error::NonPositiveWeight`] if a
/// reduced weight is not positive.
pub fn degenerate_rect_to_triangle(p: &TensorSurface, tol: f64) -> Result<TriSurface> {
    check_tolerance(tol)?;
    let h = square(p)?;
    let (tri, residual) = reduce_rows(&h);
    if residual > tol || !residual.is_finite() {
        return Err(Error::NotDegenerate { residual, tol });
    }
    let net = TriPatch::new(tri, h.degrees().0, h.dim())?;
    TriSurface::from_homogeneous(net, p.weights().is_some())
}
