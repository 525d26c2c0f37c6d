//! Which part of the input's `(u, v)` domain an output piece covers, and the maps from a
//! piece's own parameters to the input's.

use super::PatchSurface;

/// The part of the input's parameter domain covered by an output piece, as the map from the
/// piece's own parameters to the input's `(u, v)`.
#[derive(Debug, Clone, PartialEq)]
pub enum PieceDomain {
    /// Bilinear quadrilateral `[X00, X10, X01, X11]`: the piece's `(s, t)` maps to
    /// `(1-s)(1-t) X00 + s(1-t) X10 + (1-s) t X01 + s t X11` (corners may coincide: a
    /// degenerate quadrilateral, e.g. §15.4's triangle).
    Bilinear([[f64; 2]; 4]),
    /// Triangle `[A, B, C]`: the piece's `(u', v')` maps to `C + u'(A - C) + v'(B - C)`.
    Triangle([[f64; 2]; 3]),
    /// Ruled region between two Bézier curves of the `(u, v)` plane (a curved split,
    /// SPEC-convert §15.7): the piece's `(s, t)` maps to `(1 - s) L(t) + s R(t)`, where `L`
    /// (at `s = 0`) and `R` (at `s = 1`) are given by their control points (equal degrees).
    Ruled {
        /// Control points of the side `s = 0`.
        s0: Vec<[f64; 2]>,
        /// Control points of the side `s = 1`.
        s1: Vec<[f64; 2]>,
    },
}

/// One output piece of a conversion: the patch and the part of the input domain it covers.
#[derive(Debug, Clone, PartialEq)]
pub struct PatchPiece {
    /// The patch (its own parameters `(s, t)`, or `(u', v')` for a triangle).
    pub surface: PatchSurface,
    /// Where those parameters land in the input's `(u, v)` domain.
    pub domain: PieceDomain,
}

/// De Casteljau value of a planar Bézier curve.
fn plane_curve(points: &[[f64; 2]], t: f64) -> [f64; 2] {
    let mut cur = points.to_vec();
    for r in 1..cur.len() {
        for i in 0..cur.len() - r {
            cur[i] = [
                (1.0 - t) * cur[i][0] + t * cur[i + 1][0],
                (1.0 - t) * cur[i][1] + t * cur[i + 1][1],
            ];
        }
    }
    cur.first().copied().unwrap_or([0.0, 0.0])
}

impl PieceDomain {
    /// The input parameters `(u, v)` of the piece's parameters `(s, t)`.
    pub fn map(&self, s: f64, t: f64) -> [f64; 2] {
        match self {
            PieceDomain::Bilinear(x) => {
                let w = [(1.0 - s) * (1.0 - t), s * (1.0 - t), (1.0 - s) * t, s * t];
                let mut out = [0.0; 2];
                for (c, wi) in x.iter().zip(w) {
                    out[0] += wi * c[0];
                    out[1] += wi * c[1];
                }
                out
            }
            PieceDomain::Triangle([a, b, c]) => [
                c[0] + s * (a[0] - c[0]) + t * (b[0] - c[0]),
                c[1] + s * (a[1] - c[1]) + t * (b[1] - c[1]),
            ],
            PieceDomain::Ruled { s0, s1 } => {
                let (l, r) = (plane_curve(s0, t), plane_curve(s1, t));
                [(1.0 - s) * l[0] + s * r[0], (1.0 - s) * l[1] + s * r[1]]
            }
        }
    }

    /// Whether the piece's own parameter domain is a triangle (`s, t >= 0, s + t <= 1`)
    /// rather than the unit square.
    pub fn is_triangle(&self) -> bool {
        matches!(self, PieceDomain::Triangle(_))
    }

    /// Finds the piece parameters `(s, t)` of the input point `(u, v)` when it lies in the
    /// piece (within `slack` in `s, t`), by Newton's method from a few starts (exact for
    /// triangles). Used to check that pieces tile a domain.
    pub fn locate(&self, u: f64, v: f64, slack: f64) -> Option<[f64; 2]> {
        if let PieceDomain::Triangle([a, b, c]) = self {
            let (e1, e2) = ([a[0] - c[0], a[1] - c[1]], [b[0] - c[0], b[1] - c[1]]);
            let det = e1[0] * e2[1] - e1[1] * e2[0];
            let (du, dv) = (u - c[0], v - c[1]);
            let s = (du * e2[1] - dv * e2[0]) / det;
            let t = (e1[0] * dv - e1[1] * du) / det;
            let inside = s >= -slack && t >= -slack && s + t <= 1.0 + slack;
            return inside.then_some([s, t]);
        }
        let starts = [[0.5, 0.5], [0.1, 0.1], [0.9, 0.1], [0.1, 0.9], [0.9, 0.9]];
        for st in starts {
            let [mut s, mut t] = st;
            for _ in 0..60 {
                let p = self.map(s, t);
                let (ru, rv) = (p[0] - u, p[1] - v);
                let h = 1e-7;
                let ps = self.map(s + h, t);
                let pt = self.map(s, t + h);
                let j = [
                    [(ps[0] - p[0]) / h, (pt[0] - p[0]) / h],
                    [(ps[1] - p[1]) / h, (pt[1] - p[1]) / h],
                ];
                let det = j[0][0] * j[1][1] - j[0][1] * j[1][0];
                if det.abs() < 1e-300 {
                    break;
                }
                let ds = (ru * j[1][1] - rv * j[0][1]) / det;
                let dt = (j[0][0] * rv - j[1][0] * ru) / det;
                s -= ds;
                t -= dt;
                if ds.abs() + dt.abs() < 1e-15 {
                    break;
                }
            }
            let p = self.map(s, t);
            let close = (p[0] - u).abs() + (p[1] - v).abs() < 1e-10;
            let inside = (-slack..=1.0 + slack).contains(&s) && (-slack..=1.0 + slack).contains(&t);
            if close && inside {
                return Some([s, t]);
            }
        }
        None
    }
}
