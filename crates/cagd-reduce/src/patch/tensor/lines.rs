//! Row and column maps of a tensor-product control net (i-major, `dim` coordinates per
//! point): the perturbation (`mod.rs`) and the direction-by-direction curve reduction
//! (`curves.rs`) both apply a curve operator to every column, then to every row.

use cagd_core::Result;

/// Applies `f(column_in, column_out)` to every column of an `rows x cols` net (`dim`
/// coordinates, i-major), giving a `rows_out x cols` net.
pub(crate) fn map_columns(
    x: &[f64],
    (rows, cols): (usize, usize),
    dim: usize,
    rows_out: usize,
    mut f: impl FnMut(&[f64], &mut [f64]) -> Result<()>,
) -> Result<Vec<f64>> {
    let mut out = vec![0.0; rows_out * cols * dim];
    let (mut ci, mut co) = (vec![0.0; rows * dim], vec![0.0; rows_out * dim]);
    for j in 0..cols {
        for i in 0..rows {
            let s = (i * cols + j) * dim;
            ci[i * dim..(i + 1) * dim].copy_from_slice(&x[s..s + dim]);
        }
        f(&ci, &mut co)?;
        for i in 0..rows_out {
            let o = (i * cols + j) * dim;
            out[o..o + dim].copy_from_slice(&co[i * dim..(i + 1) * dim]);
        }
    }
    Ok(out)
}

/// Applies `f(row_in, row_out)` to every row of an `rows x cols` net, giving `rows x cols_out`.
pub(crate) fn map_rows(
    x: &[f64],
    (rows, cols): (usize, usize),
    dim: usize,
    cols_out: usize,
    mut f: impl FnMut(&[f64], &mut [f64]) -> Result<()>,
) -> Result<Vec<f64>> {
    let mut out = vec![0.0; rows * cols_out * dim];
    for (ri, ro) in x
        .chunks_exact(cols * dim)
        .zip(out.chunks_exact_mut(cols_out * dim))
    {
        f(ri, ro)?;
    }
    Ok(out)
}
