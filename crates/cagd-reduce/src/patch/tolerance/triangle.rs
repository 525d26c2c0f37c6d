//! Triangular patches reduced to a tolerance by 4-way midpoint subdivision (seed 000
//! Theorem 14.3.1, SPEC-reduce §5).

use cagd_core::{Error, Result, TriPatch, check_tolerance};

use super::measure::measure_tri_pieces;
use super::{MAX_PATCH_TOLERANCE_WORK, MAX_SUBDIVISION_LEVEL, tri_piece_cost};
use crate::patch::report::{PatchConstraint, TriMethod, TriOptions, TriPiece};
use crate::reduce_triangle;

/// Reduces the triangular patch `t` to degree `m` within `tol` (certified, Euclidean):
/// levels `L = 0, 1, ...` of the 4-way midpoint subdivision of seed 000 Theorem 14.3.1
/// ([`TriPatch::subdivide_midpoint`]; each level divides every `||F_k||` by `2^n`, so the
/// perturbation bound falls like `2^-nL`), `4^L` pieces each reduced by
/// [`reduce_triangle`]; the first level at which every certified bound is `<= tol` is
/// returned. With `opts.measure` the pieces' `max_error` is measured within a node budget
/// (see [`super::PIECES_MEASURE_NODE_BUDGET`]).
///
/// C⁰: with [`TriMethod::L2`] and [`PatchConstraint::Boundary`] the reduced boundary curves
/// depend only on the piece's boundary curves, so neighbouring pieces coincide along shared
/// edges up to rounding (measured `< 1e-15` relative). Midpoint sub-triangles traverse some
/// shared edges in opposite directions (the middle triangle's axes are reversed), so the
/// boundary method must be reversal-symmetric: `end_orders` with `r == p`.
///
/// # Errors
/// [`Error::BadTolerance`], the errors of [`reduce_triangle`], [`Error::ConditionNotMet`]
/// (a boundary method with `r != p`), [`Error::NoConvergence`] (with the bound reached) when
/// level [`MAX_SUBDIVISION_LEVEL`] is not enough or the next level would pass
/// [`super::MAX_PATCH_TOLERANCE_WORK`].
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
    let unit = tri_piece_cost(t.degree(), t.dim());
    let mut work = 0usize;
    for level in 0..=MAX_SUBDIVISION_LEVEL {
        // Level 0 is one reduction; a later level splits every cell in four.
        let count = if level == 0 {
            1
        } else {
            cells.len().saturating_mul(4)
        };
        work = work.saturating_add(count.saturating_mul(unit));
        if level > 0 && work > MAX_PATCH_TOLERANCE_WORK {
            break;
        }
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
            let reduction = reduce_triangle(patch, m, &search)?;
            worst = worst.max(reduction.report.error_bound);
            if worst > tol {
                break;
            }
            pieces.push(TriPiece {
                vertices: *vertices,
                reduction,
            });
        }
        achieved = worst;
        if worst <= tol {
            if opts.measure {
                let sources: Vec<TriPatch> = cells.into_iter().map(|(patch, _)| patch).collect();
                measure_tri_pieces(&sources, &mut pieces)?;
            }
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
