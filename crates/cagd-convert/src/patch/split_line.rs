//! Generalized subdivision of an `m x n` rectangular patch along the line `u = f1 v + f0`
//! (SPEC-convert §15.6.1 two trapezoids, §15.6.2 corner triangle + pentagon; the errata
//! `k + l = j` and `i = 0..m` applied).

use cagd_core::{Error, Result, TensorPatch};

use super::blossom::{elevate_to, left_part, pascal};
use super::surface::check_range;
use super::{PatchPiece, PatchSurface, PieceDomain, TensorSurface};

/// `H_i` of eq. 15.6.3 / 15.6.7 from the `Q^{(i)}_{kl}` table given by `q(i, k, l)`
/// (`dim` doubles), elevated to degree `m + n` (eq. 15.6.2): the net of the `m x (m + n)`
/// result.
fn assemble<'a>(
    m: usize,
    n: usize,
    dim: usize,
    q: impl Fn(usize, usize, usize) -> &'a [f64],
) -> Vec<f64> {
    let binom = pascal(m + n);
    let mut pts = Vec::with_capacity((m + 1) * (m + n + 1) * dim);
    for i in 0..=m {
        let mut h = vec![0.0; (n + i + 1) * dim];
        for k in 0..=i {
            for l in 0..=n {
                let j = k + l;
                let c = binom[i][k] * binom[n][l] / binom[n + i][j];
                let v = q(i, k, l);
                for x in 0..dim {
                    h[j * dim + x] += c * v[x];
                }
            }
        }
        pts.extend(elevate_to(&h, dim, m + n));
    }
    pts
}

/// Column `l` of a homogeneous net (a degree-`m` curve in `u`).
fn column(h: &TensorPatch, l: usize) -> Vec<f64> {
    let (m, _) = h.degrees();
    (0..=m).flat_map(|i| h.point(i, l).to_vec()).collect()
}

/// Net of the left trapezoid (15.6.1) of the homogeneous net `h`.
///
/// `Q^{(i)}_{kl}` is the `u`-blossom of column `l` at `(a^(i-k), b^k, 0^(m-i))` (15.6.4):
/// level `p` of the de Casteljau pyramid of the column at `a` is the net `b(a^p, ·)`, and
/// point `k` of its left part at `b` is `b(a^p, 0^(m-p-k), b^k)`; `table[l][p]` holds them.
fn trapezoid_net(h: &TensorPatch, a: f64, b: f64) -> TensorPatch {
    let ((m, n), dim) = (h.degrees(), h.dim());
    let table: Vec<Vec<Vec<f64>>> = (0..=n)
        .map(|l| {
            let mut level = column(h, l);
            let mut rows = Vec::with_capacity(m + 1);
            for p in 0..=m {
                if p > 0 {
                    let d = m - p + 1; // points of the level after this step
                    for i in 0..d {
                        for x in 0..dim {
                            level[i * dim + x] =
                                (1.0 - a) * level[i * dim + x] + a * level[(i + 1) * dim + x];
                        }
                    }
                    level.truncate(d * dim);
                }
                rows.push(left_part(&level, dim, b));
            }
            rows
        })
        .collect();
    let pts = assemble(m, n, dim, |i, k, l| {
        &table[l][i - k][k * dim..(k + 1) * dim]
    });
    TensorPatch::new(pts, m, m + n, dim).unwrap_or_else(|_| h.clone())
}

/// Net of the corner triangle (15.6.2) of the homogeneous net `h`.
///
/// `Q^{(i)}_{kl}` has `u`-arguments `(a^(i-k), 0^(m-i+k))` and `v`-arguments
/// `(b^l, 0^(n-l))` (15.6.8): the blossoms `b(0^(m-p), a^p)` and `b(0^(n-l), b^l)` are the
/// points of the left parts of the columns at `u = a` and of the rows at `v = b`, i.e. the
/// net of the sub-patch `[0, a] x [0, b]`.
fn corner_net(h: &TensorPatch, a: f64, b: f64) -> TensorPatch {
    let ((m, n), dim) = (h.degrees(), h.dim());
    let cols: Vec<Vec<f64>> = (0..=n).map(|l| left_part(&column(h, l), dim, a)).collect();
    let table: Vec<Vec<f64>> = (0..=m)
        .map(|p| {
            let row: Vec<f64> = cols
                .iter()
                .flat_map(|c| c[p * dim..(p + 1) * dim].to_vec())
                .collect();
            left_part(&row, dim, b)
        })
        .collect();
    let pts = assemble(m, n, dim, |i, k, l| &table[i - k][l * dim..(l + 1) * dim]);
    TensorPatch::new(pts, m, m + n, dim).unwrap_or_else(|_| h.clone())
}

/// Wraps a homogeneous net as a piece.
fn piece(net: TensorPatch, rational: bool, domain: PieceDomain) -> Result<PatchPiece> {
    Ok(PatchPiece {
        surface: PatchSurface::Tensor(TensorSurface::from_homogeneous(net, rational)?),
        domain,
    })
}

/// The left trapezoid `D1 = {0 <= u <= a + (b - a) v}` of an `m x n` patch as an
/// `m x (m + n)` patch with the map (15.6.1) `u = s[a(1-t) + b t]`, `v = t` (SPEC-convert
/// §15.6.1, eqs. 15.6.2–15.6.4; the line `u = f1 v + f0` has `a = f0`, `b = f0 + f1`).
/// Domain: bilinear `[(0,0), (a,0), (0,1), (b,1)]`.
///
/// # Errors
/// [`Error::BadParameter`] unless `0 <= a, b <= 1`.
pub fn trapezoid(p: &TensorSurface, a: f64, b: f64) -> Result<PatchPiece> {
    let why = "the line must meet v = 0 and v = 1 inside [0, 1]";
    check_range("a", a, 0.0, 1.0, why)?;
    check_range("b", b, 0.0, 1.0, why)?;
    let net = trapezoid_net(&p.homogeneous(), a, b);
    piece(
        net,
        p.weights().is_some(),
        PieceDomain::Bilinear([[0.0, 0.0], [a, 0.0], [0.0, 1.0], [b, 1.0]]),
    )
}

/// The corner triangle `D3` with vertices `(0,0)`, `(a,0)`, `(0,b)` of an `m x n` patch as a
/// degenerate `m x (m + n)` patch with the map (15.6.5) `u = a s (1-t)`, `v = b t`
/// (SPEC-convert §15.6.2, eqs. 15.6.6–15.6.8; `a = f0`, `b = -f0 / f1`).
/// Domain: bilinear `[(0,0), (a,0), (0,b), (0,b)]`.
///
/// # Errors
/// [`Error::BadParameter`] unless `0 < a, b <= 1`.
pub fn corner_triangle(p: &TensorSurface, a: f64, b: f64) -> Result<PatchPiece> {
    let why = "the corner triangle needs 0 < a, b <= 1";
    for (name, x) in [("a", a), ("b", b)] {
        check_range(name, x, 0.0, 1.0, why)?;
        if x <= 0.0 {
            return Err(Error::BadParameter {
                name,
                value: x,
                why,
            });
        }
    }
    let net = corner_net(&p.homogeneous(), a, b);
    piece(
        net,
        p.weights().is_some(),
        PieceDomain::Bilinear([[0.0, 0.0], [a, 0.0], [0.0, b], [0.0, b]]),
    )
}

/// A symmetry of the unit square: the canonical net is `Pc(u', v') = P(σ⁻¹(u', v'))`.
#[derive(Clone, Copy)]
struct Sym {
    mirror_u: bool,
    mirror_v: bool,
    transpose: bool,
}

impl Sym {
    /// `σ⁻¹`: canonical point → original point.
    fn back(self, p: [f64; 2]) -> [f64; 2] {
        let [mut x, mut y] = if self.transpose { [p[1], p[0]] } else { p };
        if self.mirror_u {
            x = 1.0 - x;
        }
        if self.mirror_v {
            y = 1.0 - y;
        }
        [x, y]
    }

    /// The canonical net of `h`.
    fn net(self, h: &TensorPatch) -> TensorPatch {
        let ((m, n), dim) = (h.degrees(), h.dim());
        let mut pts = Vec::with_capacity(h.points().len());
        for i in 0..=m {
            for j in 0..=n {
                let ii = if self.mirror_u { m - i } else { i };
                let jj = if self.mirror_v { n - j } else { j };
                pts.extend_from_slice(h.point(ii, jj));
            }
        }
        let net = TensorPatch::new(pts, m, n, dim).unwrap_or_else(|_| h.clone());
        if self.transpose {
            super::ruled::transpose(&net)
        } else {
            net
        }
    }

    /// A canonical bilinear domain mapped back.
    fn domain(self, x: [[f64; 2]; 4]) -> PieceDomain {
        PieceDomain::Bilinear(x.map(|c| self.back(c)))
    }
}

const ID: Sym = Sym {
    mirror_u: false,
    mirror_v: false,
    transpose: false,
};

/// Left and right trapezoids of the canonical net `hc` for the line through `(a, 0)`,
/// `(b, 1)`; the right one is D1 of the `u`-mirrored net with `1 - a`, `1 - b` (§15.6.1).
fn two_trapezoids(
    hc: &TensorPatch,
    a: f64,
    b: f64,
    sym: Sym,
    rational: bool,
) -> Result<Vec<PatchPiece>> {
    let mirrored = Sym {
        mirror_u: true,
        ..ID
    }
    .net(hc);
    Ok(vec![
        piece(
            trapezoid_net(hc, a, b),
            rational,
            sym.domain([[0.0, 0.0], [a, 0.0], [0.0, 1.0], [b, 1.0]]),
        )?,
        piece(
            trapezoid_net(&mirrored, 1.0 - a, 1.0 - b),
            rational,
            sym.domain([[1.0, 0.0], [a, 0.0], [1.0, 1.0], [b, 1.0]]),
        )?,
    ])
}

/// Corner triangle at the canonical origin (vertices `(0,0)`, `(a,0)`, `(0,b)`) and the
/// pentagon as the spec decomposes it (§15.6.2): the strip `v in [b, 1]` (a plain
/// subpatch, omitted when `b = 1`) and the part `v in [0, b]`, `u >= a(1 - v/b)`, which is
/// the trapezoid `a' = 1 - a`, `b' = 1` of the net restricted to `v in [0, b]` and
/// mirrored in `u`.
fn corner_and_pentagon(
    hc: &TensorPatch,
    a: f64,
    b: f64,
    sym: Sym,
    rational: bool,
) -> Result<Vec<PatchPiece>> {
    let mut out = vec![piece(
        corner_net(hc, a, b),
        rational,
        sym.domain([[0.0, 0.0], [a, 0.0], [0.0, b], [0.0, b]]),
    )?];
    let (lower, upper) = if b < 1.0 {
        hc.subdivide_v(b)?
    } else {
        (hc.clone(), hc.clone())
    };
    let mirrored = Sym {
        mirror_u: true,
        ..ID
    }
    .net(&lower);
    out.push(piece(
        trapezoid_net(&mirrored, 1.0 - a, 1.0),
        rational,
        sym.domain([[1.0, 0.0], [a, 0.0], [1.0, b], [0.0, b]]),
    )?);
    if b < 1.0 {
        out.push(piece(
            upper,
            rational,
            sym.domain([[0.0, b], [1.0, b], [0.0, 1.0], [1.0, 1.0]]),
        )?);
    }
    Ok(out)
}

/// Splits an `m x n` patch along the line `u = f1 v + f0` into pieces that tile the unit
/// square exactly, each with its bilinear domain. The line meets `v = 0` at `u = a = f0`
/// and `v = 1` at `u = b = f0 + f1`:
/// - both in `[0, 1]`: the two trapezoids of §15.6.1 (left `u <= line`, then right), each
///   `m x (m + n)`;
/// - the line cuts off a corner of the square: the corner triangle of §15.6.2 and the
///   pentagon as the spec decomposes it (a trapezoid and, unless the cut reaches the
///   opposite corner, a strip), the corner brought to the origin by a mirror;
/// - the line crosses `u = 0` and `u = 1`: the two trapezoids of the transposed patch
///   (`n x (n + m)`, below the line first).
///
/// # Errors
/// [`Error::BadParameter`] when `f1` or `f0` is not finite or the line does not cut the
/// open square into two parts.
///
/// ```
/// use cagd_convert::{TensorSurface, split_along_line};
/// // A bilinear patch cut by u = 0.5 v + 0.25 into two trapezoids.
/// let p = TensorSurface::new(vec![0.0, 1.0, 2.0, 4.0], 1, 1, 1, None)?;
/// let pieces = split_along_line(&p, 0.5, 0.25)?;
/// assert_eq!(pieces.len(), 2);
/// for piece in &pieces {
///     let [u, v] = piece.domain.map(0.3, 0.7);
///     assert!((piece.surface.eval(0.3, 0.7)[0] - p.eval(u, v)[0]).abs() < 1e-14);
/// }
/// # Ok::<(), cagd_core::Error>(())
/// ```
pub fn split_along_line(p: &TensorSurface, f1: f64, f0: f64) -> Result<Vec<PatchPiece>> {
    let (a, b) = (f0, f0 + f1);
    for (name, x) in [("f1", f1), ("f0", f0)] {
        if !x.is_finite() {
            return Err(Error::BadParameter {
                name,
                value: x,
                why: "must be finite",
            });
        }
    }
    let misses = || Error::BadParameter {
        name: "f0",
        value: f0,
        why: "the line u = f1 v + f0 must cut the open unit square into two parts",
    };
    let h = p.homogeneous();
    let rational = p.weights().is_some();
    let unit = |x: f64| (0.0..=1.0).contains(&x);
    if unit(a) && unit(b) {
        if (a == 0.0 && b == 0.0) || (a == 1.0 && b == 1.0) {
            return Err(misses());
        }
        return two_trapezoids(&h, a, b, ID, rational);
    }
    if f1 == 0.0 {
        return Err(misses());
    }
    let (at_u0, at_u1) = (-f0 / f1, (1.0 - f0) / f1); // v where the line meets u = 0 / u = 1
    let (sym, ac, bc) = if unit(a) && b < 0.0 {
        (ID, a, at_u0)
    } else if unit(a) && b > 1.0 {
        (
            Sym {
                mirror_u: true,
                ..ID
            },
            1.0 - a,
            at_u1,
        )
    } else if unit(b) && a < 0.0 {
        (
            Sym {
                mirror_v: true,
                ..ID
            },
            b,
            1.0 - at_u0,
        )
    } else if unit(b) && a > 1.0 {
        (
            Sym {
                mirror_u: true,
                mirror_v: true,
                transpose: false,
            },
            1.0 - b,
            1.0 - at_u1,
        )
    } else if (a < 0.0 && b > 1.0) || (a > 1.0 && b < 0.0) {
        let sym = Sym {
            transpose: true,
            ..ID
        };
        return two_trapezoids(&sym.net(&h), at_u0, at_u1, sym, rational);
    } else {
        return Err(misses());
    };
    if !(ac > 0.0 && bc > 0.0 && ac <= 1.0 && bc <= 1.0) {
        return Err(misses());
    }
    corner_and_pentagon(&sym.net(&h), ac, bc, sym, rational)
}
