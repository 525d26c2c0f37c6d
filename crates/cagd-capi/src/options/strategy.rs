//! The translation of `CagdReduceOptions` (its `spline_strategy`, a `CagdSplineStrategy`
//! code) to cagd-reduce's `BSplineOptions` and `SurfaceFitOptions`.

use cagd_reduce::{BSplineOptions, BSplineStrategy, SurfaceFitOptions};

use super::CagdReduceOptions;
use crate::boundary::{CResult, Failure};

/// The options of `cagd_bspline_reduce`: `spline_strategy` (with `method` for segments
/// only), `target`, `tolerance`, `spline_continuity`, `measure`.
///
/// # Errors
/// `CAGD_ERR_INVALID_ARGUMENT` for a `spline_strategy` code that is not a
/// `CagdSplineStrategy`, a `spline_continuity` below `-1`, or (segments) an invalid
/// `method` code. The rest (degrees, tolerance, the continuity's maximum) is checked by
/// cagd-reduce.
pub(crate) fn spline_options(o: &CagdReduceOptions) -> CResult<BSplineOptions> {
    let strategy = match o.spline_strategy {
        0 => BSplineStrategy::GlobalFit,
        1 => BSplineStrategy::Segments(o.method()?),
        2 => BSplineStrategy::PieglTiller1995,
        other => {
            return Err(Failure::invalid(format!(
                "opts->spline_strategy = {other} is not a CagdSplineStrategy (0, 1 or 2)"
            )));
        }
    };
    let continuity = spline_continuity(o)?;
    Ok(BSplineOptions {
        continuity,
        strategy,
        measure: o.measure,
        ..BSplineOptions::new(o.target, o.tolerance)
    })
}

/// `spline_continuity`: `-1` -> `None` (the most the strategy keeps), `k >= 0` -> `Some(k)`.
///
/// # Errors
/// `CAGD_ERR_INVALID_ARGUMENT` below `-1`.
fn spline_continuity(o: &CagdReduceOptions) -> CResult<Option<usize>> {
    match o.spline_continuity {
        -1 => Ok(None),
        k => usize::try_from(k).map(Some).map_err(|_| {
            Failure::invalid(format!(
                "opts->spline_continuity = {k}: must be -1 (all the continuity the input has, \
                 up to the strategy's maximum) or an order k >= 0"
            ))
        }),
    }
}

/// The options of `cagd_bsplinesurface_reduce_to_tolerance` by `spline_strategy`:
/// `Some` for `CAGD_SPLINE_FIT` (the global fit direction by direction, with
/// `spline_continuity`), `None` for `CAGD_SPLINE_SEGMENTS` (patch-wise with `method` and
/// `continuity`, uniform refinement).
///
/// # Errors
/// `CAGD_ERR_INVALID_ARGUMENT` for an unknown `spline_strategy`, for
/// `CAGD_SPLINE_PIEGL_TILLER_1995` (a curve algorithm) or a `spline_continuity` below `-1`.
pub(crate) fn surface_fit_options(
    o: &CagdReduceOptions,
    tolerance: f64,
) -> CResult<Option<SurfaceFitOptions>> {
    match o.spline_strategy {
        0 => {}
        1 => return Ok(None),
        2 => {
            return Err(Failure::invalid(
                "opts->spline_strategy = CAGD_SPLINE_PIEGL_TILLER_1995 is for curves; \
                 surfaces take CAGD_SPLINE_FIT or CAGD_SPLINE_SEGMENTS",
            ));
        }
        other => {
            return Err(Failure::invalid(format!(
                "opts->spline_strategy = {other} is not a CagdSplineStrategy (0, 1 or 2)"
            )));
        }
    }
    let continuity = spline_continuity(o)?;
    Ok(Some(SurfaceFitOptions {
        continuity,
        measure: o.measure,
        ..SurfaceFitOptions::new((o.target, o.target_v), tolerance)
    }))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::options::{CagdReduceMethod, CagdSplineStrategy};
    use crate::status::CagdStatus;
    use cagd_reduce::Method;

    #[test]
    fn strategy_codes_are_pinned_and_translate() {
        use CagdSplineStrategy as S;
        assert_eq!(S::SPLINE_FIT as i32, 0);
        assert_eq!(S::SPLINE_SEGMENTS as i32, 1);
        assert_eq!(S::SPLINE_PIEGL_TILLER_1995 as i32, 2);
        let d = CagdReduceOptions::default();
        assert_eq!(
            (d.spline_strategy, d.spline_continuity),
            (S::SPLINE_FIT as i32, -1),
            "the defaults"
        );
        let b = spline_options(&d).unwrap();
        assert_eq!(b.strategy, BSplineStrategy::GlobalFit);
        assert_eq!(b.continuity, None);
        for (code, s) in [
            (0, S::SPLINE_FIT),
            (1, S::SPLINE_SEGMENTS),
            (2, S::SPLINE_PIEGL_TILLER_1995),
        ] {
            let o = CagdReduceOptions {
                spline_strategy: code,
                spline_continuity: 1,
                target: 4,
                tolerance: 0.5,
                measure: true,
                ..d
            };
            let b = spline_options(&o).unwrap();
            assert_eq!(S::of(&b.strategy), s);
            assert_eq!(
                (b.continuity, b.target, b.tolerance, b.measure),
                (Some(1), 4, 0.5, true)
            );
        }
        let seg = CagdReduceOptions {
            spline_strategy: 1,
            method: CagdReduceMethod::METHOD_CONSTRAINED_CHEBYSHEV as i32,
            ..d
        };
        assert_eq!(
            spline_options(&seg).unwrap().strategy,
            BSplineStrategy::Segments(Method::ConstrainedChebyshev { r: 0, p: 0 })
        );
    }

    #[test]
    fn bad_codes_are_invalid_and_the_method_matters_for_segments_only() {
        let d = CagdReduceOptions::default();
        for (strategy, continuity, method) in [
            (3, -1, 11),
            (-1, -1, 11),
            (0, -2, 11),
            (2, i32::MIN, 11),
            (1, -1, 42),
        ] {
            let o = CagdReduceOptions {
                spline_strategy: strategy,
                spline_continuity: continuity,
                method,
                ..d
            };
            assert_eq!(
                spline_options(&o).unwrap_err().status,
                CagdStatus::ERR_INVALID_ARGUMENT,
                "{strategy} {continuity} {method}"
            );
        }
        for strategy in [0, 2] {
            let o = CagdReduceOptions {
                spline_strategy: strategy,
                method: 42,
                ..d
            };
            assert!(spline_options(&o).is_ok());
        }
    }

    #[test]
    fn reported_method_is_what_reduced_the_pieces() {
        use CagdReduceMethod as M;
        use CagdSplineStrategy as S;
        let asked = M::METHOD_CONSTRAINED_CHEBYSHEV as i32;
        assert_eq!(S::SPLINE_FIT.reported_method(asked), M::METHOD_L2 as i32);
        assert_eq!(S::SPLINE_SEGMENTS.reported_method(asked), asked);
        assert_eq!(
            S::SPLINE_PIEGL_TILLER_1995.reported_method(asked),
            M::METHOD_PIEGL_TILLER as i32
        );
    }
}
