//! `CagdReduceMethod`, `CagdErrorSpace` and `CagdReduceOptions`: how a reduction is asked
//! for from C, and their translation to `cagd_reduce::ReduceOptions`.

use cagd_reduce::{ErrorSpace, Method, ReduceOptions};

use crate::boundary::{CResult, Failure, boundary, out_ref};
use crate::status::CagdStatus;

/// The degree-reduction methods (cagd-reduce `Method`; seed 000 chapter 14 and the
/// classical methods it cites). Stored in `CagdReduceOptions.method` as an `int32_t`.
///
/// cbindgen:rename-all=prefix:CAGD_
#[repr(i32)]
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[allow(
    non_camel_case_types,
    reason = "C names: the variants become CAGD_METHOD_*"
)]
pub enum CagdReduceMethod {
    /// Forrest's one-degree reduction, applied stepwise; interpolates derivatives up to
    /// order `floor((m - 1) / 2)` at both ends.
    METHOD_FORREST = 0,
    /// Piegl–Tiller one-degree reduction (equal to Forrest, own formula).
    METHOD_PIEGL_TILLER = 1,
    /// Farin's one-degree reduction; interpolates the end points; needs `m >= 1`.
    METHOD_FARIN = 2,
    /// Control-point perturbation with fixed ends (seed 000 §14.2.1); needs `m >= 1`.
    METHOD_PERTURB = 3,
    /// Perturbation with G1 ends and the given `l1`, `l2` (seed 000 §14.2.3); needs
    /// `m >= 3`, `1 + l1 > 0`, `1 + l2 > 0`.
    METHOD_PERTURB_G1 = 4,
    /// Eck's one-degree reduction (Chebyshev economisation, best uniform for one degree).
    METHOD_ECK = 5,
    /// Watkins–Worsey Chebyshev truncation (multi-degree).
    METHOD_WATKINS_WORSEY = 6,
    /// Bogacki–Weinstein–Xu near-best uniform multi-degree reduction, ends free.
    METHOD_BOGACKI_WEINSTEIN_XU = 7,
    /// Generalized-inverse (L2-best) reduction without end constraints (seed 000 §14.4.1).
    METHOD_GENERALIZED_INVERSE = 8,
    /// Generalized-inverse reduction with interpolated end points (seed 000 §14.4.2);
    /// needs `m >= 1`.
    METHOD_GENERALIZED_INVERSE_ENDS = 9,
    /// Constrained Chebyshev reduction keeping derivatives `0..=r` at t = 0 and `0..=p` at
    /// t = 1 (seed 000 §14.5); needs `r + p + 1 <= m`.
    METHOD_CONSTRAINED_CHEBYSHEV = 10,
    /// L2-optimal reduction with `C^(r,p)` end constraints; needs `r + p + 1 <= m`.
    METHOD_L2 = 11,
}

/// The space in which a reduction report's error numbers are measured (matters for
/// rational curves only). Stored in `CagdReduceOptions.space` as an `int32_t`.
///
/// cbindgen:rename-all=prefix:CAGD_
#[repr(i32)]
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[allow(
    non_camel_case_types,
    reason = "C names: the variants become CAGD_SPACE_*"
)]
pub enum CagdErrorSpace {
    /// `max_t |P(t) - Q(t)|` of the Euclidean curves.
    SPACE_EUCLIDEAN = 0,
    /// The same maximum for the homogeneous curves `(wP, w)`, `(vQ, v)`.
    SPACE_HOMOGENEOUS = 1,
}

/// How to reduce: a plain struct the caller owns. Fill it with
/// `cagd_reduce_options_init`, then change the fields you need.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CagdReduceOptions {
    /// A `CagdReduceMethod` value (an `int32_t`, so that any value a caller stores is
    /// checked rather than undefined). Default `CAGD_METHOD_CONSTRAINED_CHEBYSHEV`.
    pub method: i32,
    /// The target degree `m`, below the source degree. Default 3.
    pub target: usize,
    /// Highest derivative order kept at t = 0 for `CAGD_METHOD_CONSTRAINED_CHEBYSHEV` and
    /// `CAGD_METHOD_L2`, `-1` for none. Ignored by the other methods. Default 0 (the end
    /// point is kept, so joints stay connected).
    pub r: i32,
    /// Highest derivative order kept at t = 1, as `r`. Default 0.
    pub p: i32,
    /// Tangent scale at t = 0 for `CAGD_METHOD_PERTURB_G1` (finite, `> -1`). Default 0.
    pub l1: f64,
    /// Tangent scale at t = 1 for `CAGD_METHOD_PERTURB_G1` (finite, `> -1`). Default 0.
    pub l2: f64,
    /// Also measure the error by dense sampling (costs about 8000 evaluations). Default
    /// false.
    pub measure: bool,
    /// A `CagdErrorSpace` value: the space of the report's numbers. Default
    /// `CAGD_SPACE_EUCLIDEAN`.
    pub space: i32,
}

impl Default for CagdReduceOptions {
    fn default() -> Self {
        Self {
            method: CagdReduceMethod::METHOD_CONSTRAINED_CHEBYSHEV as i32,
            target: 3,
            r: 0,
            p: 0,
            l1: 0.0,
            l2: 0.0,
            measure: false,
            space: CagdErrorSpace::SPACE_EUCLIDEAN as i32,
        }
    }
}

impl CagdReduceOptions {
    /// The cagd-reduce method these options name.
    ///
    /// # Errors
    /// `CAGD_ERR_INVALID_ARGUMENT` for a `method` code that is not a `CagdReduceMethod`.
    pub(crate) fn method(&self) -> CResult<Method> {
        let (r, p, l1, l2) = (self.r, self.p, self.l1, self.l2);
        Ok(match self.method {
            0 => Method::Forrest,
            1 => Method::PieglTiller,
            2 => Method::Farin,
            3 => Method::Perturb,
            4 => Method::PerturbG1 { l1, l2 },
            5 => Method::Eck,
            6 => Method::WatkinsWorsey,
            7 => Method::BogackiWeinsteinXu,
            8 => Method::GeneralizedInverse,
            9 => Method::GeneralizedInverseEnds,
            10 => Method::ConstrainedChebyshev { r, p },
            11 => Method::L2 { r, p },
            other => {
                return Err(Failure::invalid(format!(
                    "opts->method = {other} is not a CagdReduceMethod (0..=11)"
                )));
            }
        })
    }

    /// The cagd-reduce options these options describe.
    ///
    /// # Errors
    /// `CAGD_ERR_INVALID_ARGUMENT` for an unknown `method` or `space` code.
    pub(crate) fn rust_options(&self) -> CResult<ReduceOptions> {
        let space = match self.space {
            0 => ErrorSpace::Euclidean,
            1 => ErrorSpace::Homogeneous,
            other => {
                return Err(Failure::invalid(format!(
                    "opts->space = {other} is not a CagdErrorSpace (0 or 1)"
                )));
            }
        };
        Ok(ReduceOptions {
            measure: self.measure,
            space,
            ..ReduceOptions::new(self.method()?, self.target)
        })
    }
}

/// Fills `opts` with the defaults: `method = CAGD_METHOD_CONSTRAINED_CHEBYSHEV`,
/// `target = 3`, `r = p = 0` (end points kept), `l1 = l2 = 0`, `measure = false`,
/// `space = CAGD_SPACE_EUCLIDEAN`. Call it before setting fields, so that fields added in
/// later versions get their defaults.
///
/// Parameters:
/// - `opts` (out): the struct to fill (caller-owned, e.g. on the stack).
///
/// Returns:
/// - `CAGD_OK`: `*opts` holds the defaults.
/// - `CAGD_ERR_NULL_POINTER`: `opts` is NULL.
/// - `CAGD_ERR_INVALID_ARGUMENT`: `opts` is misaligned.
/// - `CAGD_ERR_PANIC`: internal bug caught at the boundary.
///
/// # Safety
/// `opts` must be NULL or point to a writable `CagdReduceOptions`.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn cagd_reduce_options_init(opts: *mut CagdReduceOptions) -> CagdStatus {
    boundary(|| {
        // SAFETY: the caller's contract (see # Safety).
        *unsafe { out_ref(opts, "opts") }? = CagdReduceOptions::default();
        Ok(())
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn method_codes_are_pinned_and_translate() {
        use CagdReduceMethod as M;
        let all = [
            (M::METHOD_FORREST, 0, "forrest"),
            (M::METHOD_PIEGL_TILLER, 1, "piegl-tiller"),
            (M::METHOD_FARIN, 2, "farin"),
            (M::METHOD_PERTURB, 3, "perturb"),
            (M::METHOD_PERTURB_G1, 4, "perturb-g1"),
            (M::METHOD_ECK, 5, "eck"),
            (M::METHOD_WATKINS_WORSEY, 6, "watkins-worsey"),
            (M::METHOD_BOGACKI_WEINSTEIN_XU, 7, "bogacki-weinstein-xu"),
            (M::METHOD_GENERALIZED_INVERSE, 8, "generalized-inverse"),
            (
                M::METHOD_GENERALIZED_INVERSE_ENDS,
                9,
                "generalized-inverse-ends",
            ),
            (M::METHOD_CONSTRAINED_CHEBYSHEV, 10, "constrained-chebyshev"),
            (M::METHOD_L2, 11, "l2"),
        ];
        for (m, code, name) in all {
            assert_eq!(m as i32, code);
            let opts = CagdReduceOptions {
                method: code,
                ..CagdReduceOptions::default()
            };
            assert_eq!(opts.method().unwrap().name(), name);
        }
        assert_eq!(CagdErrorSpace::SPACE_EUCLIDEAN as i32, 0);
        assert_eq!(CagdErrorSpace::SPACE_HOMOGENEOUS as i32, 1);
        for bad in [-1, 12, i32::MAX] {
            let opts = CagdReduceOptions {
                method: bad,
                ..CagdReduceOptions::default()
            };
            assert_eq!(
                opts.method().unwrap_err().status,
                CagdStatus::ERR_INVALID_ARGUMENT
            );
        }
    }
}
