//! The batch entry points: one operator applied to many curves stored contiguously through
//! the data path of `gemm.rs` and `lanes.rs` ([`reduce_batch`]), optionally with a certified
//! bound per curve from two more small products in the same pass
//! ([`reduce_batch_with_bounds`]); [`Operator::apply_into`]
//! and [`Operator::apply`] (one curve) are defined here, on top of it, so that `operator/`
//! does not depend on this module.

use cagd_core::{Error, Result};

use cagd_core::all_finite;

use super::bound::{BoundLevel, safe_amax};
use super::lanes::{self, BoundMaps, CurveNorms, NodeMaps};
use super::operator::Operator;

impl Operator {
    /// Applies the operator to `n + 1` points of `dim` coordinates (row-major), writing
    /// `m + 1` points to `out`.
    ///
    /// # Errors
    /// [`Error::ZeroDimension`], [`Error::LengthMismatch`] (input or output length),
    /// [`Error::NonFinite`] (a non-finite input coordinate).
    pub fn apply_into(&self, points: &[f64], dim: usize, out: &mut [f64]) -> Result<()> {
        reduce_batch(self, points, dim, out)
    }

    /// Applies the operator to `n + 1` points of `dim` coordinates and returns the `m + 1`
    /// reduced points.
    ///
    /// # Errors
    /// As [`Operator::apply_into`].
    pub fn apply(&self, points: &[f64], dim: usize) -> Result<Vec<f64>> {
        let mut out = vec![0.0; (self.degree_to() + 1) * dim];
        self.apply_into(points, dim, &mut out)?;
        Ok(out)
    }
}

/// Applies `op` (degree `n -> m`) to every curve of `input` and writes the reduced curves
/// to `output`.
///
/// Layout: `input` holds `n_curves` curves of `n + 1` points of `dim` coordinates each,
/// curve-major and row-major inside a curve (`input[(c * (n+1) + j) * dim + k]`);
/// `output` receives `n_curves * (m + 1) * dim` doubles in the same layout. `n_curves` is
/// `input.len() / ((n + 1) * dim)`.
///
/// Data path (`gemm.rs`): 3-D curves through the padded-point kernel (`padded.rs`: one
/// point per vector, AVX2 with FMA when the CPU has them), other dimensions through the
/// curves-in-lanes kernel (`lanes.rs`: several curves per vector, AVX-512F / AVX2 with
/// FMA), no allocation per curve (see the crate's benchmark notes for the figures).
/// The results are the definition's sums in its order, with fused multiply-adds where the
/// CPU has them (so equal to the definition up to rounding), and a curve gets the same
/// bits wherever it sits in the batch.
///
/// # Errors
/// [`Error::ZeroDimension`]; [`Error::LengthMismatch`] when `input.len()` is not a multiple
/// of `(n+1) * dim` or `output.len()` is not `n_curves * (m+1) * dim`; [`Error::NonFinite`]
/// (index = point index counted over the whole batch) when an input coordinate is NaN or
/// infinite — `output` is then unspecified.
pub fn reduce_batch(op: &Operator, input: &[f64], dim: usize, output: &mut [f64]) -> Result<()> {
    check_batch(op, input, dim, output)?;
    if op.map().apply_checked(input, dim, output) {
        return Ok(());
    }
    Err(non_finite(input, dim, output))
}

/// [`reduce_batch`] plus, per curve `c`, a certified upper bound `bounds[c]` of
/// `max_t ||P_c(t) - Q_c(t)||` (Euclidean, in the space of the given points, the `f64`
/// rounding of `Q_c` included) at `level` (see [`BoundLevel`]; the number
/// [`Operator::certified_bound`] gives for that curve up to the order of its sums). The
/// bound is two more small products in the same pass of the kernel (the error curve's
/// `n - m` coefficient points, then its values at the level's nodes, their largest norm
/// taken in registers); curves with coordinates beyond `2^±450` take the scaled per-curve
/// route. A
/// bound that overflows is `+inf`.
///
/// # Errors
/// As [`reduce_batch`], and [`Error::LengthMismatch`] when `bounds.len()` is not the number
/// of curves, [`Error::BadParameter`] for `level = BoundLevel::None` (ask
/// [`reduce_batch`] for no bounds).
pub fn reduce_batch_with_bounds(
    op: &Operator,
    input: &[f64],
    dim: usize,
    output: &mut [f64],
    bounds: &mut [f64],
    level: BoundLevel,
) -> Result<()> {
    let n_curves = check_batch(op, input, dim, output)?;
    if bounds.len() != n_curves {
        return Err(Error::LengthMismatch {
            what: "batch bounds (one per curve)",
            got: bounds.len(),
            expected: n_curves,
        });
    }
    let Some(bm) = op.bound_map(level) else {
        return Err(Error::BadParameter {
            name: "level",
            value: 0.0,
            why: "bounds need a certified level (Fast or Tight)",
        });
    };
    let map = op.map();
    let basis = op.error_basis();
    let maps = BoundMaps {
        a: map.transposed(),
        g: basis.coef.transposed(),
        v: match &bm.split {
            Some((even, odd)) => NodeMaps::Split(
                even.transposed().0,
                odd.transposed().0,
                even.cols(),
                even.rows(),
            ),
            None => {
                let (vt, nodes) = bm.samples.transposed();
                NodeMaps::Full(vt, nodes)
            }
        },
    };
    let (per_in, per_out) = (map.cols() * dim, map.rows() * dim);
    let block = map.block_curves(dim);
    let mut norms = vec![CurveNorms::default(); block.min(n_curves)];
    let mut scratch = Vec::new();
    let mut finite = true;
    for ((inp, out), bnd) in input
        .chunks(block * per_in)
        .zip(output.chunks_mut(block * per_out))
        .zip(bounds.chunks_mut(block))
    {
        let nrm = &mut norms[..bnd.len()];
        lanes::apply_with_norms(&maps, dim, inp, out, nrm, &mut scratch);
        finite &= all_finite(out);
        for (((p, q), b), cn) in inp
            .chunks_exact(per_in)
            .zip(out.chunks_exact(per_out))
            .zip(bnd.iter_mut())
            .zip(nrm.iter())
        {
            *b = if safe_amax(cn.amax) {
                op.curve_bound_norms(bm, p, dim, cn.smax, cn.pmax)
            } else {
                // Norms could overflow or underflow: the scaled per-curve route.
                op.one_bound(bm, p, dim)
            };
            *b = op.with_reduced_norms(bm, (p, q), dim, *b, cn.pmax, cn.amax);
        }
    }
    if finite {
        Ok(())
    } else {
        Err(non_finite(input, dim, output))
    }
}

/// Checks the lengths of a batch; returns the number of curves.
fn check_batch(op: &Operator, input: &[f64], dim: usize, output: &[f64]) -> Result<usize> {
    if dim == 0 {
        return Err(Error::ZeroDimension);
    }
    let (n1, m1) = (op.degree_from() + 1, op.degree_to() + 1);
    let per_in = n1 * dim;
    if input.len() % per_in != 0 {
        return Err(Error::LengthMismatch {
            what: "batch input (multiple of (n+1)*dim)",
            got: input.len(),
            expected: input.len() / per_in * per_in,
        });
    }
    let n_curves = input.len() / per_in;
    if output.len() != n_curves * m1 * dim {
        return Err(Error::LengthMismatch {
            what: "batch output",
            got: output.len(),
            expected: n_curves * m1 * dim,
        });
    }
    Ok(n_curves)
}

/// The error for a batch with a non-finite output (the kernel checks each block of output
/// while it is in cache; every output of coordinate `k` is a dense sum over all points of
/// its curve, zeros included, so a NaN or infinity anywhere in the input shows there, and
/// only then is the input searched for the culprit): the first non-finite input
/// coordinate, or (finite input overflowing, only for `|x|` near `f64::MAX`) the first
/// non-finite output coordinate.
fn non_finite(input: &[f64], dim: usize, output: &[f64]) -> Error {
    if let Some(pos) = input.iter().position(|x| !x.is_finite()) {
        return Error::NonFinite {
            index: pos / dim,
            coord: pos % dim,
            value: input[pos],
        };
    }
    let pos = output.iter().position(|x| !x.is_finite()).unwrap_or(0);
    Error::NonFinite {
        index: pos / dim,
        coord: pos % dim,
        value: output[pos],
    }
}
