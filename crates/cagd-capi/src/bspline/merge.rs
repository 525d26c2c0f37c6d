//! `cagd_bspline_from_beziers`: the exact merge of Bézier segments into one B-spline /
//! NURBS curve (seed 001 §4.1; `BSplineCurve::from_beziers`).

use cagd_core::{BSplineCurve, BezierCurve};

use crate::boundary::{
    CResult, Failure, boundary, handle_ref, into_handle, nonnull, out_ref, slice_in,
};
use crate::bspline::CagdBSpline;
use crate::curve::CagdCurve;
use crate::status::CagdStatus;

/// Borrows the `count` curve handles of a C array `const CagdCurve *const *`: a NULL
/// element gives `CAGD_ERR_NULL_POINTER` naming its index, a misaligned array or element
/// `CAGD_ERR_INVALID_ARGUMENT`.
///
/// # Safety
/// `ptr` must be non-NULL and point to `count` readable pointers, each NULL or a live
/// curve handle, all valid for `'a`.
unsafe fn handles_in<'a>(
    ptr: *const *const CagdCurve,
    count: usize,
) -> CResult<Vec<&'a CagdCurve>> {
    if !ptr.is_aligned() {
        return Err(Failure::invalid(
            "argument `segments` is not aligned for a pointer array",
        ));
    }
    if count > isize::MAX as usize / size_of::<*const CagdCurve>() {
        return Err(Failure::invalid(format!(
            "`count` = {count} pointers overflows"
        )));
    }
    // SAFETY: non-NULL (checked by the caller), aligned, the length in bytes fits isize;
    // readability is the caller's contract.
    let ptrs = unsafe { std::slice::from_raw_parts(ptr, count) };
    ptrs.iter()
        .enumerate()
        // SAFETY: each element is NULL or a live handle (the caller's contract).
        .map(|(i, &p)| unsafe { handle_ref(p, &format!("segments[{i}]")) })
        .collect()
}

/// Merges consecutive Bézier segments into one clamped B-spline (NURBS if any segment is
/// rational), exactly (seed 001 §4.1, the exact merge). Segment `i`, a curve on `[0, 1]`,
/// becomes the piece of the spline on `[breaks[i], breaks[i + 1]]`. The knots are
/// `breaks[0]` and `breaks[count]` each `m + 1` times and every interior break `m - k`
/// times (`m` the segments' degree, `k = continuity`); with `k = 0` the control points are
/// the segments' points with each shared joint point stored once (their midpoint).
///
/// The stated continuity is checked, not assumed: for `C0` the end of each segment must
/// meet the start of the next within `tol` (Euclidean distance; for rational segments the
/// distance of the homogeneous points `(w P, w)`, so end weights must agree too); for
/// `C^k`, `k >= 1`, each interior knot is removed `k` times and the accumulated certified
/// bound of the knot removal must stay within `tol` (model units). Continuity is
/// parametric in the global parameter (a segment's derivatives scale with its interval
/// length). Polynomial and rational segments may be mixed (weights 1 for the polynomial
/// ones); rational segments are merged in homogeneous space.
///
/// Parameters:
/// - `segments` (in): array of `count` curve handles, in order, all of the same degree
///   `m >= 1` and the same `dim`. Borrowed for the call; the curves are copied and stay
///   owned by the caller.
/// - `count` (in): number of segments, `>= 1`.
/// - `breaks` (in): `count + 1` doubles, finite and strictly increasing, or NULL for the
///   breaks `0, 1, ..., count`. Borrowed and copied. Not read when `count == 0`.
/// - `continuity` (in): the order `k` of the joints, `0 <= k < m` (interior knot
///   multiplicity `m - k`).
/// - `tol` (in): the tolerance of the joint check in model units, finite and `> 0`.
/// - `spline_out` (out): on `CAGD_OK`, the merged spline (degree `m`,
///   `count * (m - k) + k + 1` control points, `count * (m - k) + k + m + 2` knots), a new
///   handle owned by the caller: release it with `cagd_bspline_free`. Not written on
///   failure.
///
/// Returns:
/// - `CAGD_OK`: `*spline_out` holds the merged spline.
/// - `CAGD_ERR_NULL_POINTER`: `segments` or `spline_out` is NULL, or an element
///   `segments[i]` is NULL (the message gives `i`).
/// - `CAGD_ERR_INVALID_ARGUMENT`: `tol` is NaN, infinite or `<= 0`; a break is NaN or
///   infinite, or the breaks are not strictly increasing; the segments have degree 0, or
///   `continuity >= m`; `count` is too large for memory; a pointer is misaligned.
/// - `CAGD_ERR_NOT_ENOUGH_POINTS`: `count == 0`.
/// - `CAGD_ERR_DIMENSION_MISMATCH`: the segments do not all have the same degree and
///   `dim` (the message gives the values).
/// - `CAGD_ERR_CONDITION_NOT_MET`: consecutive segments do not meet within `tol` (C0), or
///   the joints are not `C^continuity` within `tol`.
/// - `CAGD_ERR_NON_FINITE`: a merged control point overflows (coordinates near the
///   `double` range).
/// - `CAGD_ERR_NON_POSITIVE_WEIGHT`: a merged weight of rational segments overflows to
///   infinity (weights near the `double` range; the spline's weights must be finite and
///   positive).
/// - `CAGD_ERR_PANIC`: internal bug caught at the boundary.
///
/// # Safety
/// `segments` must be NULL or point to `count` readable `const CagdCurve *`, each NULL or
/// a live curve handle; `breaks` NULL or `count + 1` readable doubles; `spline_out` NULL
/// or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_bspline_from_beziers(
    segments: *const *const CagdCurve,
    count: usize,
    breaks: *const f64,
    continuity: usize,
    tol: f64,
    spline_out: *mut *mut CagdBSpline,
) -> CagdStatus {
    boundary(|| {
        nonnull(segments, "segments")?;
        // SAFETY: the caller's contract (see # Safety).
        let out = unsafe { out_ref(spline_out, "spline_out") }?;
        // SAFETY: as above; `segments` is not NULL.
        let handles = unsafe { handles_in(segments, count) }?;
        let segs: Vec<BezierCurve> = handles.iter().map(|h| h.0.clone()).collect();
        let breaks: Vec<f64> = if count == 0 {
            Vec::new()
        } else if breaks.is_null() {
            (0..=count).map(|i| i as f64).collect()
        } else {
            // SAFETY: as above; `count + 1` does not overflow (count fits the pointer array).
            unsafe { slice_in(breaks, count + 1, "breaks") }?.to_vec()
        };
        let spline = BSplineCurve::from_beziers(&segs, &breaks, continuity, tol)?;
        *out = into_handle(CagdBSpline(spline));
        Ok(())
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::last_error::last_error_string;

    fn curve(points: &[f64], dim: usize) -> CagdCurve {
        CagdCurve(BezierCurve::new(points.to_vec(), dim).unwrap())
    }

    /// Runs the merge on Rust values; returns the status and the spline, if any.
    fn merge(
        segs: &[*const CagdCurve],
        breaks: Option<&[f64]>,
        k: usize,
        tol: f64,
    ) -> (CagdStatus, Option<BSplineCurve>) {
        let mut out: *mut CagdBSpline = std::ptr::null_mut();
        let br = breaks.map_or(std::ptr::null(), <[f64]>::as_ptr);
        // SAFETY: pointers to live locals of the stated sizes; the result is freed below.
        let st =
            unsafe { cagd_bspline_from_beziers(segs.as_ptr(), segs.len(), br, k, tol, &mut out) };
        if out.is_null() {
            return (st, None);
        }
        // SAFETY: a handle made by the call above, released once here.
        let s = unsafe { Box::from_raw(out) };
        (st, Some(s.0))
    }

    #[test]
    fn merges_with_default_and_given_breaks() {
        let (a, b) = (curve(&[0.0, 1.0, 2.0], 1), curve(&[2.0, 3.0, 5.0], 1));
        let segs = [&raw const a, &raw const b];
        let (st, s) = merge(&segs, None, 0, 1e-12);
        assert_eq!(st, CagdStatus::OK);
        let s = s.unwrap();
        assert_eq!(s.knots(), &[0.0, 0.0, 0.0, 1.0, 1.0, 2.0, 2.0, 2.0]);
        assert_eq!(s.points(), &[0.0, 1.0, 2.0, 3.0, 5.0]);
        let (st, s) = merge(&segs, Some(&[1.0, 1.5, 4.0]), 0, 1e-12);
        assert_eq!(st, CagdStatus::OK);
        assert_eq!(
            s.unwrap().knots(),
            &[1.0, 1.0, 1.0, 1.5, 1.5, 4.0, 4.0, 4.0]
        );
    }

    /// A bad-input case: the expected status, the segments, the breaks, `k`, `tol`.
    type Case<'a> = (
        CagdStatus,
        &'a [*const CagdCurve],
        Option<&'a [f64]>,
        usize,
        f64,
    );

    #[test]
    fn bad_input_statuses() {
        let (a, b) = (curve(&[0.0, 1.0, 2.0], 1), curve(&[2.5, 3.0, 5.0], 1));
        let segs = [&raw const a, &raw const b];
        let with_null = [&raw const a, std::ptr::null()];
        let cases: [Case<'_>; 6] = [
            (CagdStatus::ERR_NULL_POINTER, &with_null, None, 0, 1.0),
            (CagdStatus::ERR_NOT_ENOUGH_POINTS, &[], None, 0, 1.0),
            (CagdStatus::ERR_CONDITION_NOT_MET, &segs, None, 0, 1e-9),
            (CagdStatus::ERR_INVALID_ARGUMENT, &segs, None, 2, 1.0),
            (
                CagdStatus::ERR_INVALID_ARGUMENT,
                &segs,
                Some(&[0.0, 2.0, 1.0]),
                0,
                1.0,
            ),
            (CagdStatus::ERR_INVALID_ARGUMENT, &segs, None, 0, f64::NAN),
        ];
        for (want, s, br, k, tol) in cases {
            let (st, out) = merge(s, br, k, tol);
            assert_eq!(st, want, "{s:?} {br:?} {k} {tol}");
            assert!(out.is_none());
            assert!(!last_error_string().is_empty());
        }
        assert_eq!(
            merge(&with_null, None, 0, 1.0).0,
            CagdStatus::ERR_NULL_POINTER
        );
        assert!(last_error_string().contains("segments[1]"));
        let mut out: *mut CagdBSpline = std::ptr::null_mut();
        // SAFETY: NULL pointers are what is tested; nothing is read through them.
        let st = unsafe {
            cagd_bspline_from_beziers(std::ptr::null(), 2, std::ptr::null(), 0, 1.0, &mut out)
        };
        assert_eq!(st, CagdStatus::ERR_NULL_POINTER);
        // SAFETY: as above; `segs` holds 2 live handles.
        let st = unsafe {
            cagd_bspline_from_beziers(
                segs.as_ptr(),
                2,
                std::ptr::null(),
                0,
                1.0,
                std::ptr::null_mut(),
            )
        };
        assert_eq!(st, CagdStatus::ERR_NULL_POINTER);
        assert!(out.is_null());
    }
}
