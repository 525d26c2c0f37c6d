//! `CagdBatchLayout`: how the curves of a batch are stored in one flat array.

use crate::boundary::{CResult, Failure};

/// How `n_curves` curves of `n + 1` points of `dim` coordinates are stored in one array of
/// a batch call (passed as an `int32_t`, so that any value is checked rather than
/// undefined).
///
/// cbindgen:rename-all=prefix:CAGD_
#[repr(i32)]
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[allow(
    non_camel_case_types,
    reason = "C names: the variants become CAGD_LAYOUT_*"
)]
pub enum CagdBatchLayout {
    /// Curve after curve, each row-major: coordinate k of point j of curve c at
    /// `[(c * (n + 1) + j) * dim + k]` (the layout of `cagd_curve_reduce_batch`).
    LAYOUT_CURVE_MAJOR = 0,
    /// Point after point, each point of every curve: coordinate k of point j of curve c
    /// at `[(j * n_curves + c) * dim + k]`. Point j of all curves is one contiguous row of
    /// `n_curves * dim` doubles, so the batch is one matrix product (a GEMM's layout).
    LAYOUT_POINT_MAJOR = 1,
}

impl CagdBatchLayout {
    /// The layout of a C code.
    ///
    /// # Errors
    /// `CAGD_ERR_INVALID_ARGUMENT` for a code that is not a `CagdBatchLayout`.
    pub(super) fn of(code: i32) -> CResult<Self> {
        match code {
            0 => Ok(Self::LAYOUT_CURVE_MAJOR),
            1 => Ok(Self::LAYOUT_POINT_MAJOR),
            other => Err(Failure::invalid(format!(
                "layout = {other} is not a CagdBatchLayout (0 = CAGD_LAYOUT_CURVE_MAJOR, \
                 1 = CAGD_LAYOUT_POINT_MAJOR)"
            ))),
        }
    }

    /// `(curve, point)` of the flat point index `p` (counted in points of `dim` doubles)
    /// of a batch of `n_curves` curves of `n1` points, for messages.
    pub(super) fn curve_and_point(self, p: usize, n_curves: usize, n1: usize) -> (usize, usize) {
        match self {
            Self::LAYOUT_CURVE_MAJOR => (p / n1, p % n1),
            Self::LAYOUT_POINT_MAJOR => (p % n_curves, p / n_curves),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::status::CagdStatus;

    #[test]
    fn codes_are_pinned() {
        assert_eq!(CagdBatchLayout::LAYOUT_CURVE_MAJOR as i32, 0);
        assert_eq!(CagdBatchLayout::LAYOUT_POINT_MAJOR as i32, 1);
        for code in [0, 1] {
            assert_eq!(CagdBatchLayout::of(code).unwrap() as i32, code);
        }
        for code in [-1, 2, i32::MAX] {
            let e = CagdBatchLayout::of(code).unwrap_err();
            assert_eq!(e.status, CagdStatus::ERR_INVALID_ARGUMENT);
        }
    }

    #[test]
    fn point_index_to_curve_and_point() {
        // 3 curves of 4 points: curve-major point 6 is curve 1, point 2; point-major point
        // 7 is point 2 (row 2) of curve 1.
        let cm = CagdBatchLayout::LAYOUT_CURVE_MAJOR;
        let pm = CagdBatchLayout::LAYOUT_POINT_MAJOR;
        assert_eq!(cm.curve_and_point(6, 3, 4), (1, 2));
        assert_eq!(pm.curve_and_point(7, 3, 4), (1, 2));
    }
}
