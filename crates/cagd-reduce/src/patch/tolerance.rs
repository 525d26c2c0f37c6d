//! Patch reduction to a tolerance: uniform subdivision until every piece reduces within
//! `δ` (certified), seed 000 §14.3 (Theorem 14.3.1 for triangles, SPEC-reduce §5).
//!
//! The subdivision is uniform (every piece at the same level), so neighbouring pieces share
//! whole edges, never T-junctions; with a boundary-consistent method (see the functions)
//! the reduced pieces meet C⁰ along every shared edge.

use cagd_core::{
    Error, Result, TensorPatch, TriPatch, check_tolerance, tensor_patch_distance,
    tri_patch_distance,
};

use crate::patch::report::{
    PatchConstraint, PatchOptions, TensorPiece, TriMethod, TriOptions, TriPiece,
};
use crate::{reduce_tensor, reduce_triangle};

/// The deepest subdivision level tried (`4^8 = 65536` pieces).
pub const MAX_SUBDIVISION_LEVEL: usize = 8;

/// A tensor sub-patch with its domain `(u0, u1, v0, v1)`.
type TensorCell = (TensorPatch, [f64; 4]);

/// Reduces `p` to degree `target` within `tol` (certified, Euclidean): levels
/// `L = 0, 1, ...`: the patch is split into `2^L x 2^L` sub-patches by repeated midpoint
/// bisection (in `u`, then `v`), each is reduced by [`reduce_tensor`] with `opts`; the first
/// level at which every certified bound is `<= tol` is returned (pieces in `u`-major order).
///
/// C⁰: neighbouring sub-patches share bitwise-identical boundary rows (de Casteljau copies
/// them), and the boundary curves of a reduced piece depend only on the corresponding
/// boundary curve of the piece for [`crate::TensorMethod::Curves`] with end-interpolating
/// methods and for [`crate::TensorMethod::Perturb`] with [`PatchConstraint::Boundary`]: for
/// these the reduced pieces coincide along shared edges (bitwise). The other variants give
/// pieces that are each within `tol` but may show gaps up to `2 tol`.
///
/// # Errors
/// [`Error::BadTolerance`] (`tol` not finite and `> 0`), the errors of [`reduce_tensor`],
/// [`Error::NoConvergence`] when level [`MAX_SUBDIVISION_LEVEL`] is not enough.
pub fn reduce_tensor_to_tolerance(
    p: &TensorPatch,
    target: (usize, usize),
    tol: f64,
    opts: &PatchOptions,
) -> Result<Vec<TensorPiece>> {
    check_tolerance(tol)?;
    // The levels are searched without measuring; only the accepted pieces are measured
    // (bounded work: every rejected level measured its pieces too).
    let search = PatchOptions {
        measure: false,
        ..*opts
    };
    let mut cells: Vec<TensorCell> = vec![(p.clone(), [0.0, 1.0, 0.0, 1.0])];
    let mut achieved = f64::INFINITY;
    for level in 0..=MAX_SUBDIVISION_LEVEL {
        if level > 0 {
            cells = split_tensor(&cells)?;
        }
        let mut pieces = Vec::with_capacity(cells.len());
        let mut worst = 0.0f64;
        for (patch, d) in &cells {
            let mut reduction = reduce_tensor(patch, target, &search)?;
            worst = worst.max(reduction.report.error_bound);
            if worst > tol {
                break;
            }
            if opts.measure {
                reduction.report.max_error = Some(tensor_patch_distance(patch, &reduction.patch)?);
            }
            pieces.push(TensorPiece {
                u: (d[0], d[1]),
                v: (d[2], d[3]),
                reduction,
            });
        }
        achieved = worst;
        if worst <= tol {
            return Ok(pieces);
        }
    }
    Err(Error::NoConvergence {
        tolerance: tol,
        achieved,
    })
}

/// Every cell split into four: at `u = 1/2`, then each half at `v = 1/2`.
fn split_tensor(cells: &[TensorCell]) -> Result<Vec<TensorCell>> {
    let mut out = Vec::with_capacity(cells.len() * 4);
    for (patch, [u0, u1, v0, v1]) in cells {
        let (um, vm) = ((u0 + u1) / 2.0, (v0 + v1) / 2.0);
        let (left, right) = patch.subdivide_u(0.5)?;
        for (half, (a, b)) in [(left, (*u0, um)), (right, (um, *u1))] {
            let (lo, hi) = half.subdivide_v(0.5)?;
            out.push((lo, [a, b, *v0, vm]));
            out.push((hi, [a, b, vm, *v1]));
        }
    }
    Ok(out)
}

/// Reduces the triangular patch `t` to degree `m` within `tol` (certified, Euclidean):
/// levels `L = 0, 1, ...` of the 4-way midpoint subdivision of seed 000 Theorem 14.3.1
/// ([`TriPatch::subdivide_midpoint`]; each level divides every `||F_k||` by `2^n`, so the
/// perturbation bound falls like `2^-nL`), `4^L` pieces each reduced by
/// [`reduce_triangle`]; the first level at which every certified bound is `<= tol` is
/// returned.
///
/// C⁰: with [`TriMethod::L2`] and [`PatchConstraint::Boundary`] the reduced boundary curves
/// depend only on the piece's boundary curves, so neighbouring pieces coincide along shared
/// edges up to rounding (measured `< 1e-15` relative). Midpoint sub-triangles traverse some
/// shared edges in opposite directions (the middle triangle's axes are reversed), so the
/// boundary method must be reversal-symmetric: `end_orders` with `r == p`.
///
/// # Errors
/// [`Error::BadTolerance`], the errors of [`reduce_triangle`], [`Error::ConditionNotMet`]
/// (a boundary method with `r != p`), [`Error::NoConvergence`].
pub fn reduce_triangle_to_tolerance(
    t: &TriPatch,
    m: usize,
    tol: f64,
    opts: &TriOptions,
) -> Result<Vec<TriPiece>> {
    check_tolerance(tol)?;
    if let TriMethod::L2(PatchConstraint::Boundary(method)) = opts.method {
        let (r, p) = method.end_orders(m);
        if r != p {
            return Err(Error::ConditionNotMet {
                eq: "14.3.1",
                why: "C0 across midpoint sub-triangles needs a reversal-symmetric boundary method (r == p)",
            });
        }
    }
    let search = TriOptions {
        measure: false,
        ..*opts
    };
    type Cell = (TriPatch, [(f64, f64); 3]);
    let mut cells: Vec<Cell> = vec![(t.clone(), [(1.0, 0.0), (0.0, 1.0), (0.0, 0.0)])];
    let mut achieved = f64::INFINITY;
    for level in 0..=MAX_SUBDIVISION_LEVEL {
        if level > 0 {
            cells = cells
                .iter()
                .flat_map(|(patch, v)| {
                    let kids = patch.subdivide_midpoint();
                    let maps = child_vertices(*v);
                    kids.into_iter().zip(maps)
                })
                .collect();
        }
        let mut pieces = Vec::with_capacity(cells.len());
        let mut worst = 0.0f64;
        for (patch, vertices) in &cells {
            let mut reduction = reduce_triangle(patch, m, &search)?;
            worst = worst.max(reduction.report.error_bound);
            if worst > tol {
                break;
            }
            if opts.measure {
                reduction.report.max_error = Some(tri_patch_distance(patch, &reduction.patch)?);
            }
            pieces.push(TriPiece {
                vertices: *vertices,
                reduction,
            });
        }
        achieved = worst;
        if worst <= tol {
            return Ok(pieces);
        }
    }
    Err(Error::NoConvergence {
        tolerance: tol,
        achieved,
    })
}

/// The parameter vertices `(A, B, C)` of the four children of a piece with vertices `v`, in
/// the order and orientation of [`TriPatch::subdivide_midpoint`].
fn child_vertices([a, b, c]: [(f64, f64); 3]) -> [[(f64, f64); 3]; 4] {
    // Parent local (u', v') -> parameter point C + u' (A - C) + v' (B - C).
    let at = |u: f64, v: f64| {
        (
            c.0 + u * (a.0 - c.0) + v * (b.0 - c.0),
            c.1 + u * (a.1 - c.1) + v * (b.1 - c.1),
        )
    };
    // Each child's local corners (1,0), (0,1), (0,0) in the parent's local coordinates.
    let corner = |u0: f64, v0: f64| [at(u0 + 0.5, v0), at(u0, v0 + 0.5), at(u0, v0)];
    [
        corner(0.0, 0.0),
        corner(0.5, 0.0),
        corner(0.0, 0.5),
        [at(0.0, 0.5), at(0.5, 0.0), at(0.5, 0.5)],
    ]
}
