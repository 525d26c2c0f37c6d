//! Rust-side tests of the flat calls: every result against the library route it must equal
//! (`reduce_with`, `BezierCurve::elevate`: bit for bit for single curves and elevations; up
//! to rounding for batch reductions, which sum in the GEMM kernel's order), over random
//! curves of several degrees, dimensions, layouts and thread counts; the report struct's
//! versioning.

use std::ptr::{null, null_mut};

use cagd_core::BezierCurve;
use cagd_reduce::{ErrorSpace, Method, ReduceOptions, reduce_with};

use super::*;
use crate::options::CagdReduceOptions;
use crate::status::CagdStatus;

/// Reproducible coordinates in `[-1, 1)`.
fn random(len: usize, seed: u64) -> Vec<f64> {
    let mut s = 0x9E37_79B9_7F4A_7C15u64 ^ seed;
    (0..len)
        .map(|_| {
            s ^= s << 13;
            s ^= s >> 7;
            s ^= s << 17;
            (s >> 11) as f64 / (1u64 << 53) as f64 * 2.0 - 1.0
        })
        .collect()
}

/// `got` equals `want` up to rounding: `|g - w| <= 1e-13 max(1, |w|)` element by element.
fn assert_close(got: &[f64], want: &[f64], what: &str) {
    assert_eq!(got.len(), want.len(), "{what}");
    for (i, (g, w)) in got.iter().zip(want).enumerate() {
        assert!(
            (g - w).abs() <= 1e-13 * w.abs().max(1.0),
            "{what}: [{i}] {g} vs {w}"
        );
    }
}

fn bits(x: &[f64]) -> Vec<u64> {
    x.iter().map(|v| v.to_bits()).collect()
}

/// Every field of a report, the doubles as bits (so that NaN compares equal to NaN).
fn report_bits(r: &CagdBezierReport) -> (usize, i32, i32, usize, usize, [u64; 3]) {
    (
        r.struct_size,
        r.method,
        r.space,
        r.degree_from,
        r.degree_to,
        [r.bound, r.max_error, r.homogeneous_bound].map(f64::to_bits),
    )
}

fn empty_report() -> CagdBezierReport {
    CagdBezierReport {
        struct_size: size_of::<CagdBezierReport>(),
        method: -1,
        space: -1,
        degree_from: 0,
        degree_to: 0,
        bound: 0.0,
        max_error: 0.0,
        homogeneous_bound: 0.0,
    }
}

/// `cagd_bezier_reduce` of `pts` (rational with `w`), with a report.
fn flat_reduce(
    pts: &[f64],
    w: Option<&[f64]>,
    dim: usize,
    o: &CagdReduceOptions,
    report: bool,
) -> Result<(Vec<f64>, Vec<f64>, CagdBezierReport), CagdStatus> {
    let m1 = o.target + 1;
    let (mut out, mut wout, mut needed) = (vec![0.0; m1 * dim], vec![0.0; m1], 0);
    let mut rep = empty_report();
    let rp = if report { &raw mut rep } else { null_mut() };
    // SAFETY: buffers of the documented sizes.
    let s = unsafe {
        cagd_bezier_reduce(
            pts.as_ptr(),
            pts.len() / dim,
            dim,
            w.map_or(null(), <[f64]>::as_ptr),
            o,
            out.as_mut_ptr(),
            out.len(),
            &mut needed,
            wout.as_mut_ptr(),
            wout.len(),
            rp,
        )
    };
    if s != CagdStatus::OK {
        return Err(s);
    }
    assert_eq!(needed, m1 * dim);
    Ok((out, wout, rep))
}

#[test]
fn reduce_equals_reduce_with_bit_for_bit() {
    let methods = [
        (0, Method::Forrest),
        (5, Method::Eck),
        (8, Method::GeneralizedInverse),
        (10, Method::ConstrainedChebyshev { r: 1, p: 0 }),
        (11, Method::L2 { r: 1, p: 1 }),
    ];
    let mut seed = 0;
    for (code, method) in methods {
        for dim in 1..=4 {
            for n in [4usize, 7, 12] {
                for rational in [false, true] {
                    seed += 1;
                    let pts = random((n + 1) * dim, seed);
                    let w: Vec<f64> = random(n + 1, seed + 1000)
                        .iter()
                        .map(|x| 1.0 + 0.5 * x)
                        .collect();
                    let o = CagdReduceOptions {
                        method: code,
                        target: n - 3,
                        r: 1,
                        p: if code == 11 { 1 } else { 0 },
                        measure: seed % 3 == 0,
                        space: i32::from(rational && seed % 2 == 0),
                        ..CagdReduceOptions::default()
                    };
                    let curve = if rational {
                        BezierCurve::new_rational(pts.clone(), w.clone(), dim).unwrap()
                    } else {
                        BezierCurve::new(pts.clone(), dim).unwrap()
                    };
                    let ro = ReduceOptions {
                        measure: o.measure,
                        space: if o.space == 1 {
                            ErrorSpace::Homogeneous
                        } else {
                            ErrorSpace::Euclidean
                        },
                        ..ReduceOptions::new(method, o.target)
                    };
                    let wr = rational.then_some(w.as_slice());
                    let want = reduce_with(&curve, &ro);
                    let got = flat_reduce(&pts, wr, dim, &o, true);
                    let Ok(want) = want else {
                        assert!(got.is_err(), "{method:?} n={n} dim={dim}");
                        continue;
                    };
                    let (p, wo, rep) = got.unwrap();
                    assert_eq!(bits(&p), bits(want.curve.points()), "{method:?} {n} {dim}");
                    if let Some(ww) = want.curve.weights() {
                        assert_eq!(bits(&wo), bits(ww));
                    }
                    assert_eq!(
                        report_bits(&rep),
                        report_bits(&CagdBezierReport::of(&want.report, code))
                    );
                    assert_eq!(
                        rep.bound.to_bits(),
                        want.report.error_bound.unwrap().to_bits()
                    );
                    assert_eq!(rep.max_error.is_nan(), !o.measure);
                    // Points only: the same bits.
                    let (p2, wo2, _) = flat_reduce(&pts, wr, dim, &o, false).unwrap();
                    assert_eq!(bits(&p2), bits(&p));
                    if rational {
                        assert_eq!(bits(&wo2), bits(&wo));
                    }
                }
            }
        }
    }
}

#[test]
fn report_struct_size_is_honoured() {
    let pts = random(8 * 2, 5);
    let o = CagdReduceOptions {
        target: 4,
        ..CagdReduceOptions::default()
    };
    let mut out = [0.0; 10];
    let mut needed = 0;
    // A caller compiled against a later, larger struct: cagd writes only what it knows.
    #[repr(C)]
    struct Bigger {
        report: CagdBezierReport,
        later: f64,
    }
    let mut big = Bigger {
        report: CagdBezierReport {
            struct_size: size_of::<Bigger>(),
            ..empty_report()
        },
        later: 42.0,
    };
    let call = |rep: *mut CagdBezierReport, out: &mut [f64; 10], needed: &mut usize| {
        // SAFETY: buffers of the documented sizes; `rep` points to `struct_size` bytes.
        unsafe {
            cagd_bezier_reduce(
                pts.as_ptr(),
                8,
                2,
                null(),
                &o,
                out.as_mut_ptr(),
                10,
                needed,
                null_mut(),
                0,
                rep,
            )
        }
    };
    assert_eq!(
        call((&raw mut big).cast(), &mut out, &mut needed),
        CagdStatus::OK
    );
    assert_eq!(big.later, 42.0);
    assert_eq!(big.report.struct_size, size_of::<Bigger>());
    assert_eq!((big.report.degree_from, big.report.degree_to), (7, 4));
    assert!(big.report.bound > 0.0);
    let mut small = CagdBezierReport {
        struct_size: size_of::<CagdBezierReport>() - 8,
        ..empty_report()
    };
    assert_eq!(
        call(&mut small, &mut out, &mut needed),
        CagdStatus::ERR_INVALID_ARGUMENT
    );
    assert_eq!(small.method, -1, "nothing written");
}

#[test]
fn elevate_equals_bezier_elevate_bit_for_bit() {
    for dim in 1..=4 {
        for n in [0usize, 3, 9] {
            for r in [0usize, 1, 5] {
                let pts = random((n + 1) * dim, (dim * 100 + n * 10 + r) as u64);
                let w: Vec<f64> = random(n + 1, 77).iter().map(|x| 1.2 + x).collect();
                for rational in [false, true] {
                    let c = if rational {
                        BezierCurve::new_rational(pts.clone(), w.clone(), dim).unwrap()
                    } else {
                        BezierCurve::new(pts.clone(), dim).unwrap()
                    };
                    let e = c.elevate(r).unwrap();
                    let (mut out, mut wout, mut needed) =
                        (vec![0.0; (n + r + 1) * dim], vec![0.0; n + r + 1], 0);
                    // SAFETY: buffers of the documented sizes.
                    let s = unsafe {
                        cagd_bezier_elevate(
                            pts.as_ptr(),
                            n + 1,
                            dim,
                            if rational { w.as_ptr() } else { null() },
                            r,
                            out.as_mut_ptr(),
                            out.len(),
                            &mut needed,
                            wout.as_mut_ptr(),
                            wout.len(),
                        )
                    };
                    assert_eq!(s, CagdStatus::OK);
                    assert_eq!(bits(&out), bits(e.points()));
                    if let Some(ew) = e.weights() {
                        assert_eq!(bits(&wout), bits(ew));
                    }
                }
            }
        }
    }
}

/// Curve-major -> point-major (or back).
fn transpose(x: &[f64], k: usize, n1: usize, dim: usize, back: bool) -> Vec<f64> {
    let mut y = vec![0.0; x.len()];
    for c in 0..k {
        for j in 0..n1 {
            for d in 0..dim {
                let (cm, pm) = ((c * n1 + j) * dim + d, (j * k + c) * dim + d);
                if back {
                    y[cm] = x[pm];
                } else {
                    y[pm] = x[cm];
                }
            }
        }
    }
    y
}

/// One batch call; `Ok(opts)` reduces, `Err(r)` elevates.
#[allow(clippy::too_many_arguments, reason = "the batch call's own arguments")]
fn batch(
    input: &[f64],
    k: usize,
    n: usize,
    dim: usize,
    layout: CagdBatchLayout,
    what: Result<&CagdReduceOptions, usize>,
    threads: usize,
    m1: usize,
) -> Vec<f64> {
    let mut out = vec![f64::NAN; k * m1 * dim];
    let mut needed = 0;
    let (p, l, o, cap) = (input.as_ptr(), layout as i32, out.as_mut_ptr(), out.len());
    // SAFETY: buffers of the documented sizes.
    let s = unsafe {
        match what {
            Ok(opts) => {
                cagd_bezier_reduce_batch(p, k, n, dim, l, opts, threads, o, cap, &mut needed)
            }
            Err(r) => cagd_bezier_elevate_batch(p, k, n, dim, l, r, threads, o, cap, &mut needed),
        }
    };
    assert_eq!(s, CagdStatus::OK);
    assert_eq!(needed, out.len());
    out
}

#[test]
fn batches_equal_the_single_curve_route_in_every_layout_and_thread_count() {
    let o = CagdReduceOptions {
        target: 4,
        r: 1,
        p: 1,
        ..CagdReduceOptions::default()
    };
    for (k, n, dim) in [
        (1usize, 6usize, 2usize),
        (37, 7, 3),
        (2500, 9, 1),
        (1500, 6, 5),
    ] {
        let cm = random(k * (n + 1) * dim, (k + n + dim) as u64);
        let pm = transpose(&cm, k, n + 1, dim, false);
        let red = ReduceOptions::new(Method::L2 { r: 1, p: 1 }, 4);
        let want_red: Vec<f64> = cm
            .chunks_exact((n + 1) * dim)
            .flat_map(|c| {
                let c = BezierCurve::new(c.to_vec(), dim).unwrap();
                reduce_with(&c, &red).unwrap().curve.points().to_vec()
            })
            .collect();
        let want_ele: Vec<f64> = cm
            .chunks_exact((n + 1) * dim)
            .flat_map(|c| {
                let c = BezierCurve::new(c.to_vec(), dim).unwrap();
                c.elevate(2).unwrap().points().to_vec()
            })
            .collect();
        for threads in [0usize, 1, 2, 3] {
            let cmr = batch(
                &cm,
                k,
                n,
                dim,
                CagdBatchLayout::LAYOUT_CURVE_MAJOR,
                Ok(&o),
                threads,
                5,
            );
            // Reductions go through the GEMM kernel (blocks of >= 6 curves), whose sums run
            // in another order than the single-curve route's: equal up to rounding.
            assert_close(&cmr, &want_red, &format!("k={k} threads={threads}"));
            let pmr = batch(
                &pm,
                k,
                n,
                dim,
                CagdBatchLayout::LAYOUT_POINT_MAJOR,
                Ok(&o),
                threads,
                5,
            );
            assert_close(
                &transpose(&pmr, k, 5, dim, true),
                &want_red,
                &format!("point-major k={k} threads={threads}"),
            );
            let m1 = n + 3;
            let cme = batch(
                &cm,
                k,
                n,
                dim,
                CagdBatchLayout::LAYOUT_CURVE_MAJOR,
                Err(2),
                threads,
                m1,
            );
            assert_eq!(bits(&cme), bits(&want_ele), "k={k} threads={threads}");
            let pme = batch(
                &pm,
                k,
                n,
                dim,
                CagdBatchLayout::LAYOUT_POINT_MAJOR,
                Err(2),
                threads,
                m1,
            );
            assert_eq!(bits(&transpose(&pme, k, m1, dim, true)), bits(&want_ele));
        }
    }
}

#[test]
fn overflow_is_non_finite_with_the_curve() {
    // Finite input near the largest double: elevation stays finite (convex combination),
    // an extrapolating reduction overflows. The curve index is reported across blocks.
    let (k, n, dim) = (3000usize, 4usize, 1usize);
    let mut cm = random(k * (n + 1), 9);
    for (j, x) in cm[2100 * (n + 1)..2101 * (n + 1)].iter_mut().enumerate() {
        *x = if j % 2 == 0 { f64::MAX } else { -f64::MAX };
    }
    let o = CagdReduceOptions {
        target: 2,
        r: 0,
        p: 0,
        ..CagdReduceOptions::default()
    };
    let mut out = vec![0.0; k * 3];
    let mut needed = 0;
    // Point-major too (the GEMM runs in column tiles: the curve is found across them), in
    // dimension 1 and 3.
    let pm = transpose(&cm, k, n + 1, dim, false);
    let cm3: Vec<f64> = cm.iter().flat_map(|x| [0.5, *x, -0.25]).collect();
    let pm3 = transpose(&cm3, k, n + 1, 3, false);
    let mut out3 = vec![0.0; k * 3 * 3];
    for (threads, layout, input, d) in [
        (1usize, 0, &cm, dim),
        (2, 0, &cm, dim),
        (1, 1, &pm, dim),
        (2, 1, &pm, dim),
        (1, 1, &pm3, 3),
        (2, 1, &pm3, 3),
    ] {
        let o_buf = if d == 1 { &mut out } else { &mut out3 };
        // SAFETY: buffers of the documented sizes.
        let s = unsafe {
            cagd_bezier_reduce_batch(
                input.as_ptr(),
                k,
                n,
                d,
                layout,
                &o,
                threads,
                o_buf.as_mut_ptr(),
                o_buf.len(),
                &mut needed,
            )
        };
        assert_eq!(s, CagdStatus::ERR_NON_FINITE);
        assert!(
            crate::last_error_string().contains("curve 2100"),
            "{}",
            crate::last_error_string()
        );
    }
}

#[test]
fn non_finite_input_is_found_from_the_output() {
    // No scan precedes the kernels: a NaN or infinity anywhere (first, middle and last
    // curve; a zero-weight corner of the operator's support included) must still come
    // back as CAGD_ERR_NON_FINITE naming curve, point and coordinate, in both layouts,
    // on 1 and 2 threads, for the reduction and the elevation, in dimensions 1 and 3.
    let (k, n) = (2500usize, 5usize);
    let o = CagdReduceOptions {
        target: 3,
        r: 0,
        p: 0,
        ..CagdReduceOptions::default()
    };
    for dim in [1usize, 3] {
        for (curve, point, coord) in [(0, 0, 0), (1234, 3, dim - 1), (k - 1, n, 0)] {
            for bad in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
                let mut cm = random(k * (n + 1) * dim, 11);
                cm[(curve * (n + 1) + point) * dim + coord] = bad;
                let pm = transpose(&cm, k, n + 1, dim, false);
                for (layout, input) in [(0, &cm), (1, &pm)] {
                    for threads in [1usize, 2] {
                        for reduce in [true, false] {
                            let mut out = vec![0.0; k * (n + 2) * dim];
                            let mut needed = 0;
                            // SAFETY: buffers of the documented sizes.
                            let s = unsafe {
                                if reduce {
                                    cagd_bezier_reduce_batch(
                                        input.as_ptr(),
                                        k,
                                        n,
                                        dim,
                                        layout,
                                        &o,
                                        threads,
                                        out.as_mut_ptr(),
                                        out.len(),
                                        &mut needed,
                                    )
                                } else {
                                    cagd_bezier_elevate_batch(
                                        input.as_ptr(),
                                        k,
                                        n,
                                        dim,
                                        layout,
                                        1,
                                        threads,
                                        out.as_mut_ptr(),
                                        out.len(),
                                        &mut needed,
                                    )
                                }
                            };
                            let what = format!(
                                "dim {dim} {bad} at ({curve},{point},{coord}) layout {layout} \
                                 threads {threads} reduce {reduce}"
                            );
                            assert_eq!(s, CagdStatus::ERR_NON_FINITE, "{what}");
                            let msg = crate::last_error_string();
                            assert!(
                                msg.contains(&format!(
                                    "curve {curve}, point {point}, coordinate {coord}"
                                )),
                                "{what}: {msg}"
                            );
                        }
                    }
                }
            }
        }
    }
}
