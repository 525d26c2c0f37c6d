//! The panic boundary and the typed pointer helpers every entry point uses (STYLE §9.6,
//! §9.8): the rustls-ffi `ffi_panic_boundary!` / `Castable` ideas reduced to what cagd needs.
//!
//! Every status-returning entry point is `boundary(|| { … })`: the closure checks its
//! pointers with the helpers below (NULL → `CAGD_ERR_NULL_POINTER`, before any data is
//! read), computes, and writes its outputs last, so outputs are written only on `CAGD_OK`.
//! A panic is caught and becomes `CAGD_ERR_PANIC`; the thread-local message is set on every
//! failure and cleared on success.

use std::panic::{AssertUnwindSafe, catch_unwind};

use crate::last_error::{clear_last_error, set_last_error};
use crate::status::{CagdStatus, status_of_core};

/// A failure on its way to C: the status and the message for `cagd_last_error_message`.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Failure {
    pub(crate) status: CagdStatus,
    pub(crate) message: String,
}

impl Failure {
    /// A failure with an explicit status.
    pub(crate) fn new(status: CagdStatus, message: impl Into<String>) -> Self {
        Self {
            status,
            message: message.into(),
        }
    }

    /// `CAGD_ERR_NULL_POINTER` naming the argument.
    pub(crate) fn null(name: &str) -> Self {
        Self::new(
            CagdStatus::ERR_NULL_POINTER,
            format!("argument `{name}` is NULL"),
        )
    }

    /// `CAGD_ERR_INVALID_ARGUMENT` with a message.
    pub(crate) fn invalid(message: impl Into<String>) -> Self {
        Self::new(CagdStatus::ERR_INVALID_ARGUMENT, message)
    }
}

impl From<cagd_core::Error> for Failure {
    fn from(e: cagd_core::Error) -> Self {
        Self::new(status_of_core(&e), e.to_string())
    }
}

/// Result type of the closures run by [`boundary`].
pub(crate) type CResult<T> = Result<T, Failure>;

/// Runs an entry point's body: catches panics (`CAGD_ERR_PANIC`), sets the thread-local
/// message on failure and clears it on success.
pub(crate) fn boundary(f: impl FnOnce() -> CResult<()>) -> CagdStatus {
    match catch_unwind(AssertUnwindSafe(f)) {
        Ok(Ok(())) => {
            clear_last_error();
            CagdStatus::OK
        }
        Ok(Err(failure)) => {
            set_last_error(&failure.message);
            failure.status
        }
        Err(payload) => {
            let what = payload
                .downcast_ref::<&str>()
                .map(|s| (*s).to_owned())
                .or_else(|| payload.downcast_ref::<String>().cloned())
                .unwrap_or_else(|| "non-string panic payload".to_owned());
            set_last_error(&format!(
                "internal error in cagd (Rust panic: {what}); please report it"
            ));
            CagdStatus::ERR_PANIC
        }
    }
}

/// Runs a function that returns nothing (the `_free` functions): a panic is swallowed,
/// because it must not unwind into C, and the message is left unchanged.
pub(crate) fn boundary_void(f: impl FnOnce()) {
    let _ignored = catch_unwind(AssertUnwindSafe(f));
}

/// Borrows a handle; NULL → `CAGD_ERR_NULL_POINTER` naming the argument.
///
/// # Safety
/// `ptr` must be NULL or point to a live `T` that stays valid and unmodified for `'a`.
pub(crate) unsafe fn handle_ref<'a, T>(ptr: *const T, name: &str) -> CResult<&'a T> {
    if !ptr.is_aligned() {
        return Err(Failure::invalid(format!(
            "argument `{name}` is not a pointer cagd returned (misaligned)"
        )));
    }
    // SAFETY: non-NULL and aligned checked; validity is the caller's contract.
    unsafe { ptr.as_ref() }.ok_or_else(|| Failure::null(name))
}

/// `a * b` for a buffer length, or `CAGD_ERR_INVALID_ARGUMENT` when it overflows or the
/// buffer of doubles could not exist.
pub(crate) fn checked_len(a: usize, b: usize, what: &str) -> CResult<usize> {
    a.checked_mul(b)
        .filter(|n| *n <= isize::MAX as usize / size_of::<f64>())
        .ok_or_else(|| Failure::invalid(format!("{what}: {a} * {b} doubles overflows")))
}

/// Borrows `len` doubles of caller input (copied by the caller of this helper if kept).
/// NULL → `CAGD_ERR_NULL_POINTER` (also when `len == 0`).
///
/// # Safety
/// `ptr` must be NULL or point to `len` readable, initialised doubles valid for `'a`.
pub(crate) unsafe fn slice_in<'a>(ptr: *const f64, len: usize, name: &str) -> CResult<&'a [f64]> {
    if ptr.is_null() {
        return Err(Failure::null(name));
    }
    if !ptr.is_aligned() {
        return Err(Failure::invalid(format!(
            "argument `{name}` is not aligned for double"
        )));
    }
    checked_len(len, 1, name)?;
    // SAFETY: non-NULL, aligned, length fits isize; readability is the caller's contract.
    Ok(unsafe { std::slice::from_raw_parts(ptr, len) })
}

/// Borrows a scalar or handle out-parameter; NULL → `CAGD_ERR_NULL_POINTER`. Write it only
/// after everything that can fail has succeeded.
///
/// # Safety
/// `ptr` must be NULL or point to a writable `T` valid for `'a`.
pub(crate) unsafe fn out_ref<'a, T>(ptr: *mut T, name: &str) -> CResult<&'a mut T> {
    if !ptr.is_aligned() {
        return Err(Failure::invalid(format!(
            "argument `{name}` is not aligned for its type"
        )));
    }
    // SAFETY: aligned checked; NULL handled by as_mut; writability is the caller's contract.
    unsafe { ptr.as_mut() }.ok_or_else(|| Failure::null(name))
}

/// Names of a buffer output's arguments, for messages.
pub(crate) struct OutNames {
    /// The buffer, e.g. `"out"`.
    pub(crate) out: &'static str,
    /// Its capacity, e.g. `"out_cap"`.
    pub(crate) cap: &'static str,
    /// The size output, e.g. `"out_needed"`.
    pub(crate) needed: &'static str,
}

/// The usual names `out` / `out_cap` / `out_needed`.
pub(crate) const OUT: OutNames = OutNames {
    out: "out",
    cap: "out_cap",
    needed: "out_needed",
};

/// A checked caller buffer (`out`, `out_cap`, `out_needed`) of `T` (`f64` for every
/// double array; `i32` for the few integer arrays) not yet written.
pub(crate) struct SliceOut<'a, T> {
    out: *mut T,
    cap: usize,
    needed_out: &'a mut usize,
    names: &'a OutNames,
}

/// Checks a caller buffer's pointers up front (STYLE §9.7): `needed_out` NULL →
/// `CAGD_ERR_NULL_POINTER`; `out` NULL with `cap > 0` → `CAGD_ERR_NULL_POINTER`; `out`
/// misaligned → `CAGD_ERR_INVALID_ARGUMENT`. Nothing is written until [`SliceOut::take`].
///
/// # Safety
/// `needed_out` must be NULL or writable; `out` must be NULL or point to `cap` writable
/// `T`, both valid for `'a`.
pub(crate) unsafe fn slice_out<'a, T: Copy>(
    out: *mut T,
    cap: usize,
    needed_out: *mut usize,
    names: &'a OutNames,
) -> CResult<SliceOut<'a, T>> {
    // SAFETY: forwarded contract.
    let needed_out = unsafe { out_ref(needed_out, names.needed) }?;
    if out.is_null() && cap != 0 {
        return Err(Failure::new(
            CagdStatus::ERR_NULL_POINTER,
            format!(
                "argument `{}` is NULL but `{}` = {cap} (NULL is allowed only with capacity 0, \
                 to query the size)",
                names.out, names.cap
            ),
        ));
    }
    if !out.is_aligned() {
        return Err(Failure::invalid(format!(
            "argument `{}` is not aligned for its element type",
            names.out
        )));
    }
    Ok(SliceOut {
        out,
        cap,
        needed_out,
        names,
    })
}

impl<'a, T: Copy> SliceOut<'a, T> {
    /// Writes `needed` to `*out_needed` and returns the first `needed` elements of the
    /// buffer, or, when `cap < needed`, writes `needed` and fails with
    /// `CAGD_ERR_BUFFER_TOO_SMALL` (so capacity 0 is a size query). Call it after every
    /// check that can fail, and fill the returned slice completely.
    pub(crate) fn take(self, needed: usize) -> CResult<&'a mut [T]> {
        *self.needed_out = needed;
        if self.cap < needed {
            return Err(Failure::new(
                CagdStatus::ERR_BUFFER_TOO_SMALL,
                format!(
                    "`{}` = {} is too small: {needed} needed (written to `{}`)",
                    self.names.cap, self.cap, self.names.needed
                ),
            ));
        }
        if needed == 0 {
            return Ok(&mut []);
        }
        // SAFETY: non-NULL (cap >= needed > 0) and aligned, checked in `slice_out`; `needed
        // <= cap` writable elements by the caller's contract; the length fits isize since
        // the memory exists.
        Ok(unsafe { std::slice::from_raw_parts_mut(self.out, needed) })
    }

    /// [`SliceOut::take`] of `data.len()` elements, then copies `data` in. A value that
    /// is not finite (an overflow in the computation, e.g. evaluating far outside the
    /// domain) fails with `CAGD_ERR_NON_FINITE` before anything is written, `*out_needed`
    /// included: the C ABI never hands out NaN or infinity as a result (issue 18, "no
    /// silent garbage"; found by the fuzz harness of fuzz/capi).
    pub(crate) fn copy_from(self, data: &[T]) -> CResult<()>
    where
        T: OutValue,
    {
        check_finite_out(data, self.names.out)?;
        self.take(data.len())?.copy_from_slice(data);
        Ok(())
    }

    /// [`SliceOut::take`] of `needed` elements filled by `fill` in a scratch buffer first,
    /// copied to the caller only when every value is finite (as [`SliceOut::copy_from`]).
    /// For entry points that write in place (evaluations).
    pub(crate) fn fill_with(self, needed: usize, fill: impl FnOnce(&mut [T])) -> CResult<()>
    where
        T: OutValue + Default,
    {
        let mut scratch = vec![T::default(); needed];
        fill(&mut scratch);
        self.copy_from(&scratch)
    }
}

/// An element type of a caller buffer: `f64` (checked finite) or an integer.
pub(crate) trait OutValue: Copy {
    /// Whether the value may be handed to C (`f64`: finite).
    fn is_valid_out(&self) -> bool;
}

impl OutValue for f64 {
    fn is_valid_out(&self) -> bool {
        self.is_finite()
    }
}

impl OutValue for i32 {
    fn is_valid_out(&self) -> bool {
        true
    }
}

/// `CAGD_ERR_NON_FINITE` naming the first output value that is NaN or infinite.
pub(crate) fn check_finite_out<T: OutValue>(data: &[T], name: &str) -> CResult<()> {
    match data.iter().position(|v| !v.is_valid_out()) {
        None => Ok(()),
        Some(i) => Err(Failure::new(
            CagdStatus::ERR_NON_FINITE,
            format!(
                "`{name}`: result value {i} is not finite (the computation overflowed f64); \
                 nothing was written"
            ),
        )),
    }
}

/// A scalar result for C: `CAGD_ERR_NON_FINITE` naming it when NaN or infinite.
pub(crate) fn finite_scalar(value: f64, name: &str) -> CResult<f64> {
    if value.is_finite() {
        Ok(value)
    } else {
        Err(Failure::new(
            CagdStatus::ERR_NON_FINITE,
            format!("`{name}` = {value} is not finite (the computation overflowed f64)"),
        ))
    }
}

/// Rejects two output buffers whose written ranges (`a_len` elements of `A` at `a`,
/// `b_len` of `B` at `b`) would overlap: `CAGD_ERR_INVALID_ARGUMENT` naming `what`.
pub(crate) fn disjoint<A, B>(
    a: *const A,
    a_len: usize,
    b: *const B,
    b_len: usize,
    what: &str,
) -> CResult<()> {
    let (a0, b0) = (a.addr(), b.addr());
    let a1 = a0.saturating_add(a_len.saturating_mul(size_of::<A>()));
    let b1 = b0.saturating_add(b_len.saturating_mul(size_of::<B>()));
    if a_len > 0 && b_len > 0 && a0 < b1 && b0 < a1 {
        Err(Failure::invalid(format!("{what} overlap")))
    } else {
        Ok(())
    }
}

/// Checks that a pointer argument is not NULL (used to reject every NULL before any other
/// check, so that the status does not depend on argument order).
pub(crate) fn nonnull<T>(ptr: *const T, name: &str) -> CResult<()> {
    if ptr.is_null() {
        Err(Failure::null(name))
    } else {
        Ok(())
    }
}

/// Borrows a point buffer of `n_points × dim` doubles: `dim == 0` →
/// `CAGD_ERR_INVALID_ARGUMENT` (as cagd-core's `ZeroDimension`), overflow →
/// `CAGD_ERR_INVALID_ARGUMENT`, then [`slice_in`].
///
/// # Safety
/// As [`slice_in`] with `len = n_points * dim`.
pub(crate) unsafe fn points_in<'a>(
    ptr: *const f64,
    n_points: usize,
    dim: usize,
    name: &str,
) -> CResult<&'a [f64]> {
    nonnull(ptr, name)?;
    if dim == 0 {
        return Err(cagd_core::Error::ZeroDimension.into());
    }
    let len = checked_len(n_points, dim, "n_points * dim")?;
    // SAFETY: forwarded contract.
    unsafe { slice_in(ptr, len, name) }
}

/// Moves a value to the heap and returns the owning raw pointer (a handle); release it with
/// [`free_handle`].
pub(crate) fn into_handle<T>(value: T) -> *mut T {
    Box::into_raw(Box::new(value))
}

/// Releases a handle made by [`into_handle`]; NULL is a no-op.
///
/// # Safety
/// `ptr` must be NULL or a pointer returned by [`into_handle`] for the same `T`, not
/// released before.
pub(crate) unsafe fn free_handle<T>(ptr: *mut T) {
    if !ptr.is_null() {
        // SAFETY: by the contract, ptr came from Box::into_raw and is released once.
        drop(unsafe { Box::from_raw(ptr) });
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::last_error::last_error_string;

    #[test]
    fn panic_becomes_status_and_message() {
        let s = boundary(|| panic!("boom {}", 42));
        assert_eq!(s, CagdStatus::ERR_PANIC);
        assert!(last_error_string().contains("boom 42"));
        assert_eq!(boundary(|| Ok(())), CagdStatus::OK);
        assert_eq!(last_error_string(), "");
    }

    #[test]
    fn core_error_keeps_value_in_message() {
        let s = boundary(|| {
            Err(cagd_core::Error::NonPositiveWeight {
                index: 3,
                weight: -0.5,
            }
            .into())
        });
        assert_eq!(s, CagdStatus::ERR_NON_POSITIVE_WEIGHT);
        assert_eq!(
            last_error_string(),
            "weights[3] = -0.5 must be finite and > 0, not subnormal"
        );
    }

    /// `copy_from` through `slice_out`, as the entry points use it.
    fn copy<T: OutValue>(data: &[T], out: *mut T, cap: usize, needed: *mut usize) -> CResult<()> {
        // SAFETY: the tests pass pointers to locals of the stated sizes, or NULL.
        unsafe { slice_out(out, cap, needed, &OUT) }?.copy_from(data)
    }

    /// Regression (fuzz harness, issue 18): a non-finite result is refused with
    /// `CAGD_ERR_NON_FINITE`, and neither the buffer nor `*out_needed` is written.
    #[test]
    fn copy_from_refuses_non_finite_values() {
        for bad in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
            let data = [1.0, bad, 3.0];
            let mut buf = [9.0; 4];
            let mut needed = 7usize;
            let r = copy(&data, buf.as_mut_ptr(), 4, &mut needed);
            let f = r.unwrap_err();
            assert_eq!(f.status, CagdStatus::ERR_NON_FINITE);
            assert!(f.message.contains("value 1"), "{}", f.message);
            assert_eq!((needed, buf), (7, [9.0; 4]));
        }
        let mut needed = 0usize;
        copy(
            &[1.0, -0.0, 1e-320, f64::MAX],
            std::ptr::null_mut(),
            0,
            &mut needed,
        )
        .unwrap_err();
        assert_eq!(needed, 4, "extreme finite values pass");
        assert_eq!(
            finite_scalar(f64::NAN, "x").unwrap_err().status,
            CagdStatus::ERR_NON_FINITE
        );
        assert_eq!(finite_scalar(-0.0, "x").unwrap(), 0.0);
    }

    #[test]
    fn slice_out_size_query_and_short_buffer() {
        let data = [1.0, 2.0, 3.0];
        let mut needed = 0usize;
        let r = copy(&data, std::ptr::null_mut(), 0, &mut needed);
        assert_eq!(r.unwrap_err().status, CagdStatus::ERR_BUFFER_TOO_SMALL);
        assert_eq!(needed, 3);
        let mut buf = [9.0; 2];
        needed = 0;
        let r = copy(&data, buf.as_mut_ptr(), 2, &mut needed);
        assert_eq!(r.unwrap_err().status, CagdStatus::ERR_BUFFER_TOO_SMALL);
        assert_eq!((needed, buf), (3, [9.0, 9.0]));
        let mut buf = [9.0; 4];
        copy(&data, buf.as_mut_ptr(), 4, &mut needed).unwrap();
        assert_eq!(buf, [1.0, 2.0, 3.0, 9.0]);
        needed = 7;
        let r = copy(&data, std::ptr::null_mut(), 4, &mut needed);
        assert_eq!(r.unwrap_err().status, CagdStatus::ERR_NULL_POINTER);
        assert_eq!(needed, 7, "nothing written on a NULL buffer");
        let r = copy(&data, buf.as_mut_ptr(), 4, std::ptr::null_mut());
        assert_eq!(r.unwrap_err().status, CagdStatus::ERR_NULL_POINTER);
    }

    #[test]
    fn slice_out_of_integers() {
        let mut buf = [7i32; 3];
        let mut needed = 0usize;
        let r = copy(&[1i32, 2, 3], buf.as_mut_ptr(), 2, &mut needed);
        assert_eq!(r.unwrap_err().status, CagdStatus::ERR_BUFFER_TOO_SMALL);
        assert_eq!((needed, buf), (3, [7, 7, 7]));
        copy(&[1i32, 2, 3], buf.as_mut_ptr(), 3, &mut needed).unwrap();
        assert_eq!(buf, [1, 2, 3]);
    }

    #[test]
    fn disjoint_counts_the_bytes_of_each_type() {
        let mut buf = [0.0f64; 4];
        let p = buf.as_mut_ptr();
        let q = p.cast::<i32>();
        // one double at bytes 0..8, one int at bytes 8..12: disjoint
        assert!(disjoint(p, 1, q.wrapping_add(2), 1, "x").is_ok());
        // two doubles cover bytes 0..16
        let e = disjoint(p, 2, q.wrapping_add(2), 1, "`a` and `b`").unwrap_err();
        assert_eq!(e.status, CagdStatus::ERR_INVALID_ARGUMENT);
        assert!(e.message.contains("`a` and `b` overlap"));
        assert!(disjoint(q.wrapping_add(3), 1, p, 2, "x").is_err());
        // nothing written: never an overlap
        assert!(disjoint(p, 0, q, 5, "x").is_ok());
    }

    #[test]
    fn overflowing_length_is_invalid() {
        assert_eq!(
            checked_len(usize::MAX, 2, "points").unwrap_err().status,
            CagdStatus::ERR_INVALID_ARGUMENT
        );
        assert_eq!(checked_len(4, 3, "points"), Ok(12));
    }
}
