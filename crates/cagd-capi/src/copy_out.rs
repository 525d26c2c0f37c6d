//! Copying a result of unknown size into several caller buffers in one call (STYLE §9.7,
//! DESIGN.md "Variable-length output", for every array of a result at once): each buffer
//! comes with its capacity; one call with every capacity 0 asks all the sizes; a buffer
//! too small fails with `CAGD_ERR_BUFFER_TOO_SMALL` and writes nothing but the sizes.

use crate::boundary::{CResult, Failure, disjoint};
use crate::status::CagdStatus;

/// One caller buffer and the data it is to receive.
pub(crate) struct OutArray<'a, T> {
    ptr: *mut T,
    cap: usize,
    data: &'a [T],
    name: &'static str,
}

impl<'a, T: Copy> OutArray<'a, T> {
    /// The buffer `ptr` of `cap` elements (named `name`, e.g. `"points_out"`, whose
    /// capacity is `<name>_cap`), to receive `data`.
    pub(crate) fn new(ptr: *mut T, cap: usize, data: &'a [T], name: &'static str) -> Self {
        Self {
            ptr,
            cap,
            data,
            name,
        }
    }
}

/// What [`copy_all`] needs of a buffer, whatever its element type.
pub(crate) trait Dst {
    /// NULL with a capacity → `CAGD_ERR_NULL_POINTER`; misaligned →
    /// `CAGD_ERR_INVALID_ARGUMENT`.
    fn check(&self) -> CResult<()>;
    /// Whether the data fits.
    fn fits(&self) -> bool;
    /// `(name, capacity, needed)` for messages.
    fn describe(&self) -> (&'static str, usize, usize);
    /// `(address, bytes)` of the range that will be written.
    fn span(&self) -> (*const u8, usize);
    /// Copies the data in.
    ///
    /// # Safety
    /// `check` and `fits` passed, and the caller's contract: `cap` writable elements.
    unsafe fn write(&self);
}

impl<T: Copy> Dst for OutArray<'_, T> {
    fn check(&self) -> CResult<()> {
        if self.ptr.is_null() && self.cap != 0 {
            return Err(Failure::new(
                CagdStatus::ERR_NULL_POINTER,
                format!(
                    "argument `{}` is NULL but `{}_cap` = {} (NULL is allowed only with \
                     capacity 0)",
                    self.name, self.name, self.cap
                ),
            ));
        }
        if !self.ptr.is_aligned() {
            return Err(Failure::invalid(format!(
                "argument `{}` is not aligned for its element type",
                self.name
            )));
        }
        Ok(())
    }

    fn fits(&self) -> bool {
        self.cap >= self.data.len()
    }

    fn describe(&self) -> (&'static str, usize, usize) {
        (self.name, self.cap, self.data.len())
    }

    fn span(&self) -> (*const u8, usize) {
        (self.ptr.cast_const().cast(), size_of_val(self.data))
    }

    unsafe fn write(&self) {
        if !self.data.is_empty() {
            // SAFETY: non-NULL (cap >= len > 0 with `check`), aligned, `len <= cap`
            // writable elements by the caller's contract; the source is our own memory.
            unsafe { std::slice::from_raw_parts_mut(self.ptr, self.data.len()) }
                .copy_from_slice(self.data);
        }
    }
}

/// Copies every array of a result: checks every buffer, then calls `write_sizes` (so the
/// sizes are written on `CAGD_OK` and on `CAGD_ERR_BUFFER_TOO_SMALL`), fails with
/// `CAGD_ERR_BUFFER_TOO_SMALL` naming every short buffer, rejects overlapping buffers
/// (`CAGD_ERR_INVALID_ARGUMENT`), and only then writes the arrays.
///
/// # Safety
/// Each buffer's pointer must be NULL or point to its capacity of writable elements.
pub(crate) unsafe fn copy_all(arrays: &[&dyn Dst], write_sizes: impl FnOnce()) -> CResult<()> {
    for a in arrays {
        a.check()?;
    }
    write_sizes();
    let short: Vec<String> = arrays
        .iter()
        .filter(|a| !a.fits())
        .map(|a| {
            let (name, cap, needed) = a.describe();
            format!("`{name}_cap` = {cap} < {needed}")
        })
        .collect();
    if !short.is_empty() {
        return Err(Failure::new(
            CagdStatus::ERR_BUFFER_TOO_SMALL,
            format!(
                "buffers too small (the sizes are written to `sizes_out`): {}",
                short.join(", ")
            ),
        ));
    }
    for (i, a) in arrays.iter().enumerate() {
        for b in &arrays[i + 1..] {
            let ((pa, la), (pb, lb)) = (a.span(), b.span());
            let what = format!("`{}` and `{}`", a.describe().0, b.describe().0);
            disjoint(pa, la, pb, lb, &what)?;
        }
    }
    for a in arrays {
        // SAFETY: checked above; the caller's contract.
        unsafe { a.write() };
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn size_query_short_buffer_overlap_and_copy() {
        let (xs, ns) = ([1.0, 2.0, 3.0], [7usize, 8]);
        let mut sizes = 0;
        let mut set = |v| sizes = v;
        // Size query: every capacity 0.
        let a = OutArray::new(std::ptr::null_mut(), 0, &xs, "points_out");
        let b = OutArray::new(std::ptr::null_mut(), 0, &ns, "degrees_out");
        // SAFETY: NULL buffers of capacity 0.
        let e = unsafe { copy_all(&[&a, &b], || set(5)) }.unwrap_err();
        assert_eq!(e.status, CagdStatus::ERR_BUFFER_TOO_SMALL);
        assert!(
            e.message.contains("`points_out_cap` = 0 < 3"),
            "{}",
            e.message
        );
        assert!(
            e.message.contains("`degrees_out_cap` = 0 < 2"),
            "{}",
            e.message
        );
        assert_eq!(sizes, 5);
        // One short buffer: nothing written.
        let (mut pb, mut nb) = ([0.0; 3], [0usize; 1]);
        let a = OutArray::new(pb.as_mut_ptr(), 3, &xs, "points_out");
        let b = OutArray::new(nb.as_mut_ptr(), 1, &ns, "degrees_out");
        // SAFETY: locals of the stated capacities.
        let e = unsafe { copy_all(&[&a, &b], || {}) }.unwrap_err();
        assert_eq!(e.status, CagdStatus::ERR_BUFFER_TOO_SMALL);
        assert_eq!((pb, nb), ([0.0; 3], [0]));
        // NULL with a capacity.
        let a = OutArray::new(std::ptr::null_mut(), 3, &xs, "points_out");
        // SAFETY: as above.
        let e = unsafe { copy_all(&[&a], || {}) }.unwrap_err();
        assert_eq!(e.status, CagdStatus::ERR_NULL_POINTER);
        // Overlap.
        let mut big = [0.0; 6];
        let a = OutArray::new(big.as_mut_ptr(), 3, &xs, "points_out");
        let b = OutArray::new(big.as_mut_ptr().wrapping_add(2), 3, &xs, "weights_out");
        // SAFETY: both inside `big`.
        let e = unsafe { copy_all(&[&a, &b], || {}) }.unwrap_err();
        assert_eq!(e.status, CagdStatus::ERR_INVALID_ARGUMENT);
        assert_eq!(big, [0.0; 6]);
        // Success.
        let (mut pb, mut nb) = ([0.0; 4], [0usize; 2]);
        let a = OutArray::new(pb.as_mut_ptr(), 4, &xs, "points_out");
        let b = OutArray::new(nb.as_mut_ptr(), 2, &ns, "degrees_out");
        // SAFETY: locals of the stated capacities.
        unsafe { copy_all(&[&a, &b], || {}) }.unwrap();
        assert_eq!((pb, nb), ([1.0, 2.0, 3.0, 0.0], [7, 8]));
    }
}
