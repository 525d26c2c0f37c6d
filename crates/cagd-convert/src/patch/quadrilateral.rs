//! Triangular patch → non-degenerate rectangular patches over quadrilaterals of its domain
//! (SPEC-convert §15.5, the general quadrilateral form; eqs. 15.5.1–15.5.3 with the
//! erratum `k + l = j`).

use cagd_core::{Error, Result, TensorPatch};

use super::blossom::{pascal, tri_blossom_table};
use super::surface::check_range;
use super::{PatchPiece, PatchSurface, PieceDomain, TensorSurface, TriSurface};

/// Inner point `P` and edge points `G` (on `v = 0`), `K` (on `u + v = 1`), `H` (on
/// `u = 0`) of the three-patch split of SPEC-convert §15.5.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TriSplitPoints {
    /// Inner point `P = (a, c)`: `a, c > 0`, `a + c < 1`.
    pub p: [f64; 2],
    /// `G = (g, 0)`, `0 < g < 1`.
    pub g: f64,
    /// `K = (k, 1 - k)`, `0 < k < 1`.
    pub k: f64,
    /// `H = (0, h)`, `0 < h < 1`.
    pub h: f64,
}

impl Default for TriSplitPoints {
    /// The centroid and the edge midpoints.
    fn default() -> Self {
        Self {
            p: [1.0 / 3.0, 1.0 / 3.0],
            g: 0.5,
            k: 0.5,
            h: 0.5,
        }
    }
}

/// `det(b - a, c - a)`.
fn cross(a: [f64; 2], b: [f64; 2], c: [f64; 2]) -> f64 {
    (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])
}

/// Checks the corners of a bilinear sub-domain `[X00, X10, X01, X11]`: finite, inside the
/// closed unit triangle, and the Jacobian `> 0` at the four corners (the Jacobian of a
/// bilinear map is affine in `(s, t)`, so this is `> 0` on the whole square; SPEC-convert
/// §15.5, "non-degeneracy precondition").
///
/// # Errors
/// [`Error::BadParameter`], [`Error::DegenerateSplit`].
fn check_quad(x: &[[f64; 2]; 4]) -> Result<()> {
    const NAMES: [&str; 4] = ["corner X00", "corner X10", "corner X01", "corner X11"];
    for (c, name) in x.iter().zip(NAMES) {
        let why = "a corner of the sub-domain must lie in the unit triangle u, v >= 0, u + v <= 1";
        check_range(name, c[0], 0.0, 1.0, why)?;
        check_range(name, c[1], 0.0, 1.0, why)?;
        if c[0] + c[1] > 1.0 + 4.0 * f64::EPSILON {
            return Err(Error::BadParameter {
                name,
                value: c[0] + c[1],
                why,
            });
        }
    }
    let [x00, x10, x01, x11] = *x;
    let jac = [
        ("jacobian at corner X00", cross(x00, x10, x01)),
        ("jacobian at corner X10", cross(x10, x11, x00)),
        ("jacobian at corner X01", cross(x01, x00, x11)),
        ("jacobian at corner X11", cross(x11, x01, x10)),
    ];
    for (what, j) in jac {
        // Areas of order eps^2 of the unit triangle are folds for all practical purposes.
        if j.is_nan() || j <= 1e-14 {
            return Err(Error::DegenerateSplit { what, value: j });
        }
    }
    Ok(())
}

/// The triangle restricted to the quadrilateral `[X00, X10, X01, X11]` of its domain, as an
/// `n x n` tensor patch `P(s, t) = T(X(s, t))` with the bilinear `X` (SPEC-convert §15.5,
/// general form):
/// `P_ij = sum_k C(i,k) C(n-i,j-k) / C(n,j) * b(X11^k, X10^(i-k), X01^(j-k), X00^(n-i-j+k))`,
/// `k = max(0, j-n+i) ..= min(i, j)`, `b` the blossom of the triangle (homogeneous for a
/// rational patch). The corners must lie in the triangle and the map must not fold.
///
/// # Errors
/// [`Error::BadParameter`] (a corner outside the triangle or not finite),
/// [`Error::DegenerateSplit`] (Jacobian `<= 0` at a corner).
pub fn triangle_to_quad(t: &TriSurface, corners: [[f64; 2]; 4]) -> Result<PatchPiece> {
    check_quad(&corners)?;
    let h = t.homogeneous();
    let (n, dim) = (h.degree(), h.dim());
    let [x00, x10, x01, x11] = corners;
    let table = tri_blossom_table(h.points(), n, dim, [x11, x10, x01, x00]);
    let binom = pascal(n);
    let mut pts = vec![0.0; (n + 1) * (n + 1) * dim];
    for i in 0..=n {
        for j in 0..=n {
            let o = (i * (n + 1) + j) * dim;
            let cj = binom[n][j];
            for k in (j + i).saturating_sub(n)..=i.min(j) {
                let c = binom[i][k] * binom[n - i][j - k] / cj;
                let b = &table[k][i - k][j - k];
                for x in 0..dim {
                    pts[o + x] += c * b[x];
                }
            }
        }
    }
    let net = TensorPatch::new(pts, n, n, dim)?;
    Ok(PatchPiece {
        surface: PatchSurface::Tensor(TensorSurface::from_homogeneous(net, t.weights().is_some())?),
        domain: PieceDomain::Bilinear(corners),
    })
}

/// The triangle over the quadrilateral `D1 = (O, G, H, P)` with `G = (b, 0)`, `H = (0, d)`,
/// `P = (a, c)`: the map (15.5.3) `u = s[a t + b(1-t)]`, `v = [c s + d(1-s)] t`
/// (SPEC-convert §15.5, eqs. 15.5.1–15.5.2, computed by the general form).
///
/// # Errors
/// [`Error::BadParameter`], [`Error::DegenerateSplit`] unless `a, b, c, d > 0`,
/// `a d + b c > b d` and the corners lie in the triangle.
pub fn triangle_to_rect_d1(t: &TriSurface, a: f64, b: f64, c: f64, d: f64) -> Result<PatchPiece> {
    triangle_to_quad(t, [[0.0, 0.0], [b, 0.0], [0.0, d], [a, c]])
}

/// The triangle as three non-degenerate `n x n` rectangles through the inner point `P` and
/// the edge points `G`, `K`, `H` (SPEC-convert §15.5): `D1 = (O, G, H, P)`,
/// `D2 = (U, K, G, P)`, `D3 = (V, H, K, P)` as `(X00, X10, X01, X11)` with `O = (0,0)`,
/// `U = (1,0)`, `V = (0,1)`. Neighbours share their boundary nets (the shared edge is the
/// same blossom; equal up to rounding).
///
/// # Errors
/// [`Error::BadParameter`] (a point outside its edge / the open triangle),
/// [`Error::DegenerateSplit`] (a folded quadrilateral).
pub fn triangle_to_three_rects(t: &TriSurface, pts: TriSplitPoints) -> Result<[PatchPiece; 3]> {
    let [a, c] = pts.p;
    let open = "must lie strictly inside (0, 1)";
    check_range("G", pts.g, 0.0, 1.0, open)?;
    check_range("K", pts.k, 0.0, 1.0, open)?;
    check_range("H", pts.h, 0.0, 1.0, open)?;
    for (name, x) in [("G", pts.g), ("K", pts.k), ("H", pts.h)] {
        if x <= 0.0 || x >= 1.0 {
            return Err(Error::BadParameter {
                name,
                value: x,
                why: open,
            });
        }
    }
    let inner = "the inner point needs a, c > 0 and a + c < 1";
    check_range("P.u", a, 0.0, 1.0, inner)?;
    check_range("P.v", c, 0.0, 1.0, inner)?;
    if a <= 0.0 || c <= 0.0 || a + c >= 1.0 {
        return Err(Error::BadParameter {
            name: "P",
            value: a + c,
            why: inner,
        });
    }
    let (o, u, v) = ([0.0, 0.0], [1.0, 0.0], [0.0, 1.0]);
    let (p, g, k, h) = ([a, c], [pts.g, 0.0], [pts.k, 1.0 - pts.k], [0.0, pts.h]);
    let quads = [[o, g, h, p], [u, k, g, p], [v, h, k, p]];
    for q in &quads {
        check_quad(q)?;
    }
    Ok([
        triangle_to_quad(t, quads[0])?,
        triangle_to_quad(t, quads[1])?,
        triangle_to_quad(t, quads[2])?,
    ])
}
