//! The size limits of the command's input, enforced by the readers so that any input is
//! refused with a named error or answered in bounded time and memory (issue 18; beyond the
//! seeds). Documented in the README's command section and in `cagd --help`.
//!
//! The library bounds the work of every algorithm on an accepted input (degrees `<=`
//! [`cagd_core::MAX_DEGREE`], capped subdivision and fit rounds); these limits bound what
//! the readers themselves hold: the bytes read, the objects of one input, the control
//! points of one object and of the whole input. JSON nesting is bounded by the parser
//! (depth 128, a named "recursion limit exceeded" error).

/// The largest input, in bytes (a file or stdin): 32 MiB (parsed, at most about 16 M JSON
/// values of 32 bytes each).
pub(crate) const MAX_INPUT_BYTES: u64 = 32 << 20;

/// The most objects in one input array.
pub(crate) const MAX_OBJECTS: usize = 10_000;

/// The most control points (or knots, or numbers in one list) in one object.
pub(crate) const MAX_POINTS: usize = 100_000;

/// The most coordinates of one point.
pub(crate) const MAX_DIM: usize = 64;

/// The most control points of all objects of one input together.
pub(crate) const MAX_TOTAL_POINTS: usize = 1_000_000;

/// The largest degree (or WSGB `L`) a reader accepts: the library's
/// [`cagd_core::MAX_DEGREE`], checked at the reader so that the counts derived from a degree
/// (`(n + 1)(n + 2) / 2` points, `n_points + degree + 1` knots) cannot overflow.
pub(crate) const MAX_DEGREE: usize = cagd_core::MAX_DEGREE;

/// The depth limit of a Bézier curve reduced to a tolerance (`reduce --tol` on a
/// `"bezier"`): no piece shorter than 2^-14 of the parameter range, so at most
/// 2^14 + 1 = 16385 pieces (the library allows 2^20, minutes of work;
/// the fuzzer found a degree-8 curve to degree 1 within 1e-9 that ran for minutes). WSGB
/// curves have the library's own limit of 2^10 pieces (`cagd_reduce::MAX_WSGB_PIECES`).
pub(crate) const MAX_TOLERANCE_DEPTH: usize = 14;

/// One sentence per limit, for `cagd --help` and the README.
pub(crate) const LIMITS_TEXT: &str = "\
Input limits (larger inputs are refused, exit 2, naming the field): 32 MiB per input file or
stdin; 10000 objects per input array; 100000 control points (knots, weights, numbers of one
list) per object and 1000000 in one input; 64 coordinates per point; degrees (and WSGB L)
<= 64; JSON nesting depth 128. A Bezier curve reduced to a tolerance is cut into
pieces no shorter than 2^-14 of its parameter range, at most 16385 (a WSGB curve 1024 pieces); other reduction work is bounded by the library (subdivision depth, fit
rounds and piece counts capped). A reduction that reaches a cap is refused, naming it.
";

/// Refuses an input of `len` bytes above [`MAX_INPUT_BYTES`]; `what` names the file.
pub(crate) fn check_input_size(len: u64, what: &str) -> Result<(), String> {
    if len > MAX_INPUT_BYTES {
        Err(format!(
            "{what}: input larger than the limit of {MAX_INPUT_BYTES} bytes"
        ))
    } else {
        Ok(())
    }
}
