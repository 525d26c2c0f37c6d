//! SPEC-convert §15.2: one biquadratic NURBS patch ↔ one rational biquadratic Bézier patch.
//! The closed form covers separable weights `w_ij = g_i h_j` (Bézier weights `G_i H_j`),
//! both ways; general weights go forward by the homogeneous 15.1 maps row by row and
//! column by column, and a 3x3 Bézier weight matrix must be rank 1 for the inverse.

use cagd_core::{Error, Result, check_points, check_weights};

use super::quadratic::{forward_map, inverse_map};
use super::span::local_gaps;

/// A biquadratic patch with separable weights: 9 points (flat, i-major, `i` along `u`),
/// the `u` weights (`g` or `G`) and the `v` weights (`h` or `H`); the weight of point
/// `(i, j)` is `u_weights[i] * v_weights[j]`.
#[derive(Debug, Clone, PartialEq)]
pub struct SeparablePatch {
    /// The 9 Euclidean points, i-major.
    pub points: Vec<f64>,
    /// The weights along `u` (`G_0..G_2` of a Bézier patch, `g_{m-2}..g_m` of a NURBS one).
    pub u_weights: [f64; 3],
    /// The weights along `v` (`H_0..H_2`, or `h_{n-2}..h_n`).
    pub v_weights: [f64; 3],
    /// Coordinates per point.
    pub dim: usize,
    /// The extrapolation factor of an inverse (the product of the two directions' 15.1
    /// factors: the largest coefficient of the affine map `r = Mu ⊗ Mv R`); 1 forward.
    pub extrapolation: f64,
}

fn three(v: &[f64], what: &'static str) -> Result<[f64; 3]> {
    check_weights(v, 3).map_err(|e| match e {
        Error::LengthMismatch { got, expected, .. } => Error::LengthMismatch {
            what,
            got,
            expected,
        },
        e => e,
    })?;
    Ok([v[0], v[1], v[2]])
}

fn gaps3(knots: &[f64]) -> Result<[f64; 3]> {
    let g = local_gaps(knots, 4, 1)?;
    Ok([g[0], g[1], g[2]])
}

fn check_net(points: &[f64], dim: usize) -> Result<()> {
    let n = check_points(points, dim)?;
    if n != 9 {
        return Err(Error::LengthMismatch {
            what: "points of a biquadratic patch (3 x 3)",
            got: n,
            expected: 9,
        });
    }
    Ok(())
}

/// The 15.1 weights and Euclidean ratios of one direction: `(W, [l1, l2])` with
/// `l1 = b w1/(b w1 + c w0)`, `l2 = d w1/(c w2 + d w1)` (15.1.7, 15.2.9–15.2.10).
fn forward_direction(gaps: [f64; 3], w: [f64; 3]) -> ([f64; 3], [[f64; 3]; 3]) {
    let mut big = [0.0; 3];
    forward_map(gaps, &w, 1, &mut big);
    let [b, c, d] = gaps;
    let l1 = b * w[1] / (b * w[1] + c * w[0]);
    let l2 = d * w[1] / (c * w[2] + d * w[1]);
    (
        big,
        [[1.0 - l1, l1, 0.0], [0.0, 1.0, 0.0], [0.0, l2, 1.0 - l2]],
    )
}

/// `out_ij = sum_{a,e} U[i][a] V[j][e] r_ae` on a 3x3 net of `dim`-point.
fn tensor_apply(u: &[[f64; 3]; 3], v: &[[f64; 3]; 3], r: &[f64], dim: usize) -> Vec<f64> {
    let mut out = vec![0.0; 9 * dim];
    for i in 0..3 {
        for j in 0..3 {
            for a in 0..3 {
                for e in 0..3 {
                    let f = u[i][a] * v[j][e];
                    if f != 0.0 {
                        for c in 0..dim {
                            out[(i * 3 + j) * dim + c] += f * r[(a * 3 + e) * dim + c];
                        }
                    }
                }
            }
        }
    }
    out
}

/// A biquadratic NURBS patch with separable weights `g_i h_j` → its rational biquadratic
/// Bézier patch (SPEC-convert §15.2, eq. 15.2.3–15.2.10): 15.1 applied to `g` with the `u`
/// gaps `(p, q, r)` gives `G, s1, s2`, to `h` with `(b, c, d)` gives `H, l1, l2`, and the
/// points are the tensor product `R = U ⊗ V r` (15.2.6). `u_knots`, `v_knots` are the four
/// local knots of each direction, `points` the 3x3 net (i-major, `i` along `u`).
///
/// # Errors
/// The knot errors of [`crate::quadratic_span_to_bezier`] per direction,
/// [`Error::NonPositiveWeight`], [`Error::LengthMismatch`], [`Error::NonFinite`].
///
/// ```
/// # use cagd_convert::biquadratic_separable_to_bezier;
/// let net: Vec<f64> = (0..9).flat_map(|k| [(k / 3) as f64, (k % 3) as f64, 0.0]).collect();
/// let b = biquadratic_separable_to_bezier(&[0.0, 1.0, 3.0, 4.0], &[0.0, 0.0, 2.0, 5.0],
///     &[1.0, 2.0, 1.0], &[0.5, 1.0, 3.0], &net, 3)?;
/// assert_eq!(b.v_weights, [0.5, 1.0, 1.8]);
/// # Ok::<(), cagd_core::Error>(())
/// ```
pub fn biquadratic_separable_to_bezier(
    u_knots: &[f64],
    v_knots: &[f64],
    g: &[f64],
    h: &[f64],
    points: &[f64],
    dim: usize,
) -> Result<SeparablePatch> {
    let (gu, gv) = (gaps3(u_knots)?, gaps3(v_knots)?);
    let (g, h) = (three(g, "g (3 weights)")?, three(h, "h (3 weights)")?);
    check_net(points, dim)?;
    let (big_g, um) = forward_direction(gu, g);
    let (big_h, vm) = forward_direction(gv, h);
    let out = tensor_apply(&um, &vm, points, dim);
    check_points(&out, dim)?;
    Ok(SeparablePatch {
        points: out,
        u_weights: big_g,
        v_weights: big_h,
        dim,
        extrapolation: 1.0,
    })
}

/// The inverse of [`biquadratic_separable_to_bezier`] (SPEC-convert §15.2, eq.
/// 15.2.11–15.2.17, with the erratum of 15.2.15 line 7): the conditions 15.2.11 (`u`) and
/// 15.2.12 (`v`) are those of 15.1.8 per direction, checked as "every inverse weight
/// `> 0`"; `g_{m-2} = ((p+q) G0 - p G1)/q`, ...; the points are `r = Mu ⊗ Mv R` with
/// `Mu = [[1+t1, -t1, 0], [0, 1, 0], [0, -t2, 1+t2]]`, `t1 = p G1/(q g_{m-2})`,
/// `t2 = r G1/(q g_m)` (15.2.16), and `Mv` likewise with `k1, k2` (15.2.17).
///
/// # Errors
/// [`Error::ConversionCondition`] ("15.2.11" for `g`, "15.2.12" for `h`, with the index
/// and value of the non-positive weight); the input errors of the forward map.
pub fn bezier_to_biquadratic_separable(
    u_knots: &[f64],
    v_knots: &[f64],
    big_g: &[f64],
    big_h: &[f64],
    points: &[f64],
    dim: usize,
) -> Result<SeparablePatch> {
    let (gu, gv) = (gaps3(u_knots)?, gaps3(v_knots)?);
    let (big_g, big_h) = (
        three(big_g, "G (3 weights)")?,
        three(big_h, "H (3 weights)")?,
    );
    check_net(points, dim)?;
    let (g, mu) = inverse_direction(
        gu,
        big_g,
        "15.2.11",
        "inverse u weight g_{m-2+index} must be > 0",
    )?;
    let (h, mv) = inverse_direction(
        gv,
        big_h,
        "15.2.12",
        "inverse v weight h_{n-2+index} must be > 0",
    )?;
    let out = tensor_apply(&mu, &mv, points, dim);
    check_points(&out, dim)?;
    let row_max = |m: &[[f64; 3]; 3]| m.iter().flatten().fold(0.0f64, |a, x| a.max(x.abs()));
    Ok(SeparablePatch {
        points: out,
        u_weights: g,
        v_weights: h,
        dim,
        extrapolation: row_max(&mu) * row_max(&mv),
    })
}

/// The 15.1 inverse of one direction: the NURBS weights and the Euclidean matrix
/// `[[1+t1, -t1, 0], [0, 1, 0], [0, -t2, 1+t2]]`.
fn inverse_direction(
    gaps: [f64; 3],
    big: [f64; 3],
    condition: &'static str,
    what: &'static str,
) -> Result<([f64; 3], [[f64; 3]; 3])> {
    let mut w = [0.0; 3];
    inverse_map(gaps, &big, 1, &mut w);
    if let Some(index) = w
        .iter()
        .position(|x| !(x.is_finite() && *x >= f64::MIN_POSITIVE))
    {
        return Err(Error::ConversionCondition {
            condition,
            what,
            index,
            value: w[index],
        });
    }
    let [b, c, d] = gaps;
    let t1 = b * big[1] / (c * w[0]);
    let t2 = d * big[1] / (c * w[2]);
    Ok((
        w,
        [[1.0 + t1, -t1, 0.0], [0.0, 1.0, 0.0], [0.0, -t2, 1.0 + t2]],
    ))
}

/// Factors a 3x3 weight matrix (i-major) as `w_ij = g_i h_j` (rank 1), as SPEC-convert
/// §15.2 requires before its closed form applies: `g_i = w_ib`, `h_j = w_aj / w_ab` about the
/// largest entry `w_ab`, and every entry must equal `g_i h_j` within `1e-12` relative.
///
/// # Errors
/// [`Error::ConversionCondition`] (condition "15.2 separable weights", the i-major index
/// of the entry farthest from rank 1 and its relative deviation);
/// [`Error::NonPositiveWeight`], [`Error::LengthMismatch`] (not 9 weights).
pub fn separable_factors(weights: &[f64]) -> Result<([f64; 3], [f64; 3])> {
    check_weights(weights, 9)?;
    let (mut a, mut b) = (0, 0);
    for k in 0..9 {
        if weights[k] > weights[a * 3 + b] {
            (a, b) = (k / 3, k % 3);
        }
    }
    let wab = weights[a * 3 + b];
    let g = [weights[b], weights[3 + b], weights[6 + b]];
    let h = [
        weights[a * 3] / wab,
        weights[a * 3 + 1] / wab,
        weights[a * 3 + 2] / wab,
    ];
    let (mut worst, mut at) = (0.0f64, 0);
    for i in 0..3 {
        for j in 0..3 {
            let w = weights[i * 3 + j];
            let dev = (w - g[i] * h[j]).abs() / w;
            if dev > worst {
                (worst, at) = (dev, i * 3 + j);
            }
        }
    }
    if worst > 1e-12 {
        return Err(Error::ConversionCondition {
            condition: "15.2 separable weights",
            what: "relative deviation of weight[index] from rank 1 (w_ij = g_i h_j)",
            index: at,
            value: worst,
        });
    }
    Ok((g, h))
}

/// A biquadratic NURBS patch with any positive weights (9, i-major) → its rational
/// biquadratic Bézier patch: the homogeneous net `(w r, w)` is mapped row by row (`v`) and
/// column by column (`u`) with the 15.1 homogeneous maps (SPEC-convert §15.2, "General
/// (non-separable) NURBS weights"). Returns the 9 Bézier points and their 9 weights.
///
/// # Errors
/// As [`biquadratic_separable_to_bezier`].
pub fn biquadratic_to_bezier(
    u_knots: &[f64],
    v_knots: &[f64],
    points: &[f64],
    weights: &[f64],
    dim: usize,
) -> Result<(Vec<f64>, Vec<f64>)> {
    let (gu, gv) = (gaps3(u_knots)?, gaps3(v_knots)?);
    check_net(points, dim)?;
    check_weights(weights, 9)?;
    let pdim = dim + 1;
    let mut hom = vec![0.0; 9 * pdim];
    cagd_core::kernel::to_homogeneous(points, weights, dim, &mut hom);
    let mut rows = vec![0.0; 9 * pdim];
    for i in 0..3 {
        forward_map(
            gv,
            &hom[i * 3 * pdim..(i + 1) * 3 * pdim],
            pdim,
            &mut rows[i * 3 * pdim..(i + 1) * 3 * pdim],
        );
    }
    // Columns: gather j-th column (3 points), map along u, scatter.
    let mut col = vec![0.0; 3 * pdim];
    let mut mapped = vec![0.0; 3 * pdim];
    let mut out = vec![0.0; 9 * pdim];
    for j in 0..3 {
        for i in 0..3 {
            col[i * pdim..(i + 1) * pdim]
                .copy_from_slice(&rows[(i * 3 + j) * pdim..(i * 3 + j + 1) * pdim]);
        }
        forward_map(gu, &col, pdim, &mut mapped);
        for i in 0..3 {
            out[(i * 3 + j) * pdim..(i * 3 + j + 1) * pdim]
                .copy_from_slice(&mapped[i * pdim..(i + 1) * pdim]);
        }
    }
    let mut pts = vec![0.0; 9 * dim];
    let mut w = vec![0.0; 9];
    cagd_core::kernel::from_homogeneous(&out, dim, &mut pts, &mut w);
    check_points(&pts, dim)?;
    Ok((pts, w))
}

/// A rational biquadratic Bézier patch with a 3x3 weight matrix → the NURBS span: the
/// weights must be rank 1 ([`separable_factors`]), then [`bezier_to_biquadratic_separable`].
/// (SPEC-convert §15.2, conditions 15.2.11–12, inverse 15.2.13–17.)
///
/// # Errors
/// [`Error::ConversionCondition`] for weights that are not rank 1 or an inverse weight
/// `<= 0`; the input errors of [`bezier_to_biquadratic_separable`].
pub fn bezier_to_biquadratic(
    u_knots: &[f64],
    v_knots: &[f64],
    points: &[f64],
    weights: &[f64],
    dim: usize,
) -> Result<SeparablePatch> {
    let (g, h) = separable_factors(weights)?;
    bezier_to_biquadratic_separable(u_knots, v_knots, &g, &h, points, dim)
}
