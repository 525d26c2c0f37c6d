//! The batch entry point: one operator applied to many curves stored contiguously, with no
//! allocation; [`Operator::apply_into`] and [`Operator::apply`] (one curve) are defined
//! here, on top of it, so that `operator/` does not depend on this module.

use cagd_core::{Error, Result};

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
/// `input.len() / ((n + 1) * dim)`. No allocation; `dim = 1..=4` use unrolled kernels.
///
/// # Errors
/// [`Error::ZeroDimension`]; [`Error::LengthMismatch`] when `input.len()` is not a multiple
/// of `(n+1) * dim` or `output.len()` is not `n_curves * (m+1) * dim`; [`Error::NonFinite`]
/// (index = point index counted over the whole batch) when an input coordinate is NaN or
/// infinite — `output` is then unspecified.
pub fn reduce_batch(op: &Operator, input: &[f64], dim: usize, output: &mut [f64]) -> Result<()> {
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
    let a = op.matrix();
    // Every output is a dense dot product over all inputs (zeros included), so a NaN or
    // infinity anywhere in a curve makes its outputs non-finite: `x * 0` summed over the
    // outputs detects it without a second pass over the input (`x * 0` is `0` for finite `x`, NaN
    // otherwise).
    let finite = match dim {
        1 => kernel::<1>(a, n1, m1, input, output),
        2 => kernel::<2>(a, n1, m1, input, output),
        3 => kernel::<3>(a, n1, m1, input, output),
        4 => kernel::<4>(a, n1, m1, input, output),
        _ => kernel_dyn(a, n1, m1, dim, input, output),
    };
    if !finite {
        if let Some(pos) = input.iter().position(|x| !x.is_finite()) {
            return Err(Error::NonFinite {
                index: pos / dim,
                coord: pos % dim,
                value: input[pos],
            });
        }
        // Finite input can overflow to infinity only for |x| near f64::MAX.
        if let Some(pos) = output.iter().position(|x| !x.is_finite()) {
            return Err(Error::NonFinite {
                index: pos / dim,
                coord: pos % dim,
                value: output[pos],
            });
        }
    }
    Ok(())
}

/// Fixed-dimension kernel; returns whether every output is finite.
fn kernel<const D: usize>(
    a: &[f64],
    n1: usize,
    m1: usize,
    input: &[f64],
    output: &mut [f64],
) -> bool {
    let mut check = 0.0f64;
    for (inp, out) in input
        .chunks_exact(n1 * D)
        .zip(output.chunks_exact_mut(m1 * D))
    {
        for (row, o) in a.chunks_exact(n1).zip(out.chunks_exact_mut(D)) {
            let mut acc = [0.0f64; D];
            for (&c, x) in row.iter().zip(inp.chunks_exact(D)) {
                for k in 0..D {
                    acc[k] += c * x[k];
                }
            }
            for k in 0..D {
                o[k] = acc[k];
                check += acc[k] * 0.0;
            }
        }
    }
    check == 0.0
}

/// Any-dimension kernel; returns whether every output is finite.
fn kernel_dyn(
    a: &[f64],
    n1: usize,
    m1: usize,
    dim: usize,
    input: &[f64],
    output: &mut [f64],
) -> bool {
    let mut check = 0.0f64;
    for (inp, out) in input
        .chunks_exact(n1 * dim)
        .zip(output.chunks_exact_mut(m1 * dim))
    {
        for (row, o) in a.chunks_exact(n1).zip(out.chunks_exact_mut(dim)) {
            o.fill(0.0);
            for (&c, x) in row.iter().zip(inp.chunks_exact(dim)) {
                for (ok, xk) in o.iter_mut().zip(x) {
                    *ok += c * xk;
                }
            }
            check += o.iter().map(|v| v * 0.0).sum::<f64>();
        }
    }
    check == 0.0
}
