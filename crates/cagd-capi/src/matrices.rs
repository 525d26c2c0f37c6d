//! Constant matrices and scalar formulas of the seeds: the uniform B-spline to Bézier matrix
//! `S^(n)` (seed 001), the basis conversion matrices (`CagdBasis`), the perturbation error
//! factor `W_n` and the subdivision count of seed 000 eq. 14.2.11 (corrected).

use cagd_core::{
    Basis, Error, check_degree, from_bernstein, s_matrix, s_matrix_inverse,
    to_bernstein as basis_to_bernstein,
};
use cagd_reduce::{perturbation_error_factor, subdivision_levels};

use crate::boundary::{CResult, Failure, OUT, boundary, out_ref, slice_out};
use crate::status::CagdStatus;

/// The polynomial bases of `cagd_basis_matrix` (cagd-core `Basis`). Passed as an
/// `int32_t`.
///
/// cbindgen:rename-all=prefix:CAGD_
#[repr(i32)]
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[allow(
    non_camel_case_types,
    reason = "C names: the variants become CAGD_BASIS_*"
)]
pub enum CagdBasis {
    /// Monomials `t^k`, `k = 0..=n`.
    BASIS_POWER = 0,
    /// Shifted Chebyshev polynomials `T_k(2t - 1)` (seed 000 Lemma 14.5.3).
    BASIS_CHEBYSHEV = 1,
    /// Shifted Legendre polynomials `P_k(2t - 1)`, `P_k(1) = 1`.
    BASIS_LEGENDRE = 2,
    /// The Said–Ball basis (WSGB with `L = 0`).
    BASIS_SAID_BALL = 3,
    /// The Wang–Ball basis (WSGB with `L = max(floor(n/2) - 1, 0)`).
    BASIS_WANG_BALL = 4,
    /// The Wang–Said generalized Ball basis WSGB(n, L) of seed 003 (SPEC-reduce §9.1),
    /// `0 <= L <= max(floor(n/2) - 1, 0)`, `L` given by `param_l`.
    BASIS_WSGB = 5,
}

/// The cagd-core basis of a `CagdBasis` code (`l` used only for WSGB).
fn basis_of(code: i32, l: usize) -> CResult<Basis> {
    Ok(match code {
        0 => Basis::Power,
        1 => Basis::Chebyshev,
        2 => Basis::Legendre,
        3 => Basis::SaidBall,
        4 => Basis::WangBall,
        5 => Basis::Wsgb { l },
        other => {
            return Err(Failure::invalid(format!(
                "basis = {other} is not a CagdBasis (0..=5)"
            )));
        }
    })
}

/// Copies seed 001's matrix `S^(n)` (uniform B-spline control points of one segment to its
/// Bézier points, seed 001 §4.1), or its inverse `S^(-n)` (seed 001 §4.2), computed once in
/// exact rational arithmetic, rounded once to `f64`, cached process-wide. Row-major
/// `(n + 1) x (n + 1)`: `b_i = sum_j out[i * (n + 1) + j] p_j` (row `i` is Bézier point
/// `i`, column `j` B-spline point `j`). The entries of `S^(-n)` grow fast (largest entry
/// `1.6e106` at `n = 64`): usable in `f64` only for small degrees.
///
/// Parameters:
/// - `n` (in): the degree, `0..=64`.
/// - `inverse` (in): `false` for `S^(n)`, `true` for `S^(-n)`.
/// - `out` (out): buffer of `out_cap` doubles; on `CAGD_OK` its first `(n + 1)^2` doubles
///   hold the matrix. May be NULL only when `out_cap == 0`.
/// - `out_cap` (in): capacity of `out` in doubles.
/// - `out_needed` (out): on `CAGD_OK` and on `CAGD_ERR_BUFFER_TOO_SMALL`, `(n + 1)^2`.
///
/// Returns:
/// - `CAGD_OK`: the matrix is in `out`.
/// - `CAGD_ERR_NULL_POINTER`: `out_needed` is NULL, or `out` is NULL with `out_cap > 0`.
/// - `CAGD_ERR_DEGREE_OUT_OF_RANGE`: `n > 64` (`*out_needed` is not written).
/// - `CAGD_ERR_INVALID_ARGUMENT`: a pointer is misaligned.
/// - `CAGD_ERR_BUFFER_TOO_SMALL`: `out_cap < (n + 1)^2`; only `*out_needed` is written.
/// - `CAGD_ERR_PANIC`: internal bug caught at the boundary.
///
/// # Safety
/// `out` must be NULL or point to `out_cap` writable doubles; `out_needed` NULL or
/// writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_uniform_bspline_matrix(
    n: usize,
    inverse: bool,
    out: *mut f64,
    out_cap: usize,
    out_needed: *mut usize,
) -> CagdStatus {
    boundary(|| {
        // SAFETY: the caller's contract (see # Safety).
        let dst = unsafe { slice_out(out, out_cap, out_needed, &OUT) }?;
        let m = if inverse {
            s_matrix_inverse(n)?
        } else {
            s_matrix(n)?
        };
        dst.copy_from(m)
    })
}

/// Copies the basis conversion matrix of degree `n` between `basis` and the Bernstein
/// basis (cagd_core::to_bernstein / from_bernstein): computed once in exact rational
/// arithmetic, rounded once to `f64`, cached process-wide. With `to_bernstein` the matrix
/// `M` gives Bernstein coefficients `b = M c` from coefficients `c` in `basis`; otherwise
/// its inverse, `c = M^(-1) b`. Row-major `(n + 1) x (n + 1)`: `b_i = sum_j
/// out[i * (n + 1) + j] c_j`. Each entry is correctly rounded; the inverse matrices of the
/// Power, Chebyshev and Legendre bases have large entries at high degree, so converting
/// given coefficients to Bernstein loses accuracy beyond degree ~15.
///
/// Parameters:
/// - `basis` (in): a `CagdBasis` code.
/// - `param_l` (in): the order `L` of `CAGD_BASIS_WSGB`,
///   `0 <= L <= max(floor(n/2) - 1, 0)`; ignored for the other bases.
/// - `n` (in): the degree, `0..=64`.
/// - `to_bernstein` (in): `true` for `M` (basis to Bernstein), `false` for `M^(-1)`.
/// - `out` (out): buffer of `out_cap` doubles; on `CAGD_OK` its first `(n + 1)^2` doubles
///   hold the matrix. May be NULL only when `out_cap == 0`.
/// - `out_cap` (in): capacity of `out` in doubles.
/// - `out_needed` (out): on `CAGD_OK` and on `CAGD_ERR_BUFFER_TOO_SMALL`, `(n + 1)^2`.
///
/// Returns:
/// - `CAGD_OK`: the matrix is in `out`.
/// - `CAGD_ERR_NULL_POINTER`: `out_needed` is NULL, or `out` is NULL with `out_cap > 0`.
/// - `CAGD_ERR_INVALID_ARGUMENT`: `basis` is not a `CagdBasis`, or a pointer is
///   misaligned.
/// - `CAGD_ERR_DEGREE_OUT_OF_RANGE`: `n > 64`.
/// - `CAGD_ERR_CONDITION_NOT_MET`: `CAGD_BASIS_WSGB` with `param_l` outside its range.
/// - `CAGD_ERR_BUFFER_TOO_SMALL`: `out_cap < (n + 1)^2`; only `*out_needed` is written.
/// - `CAGD_ERR_PANIC`: internal bug caught at the boundary.
///
/// # Safety
/// `out` must be NULL or point to `out_cap` writable doubles; `out_needed` NULL or
/// writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_basis_matrix(
    basis: i32,
    param_l: usize,
    n: usize,
    to_bernstein: bool,
    out: *mut f64,
    out_cap: usize,
    out_needed: *mut usize,
) -> CagdStatus {
    boundary(|| {
        // SAFETY: the caller's contract (see # Safety).
        let dst = unsafe { slice_out(out, out_cap, out_needed, &OUT) }?;
        let b = basis_of(basis, param_l)?;
        let m = if to_bernstein {
            basis_to_bernstein(b, n)?
        } else {
            from_bernstein(b, n)?
        };
        let size = n + 1;
        let dst = dst.take(size * size)?;
        for i in 0..size {
            for j in 0..size {
                dst[i * size + j] = m[(i, j)];
            }
        }
        Ok(())
    })
}

/// The perturbation error factor `W_n = max_{t in [0,1]} |w_n(t)|` of seed 000 §14.2.1
/// (SPEC-reduce §2.1, vector `W_n-table`), rounded up so that the certified error of the
/// perturbation reduction, `W_n ||Delta^n P_0|| / (C(2n,n) - 2)`, is an upper bound.
///
/// Parameters:
/// - `n` (in): the source degree, `2..=64`.
/// - `out` (out): on `CAGD_OK`, `W_n`. Not written on failure.
///
/// Returns:
/// - `CAGD_OK`: `*out` holds `W_n`.
/// - `CAGD_ERR_NULL_POINTER`: `out` is NULL.
/// - `CAGD_ERR_DEGREE_OUT_OF_RANGE`: `n > 64`.
/// - `CAGD_ERR_BAD_DEGREE_PAIR`: `n < 2` (the perturbation reduction needs `n >= 2`).
/// - `CAGD_ERR_INVALID_ARGUMENT`: `out` is misaligned.
/// - `CAGD_ERR_PANIC`: internal bug caught at the boundary.
///
/// # Safety
/// `out` must be NULL or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_perturbation_error_factor(n: usize, out: *mut f64) -> CagdStatus {
    boundary(|| {
        // SAFETY: the caller's contract (see # Safety).
        let o = unsafe { out_ref(out, "out") }?;
        check_degree(n)?;
        if n < 2 {
            return Err(Error::BadDegreePair {
                from: n,
                to: n.saturating_sub(1),
                why: "W_n is defined for source degrees n >= 2",
            }
            .into());
        }
        *o = perturbation_error_factor(n);
        Ok(())
    })
}

/// The number `N` of midpoint-subdivision levels after which every piece of a degree-`n`
/// curve with `||Delta^n P_0|| = norm_f` reduces one degree by the perturbation method
/// within `delta` (seed 000 eq. 14.2.11 as corrected in SPEC-reduce §2.2, vector
/// `N-formula-1`): `N = max(0, ceil((1/n) log2(W_n ||F|| / ((C(2n,n) - 2) delta))))`.
///
/// Parameters:
/// - `n` (in): the source degree, `2..=64`.
/// - `norm_f` (in): `||Delta^n P_0||`, finite and `>= 0` (e.g. the Euclidean norm of
///   `cagd_curve_forward_difference`).
/// - `delta` (in): the tolerance, finite and `> 0`.
/// - `out` (out): on `CAGD_OK`, `N`. Not written on failure.
///
/// Returns:
/// - `CAGD_OK`: `*out` holds `N`.
/// - `CAGD_ERR_NULL_POINTER`: `out` is NULL.
/// - `CAGD_ERR_DEGREE_OUT_OF_RANGE`: `n > 64`.
/// - `CAGD_ERR_BAD_DEGREE_PAIR`: `n < 2`.
/// - `CAGD_ERR_INVALID_ARGUMENT`: `delta` not finite and `> 0`, `norm_f` negative or not
///   finite, or `out` misaligned.
/// - `CAGD_ERR_PANIC`: internal bug caught at the boundary.
///
/// # Safety
/// `out` must be NULL or writable.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_subdivision_levels(
    n: usize,
    norm_f: f64,
    delta: f64,
    out: *mut usize,
) -> CagdStatus {
    boundary(|| {
        // SAFETY: the caller's contract (see # Safety).
        let o = unsafe { out_ref(out, "out") }?;
        *o = subdivision_levels(n, norm_f, delta)?;
        Ok(())
    })
}
