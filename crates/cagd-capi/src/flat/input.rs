//! The argument checks shared by the single-curve flat calls: a curve given as arrays
//! (validated exactly as `cagd_curve_new` / `cagd_curve_new_rational` validate, so the
//! statuses agree with the handle API) and the weight buffer of a rational result, checked
//! against the points buffer.

use cagd_core::{check_degree, check_points, check_weights};

use crate::boundary::{CResult, Failure, disjoint, points_in, slice_in};
use crate::status::CagdStatus;

/// A validated curve given as arrays: `n + 1` points of `dim` coordinates, and the weights
/// when rational.
pub(super) struct CurveIn<'a> {
    /// `(n + 1) * dim` finite doubles, row-major.
    pub(super) points: &'a [f64],
    /// `n + 1` finite, positive weights, or `None` (polynomial).
    pub(super) weights: Option<&'a [f64]>,
    /// Coordinates per point, `>= 1`.
    pub(super) dim: usize,
}

impl CurveIn<'_> {
    /// The degree `n`.
    pub(super) fn degree(&self) -> usize {
        self.points.len() / self.dim - 1
    }
}

/// Borrows and validates a curve: NULL `points` → `CAGD_ERR_NULL_POINTER`; `dim == 0` or
/// an overflowing size → `CAGD_ERR_INVALID_ARGUMENT`; `n_points == 0` →
/// `CAGD_ERR_NOT_ENOUGH_POINTS`; `n_points > 65` → `CAGD_ERR_DEGREE_OUT_OF_RANGE`; a
/// non-finite coordinate → `CAGD_ERR_NON_FINITE`; a weight not finite and `>= DBL_MIN` →
/// `CAGD_ERR_NON_POSITIVE_WEIGHT`. `weights` NULL means polynomial.
///
/// # Safety
/// `points` must be NULL or point to `n_points * dim` readable doubles, `weights` NULL or
/// `n_points` readable doubles, valid for `'a`.
pub(super) unsafe fn curve_in<'a>(
    points: *const f64,
    n_points: usize,
    dim: usize,
    weights: *const f64,
) -> CResult<CurveIn<'a>> {
    // SAFETY: forwarded contract.
    let points = unsafe { points_in(points, n_points, dim, "points") }?;
    check_points(points, dim)?;
    check_degree(n_points - 1)?;
    let weights = if weights.is_null() {
        None
    } else {
        // SAFETY: forwarded contract.
        let w = unsafe { slice_in(weights, n_points, "weights") }?;
        check_weights(w, n_points)?;
        Some(w)
    };
    Ok(CurveIn {
        points,
        weights,
        dim,
    })
}

/// The weight buffer of a result of `n_out` points: `None` for a polynomial input (the
/// buffer is then ignored and may be NULL); for a rational one `weights_out` must be
/// non-NULL (`CAGD_ERR_NULL_POINTER`), aligned (`CAGD_ERR_INVALID_ARGUMENT`) and hold
/// `n_out` doubles (`CAGD_ERR_BUFFER_TOO_SMALL`, after `*out_needed` was written by the
/// caller). Checked before anything is written; the slice is not written here.
///
/// # Safety
/// `weights_out` must be NULL or point to `weights_cap` writable doubles valid for `'a`.
unsafe fn weights_buffer<'a>(
    rational: bool,
    weights_out: *mut f64,
    weights_cap: usize,
    n_out: usize,
) -> CResult<Option<&'a mut [f64]>> {
    if !rational {
        return Ok(None);
    }
    if weights_out.is_null() {
        return Err(Failure::null("weights_out"));
    }
    if !weights_out.is_aligned() {
        return Err(Failure::invalid(
            "argument `weights_out` is not aligned for double",
        ));
    }
    if weights_cap < n_out {
        return Err(Failure::new(
            CagdStatus::ERR_BUFFER_TOO_SMALL,
            format!(
                "`weights_out_cap` = {weights_cap} is too small: {n_out} weights needed \
                 (= *out_needed / dim)"
            ),
        ));
    }
    // SAFETY: non-NULL, aligned, `n_out <= weights_cap` writable doubles by the contract.
    Ok(Some(unsafe {
        std::slice::from_raw_parts_mut(weights_out, n_out)
    }))
}

/// The weight output of a single-curve flat call whose points go to `dst` (`n_out` points
/// of `dim` doubles, already sized): [`weights_buffer`] for the curve (`None` for a
/// polynomial one), and `out` / `weights_out` must not overlap
/// (`CAGD_ERR_INVALID_ARGUMENT`). Returns the buffer and its length in doubles (`0` for a
/// polynomial curve), for further overlap checks.
///
/// # Safety
/// As [`weights_buffer`].
pub(super) unsafe fn result_weights<'a>(
    curve: &CurveIn<'_>,
    dst: &[f64],
    weights_out: *mut f64,
    weights_cap: usize,
    n_out: usize,
) -> CResult<(Option<&'a mut [f64]>, usize)> {
    let rational = curve.weights.is_some();
    // SAFETY: forwarded contract.
    let w_dst = unsafe { weights_buffer(rational, weights_out, weights_cap, n_out) }?;
    let w_len = if rational { n_out } else { 0 };
    disjoint(
        dst.as_ptr(),
        dst.len(),
        weights_out,
        w_len,
        "`out` and `weights_out`",
    )?;
    Ok((w_dst, w_len))
}
