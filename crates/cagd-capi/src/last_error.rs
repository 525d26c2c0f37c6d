//! The thread-local message behind `cagd_last_error_message()` (STYLE §9.5).
//!
//! Every entry point that returns a `CagdStatus` sets the message on failure (with the
//! offending value) and clears it on success; `cagd_status_name`, `cagd_last_error_message`
//! and the `_free` functions leave it alone, so a failure can be reported after cleanup.

use std::cell::RefCell;
use std::ffi::{CString, c_char};

thread_local! {
    static LAST_ERROR: RefCell<CString> = RefCell::new(CString::default());
}

/// Stores `message` as this thread's last error (interior NULs become `\0` text).
pub(crate) fn set_last_error(message: &str) {
    let c = CString::new(message.replace('\0', "\\0")).unwrap_or_default();
    LAST_ERROR.with(|m| *m.borrow_mut() = c);
}

/// Clears this thread's last error (no allocation when it is already empty).
pub(crate) fn clear_last_error() {
    LAST_ERROR.with(|m| {
        let mut m = m.borrow_mut();
        if !m.as_bytes().is_empty() {
            *m = CString::default();
        }
    });
}

/// This thread's last error message as an owned string (for Rust tests).
pub fn last_error_string() -> String {
    LAST_ERROR.with(|m| m.borrow().to_string_lossy().into_owned())
}

/// A human-readable description of the last failure of a `cagd_*` function on the calling
/// thread, naming the argument and the offending value (e.g.
/// `"weights[3] = -0.5 must be finite and > 0, not subnormal"`).
///
/// Returns a UTF-8, NUL-terminated string, never NULL; the empty string `""` when the last
/// status-returning call on this thread succeeded or none was made. The string is owned by
/// cagd and stays valid until the next status-returning `cagd_*` call on the same thread
/// (`cagd_status_name`, `cagd_last_error_message` and the `_free` functions do not change
/// it). The caller must not free it. Meant for logs and diagnostics only: program logic
/// should depend on the returned `CagdStatus`, never on this text.
#[unsafe(no_mangle)]
pub extern "C" fn cagd_last_error_message() -> *const c_char {
    LAST_ERROR.with(|m| m.borrow().as_ptr())
}
