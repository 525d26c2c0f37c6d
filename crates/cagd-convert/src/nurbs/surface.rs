//! The general route for tensor-product B-spline / NURBS surfaces, both ways: extraction
//! in `u` on whole rows of the homogeneous net and then in `v` (the curve kernel with a
//! "point" that is a row), and the merge in `u` on whole rows of the pieces and then in
//! `v`, where a knot copy is removed only when it can be removed from every row at once.

use cagd_core::{
    BSplineSurface, Error, Result, SurfacePatchPiece, TensorPatch, check_tolerance, kernel,
};

use super::extract_kernel::extract;
use super::merge::{DEFAULT_REL_TOL, max_abs};
use super::merge_kernel::merge;
use super::pieces::check_breaks;

/// The homogeneous (or, when polynomial, plain) working net of a surface and its `pdim`.
fn working_net(s: &BSplineSurface) -> (Vec<f64>, usize) {
    let dim = s.dim();
    match s.weights() {
        None => (s.points().to_vec(), dim),
        Some(w) => {
            let mut hom = vec![0.0; w.len() * (dim + 1)];
            kernel::to_homogeneous(s.points(), w, dim, &mut hom);
            (hom, dim + 1)
        }
    }
}

/// A Bézier patch of working points (i-major) as a [`SurfacePatchPiece`].
fn piece_of(
    net: Vec<f64>,
    degrees: (usize, usize),
    dim: usize,
    rational: bool,
    u: (f64, f64),
    v: (f64, f64),
) -> Result<SurfacePatchPiece> {
    let (p, q) = degrees;
    let (patch, weights) = if rational {
        let n = (p + 1) * (q + 1);
        let (mut pts, mut w) = (vec![0.0; n * dim], vec![0.0; n]);
        kernel::from_homogeneous(&net, dim, &mut pts, &mut w);
        cagd_core::check_weights(&w, n)?;
        (TensorPatch::new(pts, p, q, dim)?, Some(w))
    } else {
        (TensorPatch::new(net, p, q, dim)?, None)
    };
    Ok(SurfacePatchPiece {
        u,
        v,
        patch,
        weights,
    })
}

/// Every non-empty span rectangle of a B-spline / NURBS surface as a (rational) Bézier
/// patch, `u` spans outer and `v` spans inner (the order of
/// [`BSplineSurface::to_beziers`]), by Böhm insertion in homogeneous space (SPEC-convert
/// §15.2 "General (non-separable) NURBS weights", any degrees).
///
/// # Errors
/// [`Error::NonFinite`] / [`Error::NonPositiveWeight`] only after an overflow.
pub fn surface_to_bezier_patches(surface: &BSplineSurface) -> Result<Vec<SurfacePatchPiece>> {
    let ((p, q), (nu, nv), dim) = (surface.degrees(), surface.counts(), surface.dim());
    let (net, pdim) = working_net(surface);
    let rational = surface.is_rational();
    let row = nv * pdim;
    let mut out = Vec::new();
    let mut failure = None;
    let mut strips: Vec<Vec<(f64, f64, Vec<f64>)>> = Vec::with_capacity(p + 1);
    extract(
        surface.knots_u(),
        p,
        nu,
        row,
        |i, o| o.copy_from_slice(&net[i * row..(i + 1) * row]),
        |ua, ub, win| {
            strips.clear();
            for i in 0..=p {
                let r = &win[i * row..(i + 1) * row];
                let mut pieces = Vec::new();
                extract(
                    surface.knots_v(),
                    q,
                    nv,
                    pdim,
                    |j, o| o.copy_from_slice(&r[j * pdim..(j + 1) * pdim]),
                    |va, vb, w| pieces.push((va, vb, w.to_vec())),
                );
                strips.push(pieces);
            }
            for jv in 0..strips[0].len() {
                let mut patch = Vec::with_capacity((p + 1) * (q + 1) * pdim);
                for strip in &strips {
                    patch.extend_from_slice(&strip[jv].2);
                }
                let (va, vb) = (strips[0][jv].0, strips[0][jv].1);
                match piece_of(patch, (p, q), dim, rational, (ua, ub), (va, vb)) {
                    Ok(pc) => out.push(pc),
                    Err(e) => {
                        if failure.is_none() {
                            failure = Some(e);
                        }
                    }
                }
            }
        },
    );
    match failure {
        Some(e) => Err(e),
        None => Ok(out),
    }
}

/// One surface made from Bézier patches, with the continuity found across each knot line.
#[derive(Debug, Clone, PartialEq)]
pub struct SurfaceFromPatches {
    /// The surface (clamped knots; rational iff any patch is).
    pub surface: BSplineSurface,
    /// Continuity across each interior `u` break (`-1`: the patches do not meet).
    pub continuity_u: Vec<i64>,
    /// Continuity across each interior `v` break.
    pub continuity_v: Vec<i64>,
    /// Certified bound of every change made, working coordinates.
    pub bound: f64,
    /// The tolerance of each joint (working coordinates).
    pub tolerance: f64,
}

/// The reverse of [`surface_to_bezier_patches`]: patches on a full grid (`u` outer, `v`
/// inner, as returned by it; each with its `u` and `v` interval) → one B-spline / NURBS
/// surface with the highest continuity across each knot line that every row (column) of
/// patches has, by the curve merge of [`crate::pieces_to_nurbs`] on bundles of rows.
/// (Seed 001 §4.1 merge per direction; SPEC-convert §15.2 generalised.)
///
/// # Errors
/// [`Error::NotEnoughPoints`] (no patch); [`Error::LengthMismatch`] (differing degrees or
/// dimensions, or patches that are not a full grid); [`Error::BadParameter`] (`"breaks"`
/// not increasing, or a patch whose interval does not match its place in the grid);
/// [`Error::BadTolerance`].
pub fn patches_to_nurbs(
    patches: &[SurfacePatchPiece],
    tol: Option<f64>,
) -> Result<SurfaceFromPatches> {
    let first = patches
        .first()
        .ok_or(Error::NotEnoughPoints { got: 0, need: 1 })?;
    let ((p, q), dim) = (first.patch.degrees(), first.patch.dim());
    let nv = patches.iter().take_while(|pc| pc.u == first.u).count();
    if patches.len() % nv != 0 {
        return Err(Error::LengthMismatch {
            what: "patches (a full grid, u outer, v inner)",
            got: patches.len(),
            expected: (patches.len() / nv + 1) * nv,
        });
    }
    let nu = patches.len() / nv;
    let mut bu: Vec<f64> = (0..nu).map(|i| patches[i * nv].u.0).collect();
    bu.push(patches[(nu - 1) * nv].u.1);
    let mut bv: Vec<f64> = (0..nv).map(|j| patches[j].v.0).collect();
    bv.push(patches[nv - 1].v.1);
    check_breaks(&bu)?;
    check_breaks(&bv)?;
    for (k, pc) in patches.iter().enumerate() {
        let (i, j) = (k / nv, k % nv);
        if pc.patch.degrees() != (p, q) || pc.patch.dim() != dim {
            return Err(Error::LengthMismatch {
                what: "patch degrees and dimensions",
                got: k,
                expected: 0,
            });
        }
        if pc.u != (bu[i], bu[i + 1]) || pc.v != (bv[j], bv[j + 1]) {
            return Err(Error::BadParameter {
                name: "patch interval",
                value: k as f64,
                why: "patch k must cover [bu[k / nv], bu[k / nv + 1]] x [bv[k % nv], bv[k % nv + 1]]",
            });
        }
        if let Some(w) = &pc.weights {
            cagd_core::check_weights(w, (p + 1) * (q + 1))?;
        }
    }
    let rational = patches.iter().any(|pc| pc.weights.is_some());
    let pdim = if rational { dim + 1 } else { dim };
    // Working points of every patch, i-major, patch after patch.
    let m = (p + 1) * (q + 1);
    let mut work = vec![0.0; patches.len() * m * pdim];
    for (k, pc) in patches.iter().enumerate() {
        let dst = &mut work[k * m * pdim..(k + 1) * m * pdim];
        match (rational, &pc.weights) {
            (false, _) => dst.copy_from_slice(pc.patch.points()),
            (true, Some(w)) => kernel::to_homogeneous(pc.patch.points(), w, dim, dst),
            (true, None) => kernel::to_homogeneous(pc.patch.points(), &vec![1.0; m], dim, dst),
        }
    }
    let tol = match tol {
        Some(t) => {
            check_tolerance(t)?;
            t
        }
        None => (DEFAULT_REL_TOL * max_abs(&work)).max(f64::MIN_POSITIVE),
    };
    // Merge in u: point i of piece iu is the row i of every patch (iu, jv), jv = 0..nv.
    let row_u = nv * (q + 1) * pdim;
    let mu = merge(&bu, p, row_u, tol, None, |iu, i, o| {
        for jv in 0..nv {
            let at = ((iu * nv + jv) * m + i * (q + 1)) * pdim;
            o[jv * (q + 1) * pdim..(jv + 1) * (q + 1) * pdim]
                .copy_from_slice(&work[at..at + (q + 1) * pdim]);
        }
    });
    let n_u = mu.work.len() / row_u;
    // Merge in v: point j of piece jv is the column (a = 0..n_u) of merged rows.
    let col = n_u * pdim;
    let mv = merge(&bv, q, col, tol, None, |jv, j, o| {
        for a in 0..n_u {
            let at = a * row_u + (jv * (q + 1) + j) * pdim;
            o[a * pdim..(a + 1) * pdim].copy_from_slice(&mu.work[at..at + pdim]);
        }
    });
    let n_v = mv.work.len() / col;
    let mut net = vec![0.0; n_u * n_v * pdim];
    for a in 0..n_u {
        for b in 0..n_v {
            net[(a * n_v + b) * pdim..(a * n_v + b + 1) * pdim]
                .copy_from_slice(&mv.work[b * col + a * pdim..b * col + (a + 1) * pdim]);
        }
    }
    let surface = if rational {
        let n = n_u * n_v;
        let (mut pts, mut w) = (vec![0.0; n * dim], vec![0.0; n]);
        kernel::from_homogeneous(&net, dim, &mut pts, &mut w);
        BSplineSurface::new_rational((p, q), mu.knots, mv.knots, pts, w, (n_u, n_v), dim)?
    } else {
        BSplineSurface::new((p, q), mu.knots, mv.knots, net, (n_u, n_v), dim)?
    };
    let cont = |deg: usize, mults: &[usize]| -> Vec<i64> {
        mults
            .iter()
            .map(|&s| i64::try_from(deg).unwrap_or(i64::MAX) - i64::try_from(s).unwrap_or(0))
            .collect()
    };
    Ok(SurfaceFromPatches {
        surface,
        continuity_u: cont(p, &mu.mults),
        continuity_v: cont(q, &mv.mults),
        bound: mu.bound + mv.bound,
        tolerance: tol,
    })
}
