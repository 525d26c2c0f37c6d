//! `CagdIntervalTriPatch`: interval triangular Bézier patches (seed 004, SPEC-convert part I)
//! — creation, read-back, thickness, certified containment, the elevation matrix, and the
//! degree reduction by linear programming.

use cagd_core::tri_count;
use cagd_reduce::{
    IntervalOptions, IntervalTriPatch, MAX_INTERVAL_DEGREE, reduce_interval_triangle,
    triangle_elevation_matrix,
};

use crate::boundary::{
    CResult, Failure, OUT, boundary, boundary_void, checked_len, free_handle, handle_ref,
    into_handle, nonnull, out_ref, points_in, slice_out,
};
use crate::status::CagdStatus;

/// Opaque handle to an interval triangular Bézier patch of degree `n` (`0..=64`) in `dim`
/// coordinates: one control box `[lo, hi]` per coordinate for each of the
/// `(n + 1)(n + 2) / 2` indices `i + j + k = n`, stored i-major (for i in 0..=n, for j in
/// 0..=n-i) as two nets `lo` and `hi` of `(n + 1)(n + 2) / 2 * dim` doubles. Invariant:
/// every bound finite and `lo <= hi`. Immutable; release with `cagd_intervaltri_free`.
#[derive(Debug, Clone, PartialEq)]
pub struct CagdIntervalTriPatch(pub(crate) IntervalTriPatch);

impl CagdIntervalTriPatch {
    /// The patch behind the handle (for Rust callers of this crate).
    pub fn as_patch(&self) -> &IntervalTriPatch {
        &self.0
    }
}

/// The report of `cagd_intervaltri_reduce` (plain data, written only on `CAGD_OK`).
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CagdIntervalReport {
    /// Thickness of the input: the mean box width over boxes and coordinates
    /// (SPEC-convert I.1).
    pub thickness_in: f64,
    /// Thickness of the result.
    pub thickness_out: f64,
    /// `thickness_out / thickness_in`; NaN when the input has thickness 0.
    pub ratio: f64,
    /// Number of coordinates whose decoupled LP optimum had an empty box, so that the
    /// coupled LP (with `L <= U`) was solved (0 = decoupled everywhere).
    pub n_coupled: usize,
    /// The largest outward shift of the containment repair (model units; 0 when the
    /// solver's vertex was certified as it was).
    pub repair: f64,
    /// The largest pointwise containment violation found by sampling 1 035 domain points
    /// (`<= 0`: contained at every sample; differences within the rounding bound of the
    /// `f64` evaluation count as 0).
    pub max_violation: f64,
    /// The containment degree `N` of the model solved and certified.
    pub containment_degree: usize,
    /// Sum over coordinates of the LP optima `sum U - sum L` (before repair).
    pub objective: f64,
    /// Sum over coordinates of the decoupled LP optima (`<= objective`).
    pub objective_decoupled: f64,
}

/// Creates an interval triangle of degree `degree` from its lower and upper nets.
///
/// Parameters:
/// - `lo`, `hi` (in): `(degree + 1) * (degree + 2) / 2 * dim` doubles each, i-major: box
///   `(i, j)` starts at double `(i * (2n + 3 - i) / 2 + j) * dim`; coordinate `c` of the box
///   is the interval `[lo[.. + c], hi[.. + c]]`. Borrowed and copied.
/// - `degree` (in): the degree `n`, `0..=64`.
/// - `dim` (in): coordinates per box, `>= 1`.
/// - `patch_out` (out): on `CAGD_OK`, a new handle owned by the caller (release with
///   `cagd_intervaltri_free`). Not written on failure.
///
/// Returns:
/// - `CAGD_OK`: `*patch_out` holds the new patch.
/// - `CAGD_ERR_NULL_POINTER`: `lo`, `hi` or `patch_out` is NULL.
/// - `CAGD_ERR_INVALID_ARGUMENT`: `dim == 0`, the length formula overflows, or a pointer
///   is misaligned.
/// - `CAGD_ERR_DEGREE_OUT_OF_RANGE`: `degree > 64`.
/// - `CAGD_ERR_NON_FINITE`: a bound is NaN or infinite.
/// - `CAGD_ERR_EMPTY_INTERVAL`: `lo > hi` for some box and coordinate (the message names
///   them).
/// - `CAGD_ERR_PANIC`: internal bug caught at the boundary.
///
/// # Safety
/// `lo` and `hi` must be NULL or point to `(degree + 1) * (degree + 2) / 2 * dim` readable
/// doubles each; `patch_out` NULL or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_intervaltri_new(
    lo: *const f64,
    hi: *const f64,
    degree: usize,
    dim: usize,
    patch_out: *mut *mut CagdIntervalTriPatch,
) -> CagdStatus {
    boundary(|| {
        nonnull(lo, "lo")?;
        nonnull(hi, "hi")?;
        // SAFETY: the caller's contract (see # Safety).
        let out = unsafe { out_ref(patch_out, "patch_out") }?;
        check_degree(degree)?;
        // SAFETY: as above; degree <= 64 so tri_count cannot overflow.
        let l = unsafe { points_in(lo, tri_count(degree), dim, "lo") }?;
        // SAFETY: as above.
        let h = unsafe { points_in(hi, tri_count(degree), dim, "hi") }?;
        let p = IntervalTriPatch::new(l.to_vec(), h.to_vec(), degree, dim)?;
        *out = into_handle(CagdIntervalTriPatch(p));
        Ok(())
    })
}

fn check_degree(degree: usize) -> CResult<()> {
    if degree > MAX_INTERVAL_DEGREE {
        return Err(cagd_core::Error::DegreeOutOfRange {
            degree,
            max: MAX_INTERVAL_DEGREE,
        }
        .into());
    }
    Ok(())
}

/// Releases an interval triangle. NULL is accepted and ignored (freeing NULL twice is
/// fine); a non-NULL handle must be released exactly once and not used afterwards.
///
/// Parameters:
/// - `patch` (in, consumed): a handle from `cagd_intervaltri_new` or
///   `cagd_intervaltri_reduce`, or NULL.
///
/// Does not change `cagd_last_error_message()`.
///
/// # Safety
/// `patch` must be NULL or a live handle created by cagd that is not used afterwards.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_intervaltri_free(patch: *mut CagdIntervalTriPatch) {
    // SAFETY: the caller's contract (see # Safety).
    boundary_void(|| unsafe { free_handle(patch) });
}

/// Reads the degree, the dimension and the thickness of an interval triangle.
///
/// Parameters:
/// - `patch` (in): the patch.
/// - `degree_out` (out): on `CAGD_OK`, the degree `n`.
/// - `dim_out` (out): on `CAGD_OK`, the coordinates per box.
/// - `thickness_out` (out): on `CAGD_OK`, the thickness (mean box width over boxes and
///   coordinates, SPEC-convert I.1).
///
/// Returns:
/// - `CAGD_OK`: every output is written.
/// - `CAGD_ERR_NULL_POINTER`: any argument is NULL.
/// - `CAGD_ERR_INVALID_ARGUMENT`: a pointer is misaligned.
/// - `CAGD_ERR_NON_FINITE`: the thickness overflows (boxes wider than the double range);
///   nothing is written.
/// - `CAGD_ERR_PANIC`: internal bug caught at the boundary.
///
/// # Safety
/// `patch` must be NULL or a live handle; the outputs NULL or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_intervaltri_shape(
    patch: *const CagdIntervalTriPatch,
    degree_out: *mut usize,
    dim_out: *mut usize,
    thickness_out: *mut f64,
) -> CagdStatus {
    boundary(|| {
        // SAFETY: the caller's contract (see # Safety).
        let p = unsafe { handle_ref(patch, "patch") }?;
        // SAFETY: as above.
        let (n, d, t) = unsafe {
            (
                out_ref(degree_out, "degree_out")?,
                out_ref(dim_out, "dim_out")?,
                out_ref(thickness_out, "thickness_out")?,
            )
        };
        let thickness = p.0.thickness();
        if !thickness.is_finite() {
            // Boxes wider than the double range (bounds near +-DBL_MAX; C ABI fuzz run,
            // seed 103): the mean width is not a double.
            return Err(Failure::new(
                CagdStatus::ERR_NON_FINITE,
                "the thickness (mean box width) overflows: boxes wider than the double range",
            ));
        }
        (*n, *d, *t) = (p.0.degree(), p.0.dim(), thickness);
        Ok(())
    })
}

/// Copies one net of an interval triangle: `upper == false` the lower net, `true` the
/// upper net, i-major as in `cagd_intervaltri_new`. Call with `out_cap = 0` (and `out` NULL)
/// to ask the size.
///
/// Parameters:
/// - `patch` (in): the patch.
/// - `upper` (in): which net.
/// - `out` (out): buffer of `out_cap` doubles; on `CAGD_OK` its first
///   `(n + 1) * (n + 2) / 2 * dim` doubles hold the net. May be NULL only when
///   `out_cap == 0`.
/// - `out_cap` (in): capacity of `out` in doubles.
/// - `out_needed` (out): on `CAGD_OK` and on `CAGD_ERR_BUFFER_TOO_SMALL`,
///   `(n + 1) * (n + 2) / 2 * dim`.
///
/// Returns:
/// - `CAGD_OK`: the net is in `out`.
/// - `CAGD_ERR_NULL_POINTER`: `patch` or `out_needed` is NULL, or `out` is NULL with
///   `out_cap > 0`.
/// - `CAGD_ERR_BUFFER_TOO_SMALL`: `out_cap` is below the formula; only `*out_needed` is
///   written.
/// - `CAGD_ERR_INVALID_ARGUMENT`: a pointer is misaligned.
/// - `CAGD_ERR_PANIC`: internal bug caught at the boundary.
///
/// # Safety
/// `patch` must be NULL or a live handle; `out` NULL or `out_cap` writable doubles;
/// `out_needed` NULL or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_intervaltri_net(
    patch: *const CagdIntervalTriPatch,
    upper: bool,
    out: *mut f64,
    out_cap: usize,
    out_needed: *mut usize,
) -> CagdStatus {
    boundary(|| {
        // SAFETY: the caller's contract (see # Safety).
        let p = unsafe { handle_ref(patch, "patch") }?;
        // SAFETY: as above.
        let buf = unsafe { slice_out(out, out_cap, out_needed, &OUT) }?;
        buf.copy_from(if upper { p.0.hi() } else { p.0.lo() })
    })
}

/// Certified containment: whether `outer` contains `inner` in the control-box sense at
/// degree `N = max(n_outer, n_inner, containment_degree)`, i.e.
/// `E_{n_outer->N} lo_outer <= E_{n_inner->N} lo_inner` and the same `>=` for `hi`, decided
/// in exact arithmetic on the stored doubles. This implies pointwise containment of the
/// interval surfaces.
///
/// Parameters:
/// - `outer`, `inner` (in): the patches (same `dim`).
/// - `containment_degree` (in): `N`; 0 (or anything below the degrees) means the larger
///   of the two degrees.
/// - `contains_out` (out): on `CAGD_OK`, the answer.
///
/// Returns:
/// - `CAGD_OK`: `*contains_out` is written.
/// - `CAGD_ERR_NULL_POINTER`: any pointer is NULL.
/// - `CAGD_ERR_DIMENSION_MISMATCH`: the dimensions differ.
/// - `CAGD_ERR_DEGREE_OUT_OF_RANGE`: `N > 64`.
/// - `CAGD_ERR_INVALID_ARGUMENT`: a pointer is misaligned.
/// - `CAGD_ERR_PANIC`: internal bug caught at the boundary.
///
/// # Safety
/// `outer`, `inner` must be NULL or live handles; `contains_out` NULL or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_intervaltri_contains(
    outer: *const CagdIntervalTriPatch,
    inner: *const CagdIntervalTriPatch,
    containment_degree: usize,
    contains_out: *mut bool,
) -> CagdStatus {
    boundary(|| {
        // SAFETY: the caller's contract (see # Safety).
        let (o, i) = unsafe { (handle_ref(outer, "outer")?, handle_ref(inner, "inner")?) };
        // SAFETY: as above.
        let out = unsafe { out_ref(contains_out, "contains_out") }?;
        let big = containment_degree.max(o.0.degree()).max(i.0.degree());
        *out = o.0.contains(&i.0, Some(big))?;
        Ok(())
    })
}

/// Reduces an interval triangle of degree `n` to the tightest degree-`target` interval
/// triangle that contains it (seed 004's LP, SPEC-convert I.2): per coordinate
/// `min sum U - sum L` s.t. `E_{m->N} L <= E_{n->N} lo`, `E_{m->N} U >= E_{n->N} hi`,
/// decoupled first and coupled (`L <= U`) where the decoupled optimum has an empty box;
/// the answer is moved outward until the containment holds in exact arithmetic on the
/// returned doubles (never returned uncertified).
///
/// Parameters:
/// - `patch` (in): the input, degree `n`.
/// - `target` (in): the degree `m < n`.
/// - `containment_degree` (in): `N >= n` of the tighter model; 0 means `N = n` (the
///   paper's model).
/// - `patch_out` (out): on `CAGD_OK`, a new handle of degree `target` owned by the caller
///   (release with `cagd_intervaltri_free`).
/// - `report_out` (out): on `CAGD_OK`, the report; may be NULL when not wanted.
///
/// Time (release, 3-D, random boxes, the project's 2-core machine): 4 -> 3 about 4 ms,
/// 10 -> 5 about 30 ms, 20 -> 10 (LPs of 231 rows x 66 variables) about 0.4 s.
///
/// Returns:
/// - `CAGD_OK`: `*patch_out` (and `*report_out`) are written.
/// - `CAGD_ERR_NULL_POINTER`: `patch` or `patch_out` is NULL.
/// - `CAGD_ERR_BAD_DEGREE_PAIR`: `target >= n`, or `0 < containment_degree < n`.
/// - `CAGD_ERR_DEGREE_OUT_OF_RANGE`: `containment_degree > 64`.
/// - `CAGD_ERR_LP_INFEASIBLE`, `CAGD_ERR_LP_UNBOUNDED`: the LP solver said so (impossible by
///   SPEC-convert I.2; reported, never hidden).
/// - `CAGD_ERR_LP_FAILED`: the LP solver failed or panicked (caught).
/// - `CAGD_ERR_NOT_CERTIFIED`: the containment could not be certified after repair.
/// - `CAGD_ERR_CONDITION_NOT_MET`: the LPs are beyond the work cap
///   (`MAX_INTERVAL_LP_WORK`: `tri_count(N) tri_count(target)^2 dim <= 2^23`, about a
///   second of simplex; e.g. a 3-D 20 -> 10 is answered, a 1-D 58 -> 14 refused).
/// - `CAGD_ERR_INVALID_ARGUMENT`: a pointer is misaligned.
/// - `CAGD_ERR_NON_FINITE`: an intermediate or result value overflows f64 (coordinates near the limits of f64).
/// - `CAGD_ERR_PANIC`: internal bug caught at the boundary.
///
/// # Safety
/// `patch` must be NULL or a live handle; `patch_out` NULL or writable; `report_out` NULL
/// or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_intervaltri_reduce(
    patch: *const CagdIntervalTriPatch,
    target: usize,
    containment_degree: usize,
    patch_out: *mut *mut CagdIntervalTriPatch,
    report_out: *mut CagdIntervalReport,
) -> CagdStatus {
    boundary(|| {
        // SAFETY: the caller's contract (see # Safety).
        let p = unsafe { handle_ref(patch, "patch") }?;
        // SAFETY: as above.
        let out = unsafe { out_ref(patch_out, "patch_out") }?;
        let report = if report_out.is_null() {
            None
        } else {
            // SAFETY: as above (non-NULL).
            Some(unsafe { out_ref(report_out, "report_out") }?)
        };
        let opts = IntervalOptions {
            containment_degree: (containment_degree != 0).then_some(containment_degree),
            ..IntervalOptions::new(target)
        };
        let red = reduce_interval_triangle(&p.0, &opts)?;
        let r = &red.report;
        if let Some(rep) = report {
            *rep = CagdIntervalReport {
                thickness_in: r.thickness_in,
                thickness_out: r.thickness_out,
                ratio: r.ratio.unwrap_or(f64::NAN),
                n_coupled: r.coupled.iter().filter(|&&c| c).count(),
                repair: r.repair,
                max_violation: r.max_violation.unwrap_or(f64::NAN),
                containment_degree: r.containment_degree,
                objective: r.objective,
                objective_decoupled: r.objective_decoupled,
            };
        }
        *out = into_handle(CagdIntervalTriPatch(red.patch));
        Ok(())
    })
}

/// The elevation matrix `E_{m->n}` of triangular nets (SPEC-convert I.1; entry
/// `C(m;b) C(n-m;a-b) / C(n;a)` rounded once), row-major: row `a` = index of the degree-`n`
/// net, column `b` = index of the degree-`m` net, both i-major. Call with `out_cap = 0` to
/// ask the size.
///
/// Parameters:
/// - `m`, `n` (in): degrees, `m <= n <= 64`.
/// - `out` (out): buffer of `out_cap` doubles; on `CAGD_OK` its first
///   `(n+1)(n+2)/2 * (m+1)(m+2)/2` doubles hold the matrix. May be NULL only when
///   `out_cap == 0`.
/// - `out_cap` (in): capacity of `out` in doubles.
/// - `out_needed` (out): on `CAGD_OK` and on `CAGD_ERR_BUFFER_TOO_SMALL`, the size above.
///
/// Returns:
/// - `CAGD_OK`: the matrix is in `out`.
/// - `CAGD_ERR_NULL_POINTER`: `out_needed` is NULL, or `out` is NULL with `out_cap > 0`.
/// - `CAGD_ERR_BUFFER_TOO_SMALL`: `out_cap` is too small; only `*out_needed` is written.
/// - `CAGD_ERR_BAD_DEGREE_PAIR`: `m > n`.
/// - `CAGD_ERR_DEGREE_OUT_OF_RANGE`: `n > 64`.
/// - `CAGD_ERR_INVALID_ARGUMENT`: a pointer is misaligned.
/// - `CAGD_ERR_PANIC`: internal bug caught at the boundary.
///
/// # Safety
/// `out` NULL or `out_cap` writable doubles; `out_needed` NULL or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_triangle_elevation_matrix(
    m: usize,
    n: usize,
    out: *mut f64,
    out_cap: usize,
    out_needed: *mut usize,
) -> CagdStatus {
    boundary(|| {
        // SAFETY: the caller's contract (see # Safety).
        let buf = unsafe { slice_out(out, out_cap, out_needed, &OUT) }?;
        let e = triangle_elevation_matrix(m, n)?;
        checked_len(tri_count(n), tri_count(m), "matrix size")?;
        buf.copy_from(&e)
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reduce_round_trip_and_statuses() {
        // Degree-2 1-D interval triangle reduced to degree 1.
        let lo = [0.0, 1.0, 0.0, 2.0, 1.0, 0.0];
        let hi = [1.0, 2.0, 1.0, 3.0, 2.0, 1.0];
        let mut p = std::ptr::null_mut();
        let mut q = std::ptr::null_mut();
        let mut rep = CagdIntervalReport {
            thickness_in: 0.0,
            thickness_out: 0.0,
            ratio: 0.0,
            n_coupled: 0,
            repair: 0.0,
            max_violation: 0.0,
            containment_degree: 0,
            objective: 0.0,
            objective_decoupled: 0.0,
        };
        let mut contains = false;
        // SAFETY: valid pointers of the documented sizes; handles freed once.
        unsafe {
            assert_eq!(
                cagd_intervaltri_new(lo.as_ptr(), hi.as_ptr(), 2, 1, &mut p),
                CagdStatus::OK
            );
            assert_eq!(
                cagd_intervaltri_reduce(p, 1, 0, &mut q, &mut rep),
                CagdStatus::OK
            );
            assert_eq!(
                cagd_intervaltri_contains(q, p, 0, &mut contains),
                CagdStatus::OK
            );
            assert!(contains);
            assert_eq!(
                cagd_intervaltri_reduce(p, 2, 0, &mut q, &mut rep),
                CagdStatus::ERR_BAD_DEGREE_PAIR
            );
            let bad = [0.0, 1.0, 5.0, 2.0, 1.0, 0.0];
            let mut r = std::ptr::null_mut();
            assert_eq!(
                cagd_intervaltri_new(bad.as_ptr(), hi.as_ptr(), 2, 1, &mut r),
                CagdStatus::ERR_EMPTY_INTERVAL
            );
            assert!(r.is_null());
            cagd_intervaltri_free(q);
            cagd_intervaltri_free(p);
        }
        assert_eq!(rep.thickness_in, 1.0);
        assert!(rep.thickness_out >= 1.0 && rep.max_violation <= 0.0);
        assert_eq!(rep.containment_degree, 2);
    }
}
