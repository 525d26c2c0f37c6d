//! Tests of the options (`mod.rs`): the pinned codes and their translation, the
//! `struct_size` versioning rule.

use super::*;
use crate::status::CagdStatus;

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
    assert_eq!(CagdBoundLevel::BOUND_NONE as i32, 0);
    assert_eq!(CagdBoundLevel::BOUND_FAST as i32, 1);
    assert_eq!(CagdBoundLevel::BOUND_TIGHT as i32, 2);
    assert_eq!(
        CagdReduceOptions::default().bound_level,
        CagdBoundLevel::BOUND_TIGHT as i32
    );
    assert_eq!(
        CagdReduceOptions::default().method().unwrap().name(),
        "l2",
        "the default method"
    );
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

#[test]
fn struct_size_rule() {
    let mut o = CagdReduceOptions::default();
    assert_eq!(o.struct_size, size_of::<CagdReduceOptions>());
    o.target = 7;
    (o.spline_strategy, o.spline_continuity) = (2, 1);
    // SAFETY: a valid, initialised struct.
    let r = unsafe { read_options(&o) }.unwrap();
    assert_eq!(r, o);
    // Nothing is released yet: the first version is the whole struct, and the fields
    // added last are appended at the end (the versioning rule).
    assert_eq!(OPTIONS_MIN_SIZE, size_of::<CagdReduceOptions>());
    use std::mem::offset_of;
    assert!(offset_of!(CagdReduceOptions, merge) < offset_of!(CagdReduceOptions, spline_strategy));
    assert!(
        offset_of!(CagdReduceOptions, spline_strategy)
            < offset_of!(CagdReduceOptions, spline_continuity)
    );
    assert!(
        offset_of!(CagdReduceOptions, spline_continuity)
            < offset_of!(CagdReduceOptions, bound_level)
    );
    let end = offset_of!(CagdReduceOptions, bound_level) + size_of::<i32>();
    assert!(size_of::<CagdReduceOptions>() - end < align_of::<CagdReduceOptions>());
    o.struct_size = OPTIONS_MIN_SIZE - 1;
    // SAFETY: as above.
    let e = unsafe { read_options(&o) }.unwrap_err();
    assert_eq!(e.status, CagdStatus::ERR_INVALID_ARGUMENT);
    o.struct_size = 0;
    // SAFETY: as above.
    assert!(unsafe { read_options(&o) }.is_err());
    // A C caller may store any byte in the bool: read as true, never UB.
    let mut raw = std::mem::MaybeUninit::new(CagdReduceOptions::default());
    // SAFETY: writes the byte of `measure` through a byte pointer, as C could (a
    // MaybeUninit may hold any bytes).
    unsafe {
        raw.as_mut_ptr()
            .cast::<u8>()
            .add(std::mem::offset_of!(CagdReduceOptions, measure))
            .write(7);
    }
    // SAFETY: memory laid out as CagdReduceOptions; read_options reads it as bytes.
    assert!(unsafe { read_options(raw.as_ptr()) }.unwrap().measure);
    // SAFETY: NULL is allowed by the contract.
    let e = unsafe { read_options(std::ptr::null()) }.unwrap_err();
    assert_eq!(e.status, CagdStatus::ERR_NULL_POINTER);
}
