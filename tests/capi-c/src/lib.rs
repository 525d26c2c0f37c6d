//! The C and C++ tests of the cagd C ABI (STYLE §9.10). `build.rs` compiles `c/*.c` (C11)
//! and `cpp/*.cpp` (C++17) against `include/cagd.h`; each `int cagd_ctest_<name>(void)`
//! becomes the Rust test `<name>` here, which passes when the C function returns 0 (on
//! failure the C code prints the expression, the status and the message to stderr).
//! `every_c_test_is_wired` fails when a C test function is not listed below.

// Without a use of the library, the linker drops it and the C objects' `cagd_*`
// references are undefined (checked: rust-lld reports each of them).
use cagd_capi as _;

mod fuzz;
mod statuses;

/// Declares each C test and the Rust test that runs it, and the list of wired names.
macro_rules! c_tests {
    ($($name:ident),* $(,)?) => {
        /// Names of the wired C tests (without the `cagd_ctest_` prefix).
        #[cfg(test)]
        const WIRED: &[&str] = &[$(stringify!($name)),*];

        #[cfg(test)]
        #[allow(unsafe_code, reason = "calls the C test functions")]
        mod c {
            $(
                #[test]
                fn $name() {
                    unsafe extern "C" {
                        #[link_name = concat!("cagd_ctest_", stringify!($name))]
                        fn run() -> i32;
                    }
                    // SAFETY: the C test takes no arguments, uses only its own memory and
                    // the cagd C ABI, and returns an int.
                    let rc = unsafe { run() };
                    assert_eq!(
                        rc, 0,
                        "C test cagd_ctest_{} failed; see its stderr above",
                        stringify!($name)
                    );
                }
            )*
        }
    };
}

c_tests![
    // c/fuzz_regressions.c
    fuzz_eval_overflow_is_non_finite,
    fuzz_intersect_degree_product_refused,
    fuzz_split_curve_piece_degree_refused,
    fuzz_report_bound_never_infinite,
    fuzz_bezier_elevate_overflow_is_non_finite,
    fuzz_bezier_report_bound_never_infinite,
    fuzz_curve_reduce_batch_overflow_is_non_finite,
    fuzz_nurbs_span_extrapolation_overflow_refused,
    fuzz_tensor_degeneracy_overflow_is_non_finite,
    fuzz_subdivide_extrapolation_refused,
    fuzz_uniform_nurbs_near_dbl_max_measured,
    // c/interval.c
    intervaltri_example_1,
    intervaltri_elevation_matrix,
    intervaltri_bad_input,
    intervaltri_thickness_overflow,
    // c/status.c
    status_names,
    last_error_message,
    // c/curve.c
    curve_roundtrip,
    curve_eval_many,
    curve_rational_circle,
    curve_elevate_subdivide_segment,
    // c/curve_bad_input.c
    curve_new_bad_input,
    curve_accessors_bad_input,
    curve_ops_bad_input,
    // c/convert_patch.c
    convert_triangle_to_rectangles,
    convert_rectangle_splits,
    convert_bad_input,
    // c/patch.c
    tensorpatch_roundtrip,
    tensorpatch_bad_input,
    tripatch_roundtrip,
    tripatch_bad_input,
    // c/reduce.c
    reduce_forrest_1,
    reduce_ginv_n7_m3_free,
    reduce_hermite_n7_m3,
    reduce_batch,
    reduce_batch_bounds,
    reduce_rational_roundtrip,
    // c/reduce_bad_input.c
    reduce_bad_input,
    report_accessors_bad_input,
    reduce_batch_bad_input,
    reduce_options_struct_size,
    // c/reduce_tolerance.c
    reduce_tolerance_stepwise_spec,
    reduce_tolerance_exact,
    reduce_tolerance_c1,
    reduce_tolerance_bad_input,
    // c/bspline.c
    bspline_polynomial_closed_form,
    bspline_nurbs_circle,
    bspline_to_beziers,
    // c/convert_nurbs.c
    convert_span_closed_forms,
    convert_biquadratic,
    convert_curve_round_trip,
    // c/convert_surface.c
    convert_unclamped_round_trip,
    convert_surface_round_trip,
    // c/bspline_merge.c
    bspline_merge_001_exact,
    bspline_merge_c1_round_trip,
    bspline_merge_bad_input,
    // c/bspline_bad_input.c
    bspline_new_bad_knots,
    bspline_new_bad_input,
    bspline_ops_bad_input,
    // c/patch_reduce.c
    tensorpatch_reduce_spec,
    tripatch_reduce_spec,
    patch_reduce_roundtrip,
    patch_reduce_to_tolerance,
    patch_reduce_bad_input,
    // c/bspline_reduce.c
    bspline_reduce_uniform_001,
    bspline_reduce_tolerance,
    bspline_reduce_bad_input,
    // c/bspline_reduce_strategy.c
    bspline_reduce_fit_c2,
    bspline_reduce_continuity_limits,
    bspline_reduce_piegl_tiller,
    bspline_reduce_strategy_bad_input,
    report_spline_accessors,
    // c/core_invariants.c
    curve_forward_difference,
    tensorpatch_degeneracy,
    tripatch_degeneracy,
    distances,
    // c/core_matrices.c
    uniform_bspline_matrix,
    basis_matrix,
    perturbation_scalars,
    // c/reduce_extra.c
    curve_exact_degree,
    curve_reduce_g1_optimal,
    reduce_operator_matrix,
    reduce_extra_bad_input,
    // c/bspline_surface.c
    bsplinesurface_roundtrip,
    bsplinesurface_reduce,
    bsplinesurface_reduce_to_tolerance,
    bsplinesurface_bad_input,
    // c/patch_ops.c
    tensorpatch_ops,
    tripatch_ops,
    patch_ops_bad_input,
    // c/implicit.c
    implicit_conic_spec,
    implicit_subdivision_matrix,
    curve_intersect,
    implicit_bad_input,
    // c/rational_to_polynomial.c
    rational_to_polynomial_half_circle,
    rational_to_polynomial_equal_weights_and_errors,
    // c/wsgb.c
    wsgb_paper_example,
    wsgb_bad_input,
    wsgb_reduce_to_tolerance,
    // c/flat.c
    flat_reduce_equals_handle,
    flat_reduce_bad_input,
    flat_elevate_equals_handle,
    flat_elevate_bad_input,
    // c/flat_batch.c
    flat_batch_reduce_layouts,
    flat_batch_elevate_layouts,
    flat_batch_bad_input,
    // c/copy_out.c
    curvelist_copy,
    bspline_copy,
    patchlist_copy,
    wsgblist_copy,
    // cpp/header_compiles.cpp
    cpp_header,
];

#[cfg(test)]
mod wiring {
    use std::path::PathBuf;

    /// The `cagd_ctest_<name>` functions defined in the C and C++ sources.
    fn defined() -> Vec<String> {
        let here = PathBuf::from(env!("CARGO_MANIFEST_DIR"));
        let mut names = Vec::new();
        for (dir, ext) in [("c", "c"), ("cpp", "cpp")] {
            for entry in std::fs::read_dir(here.join(dir)).expect("source dir") {
                let path = entry.expect("entry").path();
                if path.extension().is_none_or(|e| e != ext) {
                    continue;
                }
                let text = std::fs::read_to_string(&path).expect("source file");
                for line in text.lines() {
                    // `int cagd_ctest_x(void) {`, optionally after `extern "C" ` in C++.
                    let Some((_, rest)) = line.split_once("int cagd_ctest_") else {
                        continue;
                    };
                    if let Some(name) = rest.strip_suffix("(void) {") {
                        names.push(name.to_owned());
                    }
                }
            }
        }
        names.sort();
        names
    }

    #[test]
    fn every_c_test_is_wired() {
        let defined = defined();
        assert!(
            defined.len() >= 10,
            "found only {defined:?}; parser broken?"
        );
        let mut wired: Vec<String> = super::WIRED.iter().map(|s| (*s).to_owned()).collect();
        wired.sort();
        assert_eq!(
            defined, wired,
            "C tests defined (left) vs wired in src/lib.rs (right)"
        );
    }
}
