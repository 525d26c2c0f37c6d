//! Bounded work on the CLI fuzzer's former pending inputs (`tests/data/fuzz/`, issue 18):
//! each is answered or refused with one named line, no longer after minutes of work.

use std::process::Command;

fn run(args: &[&str], file: &str) -> (Option<i32>, String) {
    let path = format!("{}/tests/data/fuzz/{file}", env!("CARGO_MANIFEST_DIR"));
    let out = Command::new(env!("CARGO_BIN_EXE_cagd"))
        .args(args)
        .args(["-i", &path])
        .output()
        .unwrap();
    (
        out.status.code(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

/// A bicubic 4 x 5 NURBS surface to (1, 1) within 1e-4 by the global fit ran for more than
/// five minutes: the fit's work cap (2^23 span coordinates over the rounds) refuses it.
#[test]
fn surface_fit_refused_by_the_work_cap() {
    let (code, err) = run(
        &["reduce", "--to", "1", "--strategy", "fit", "--tol", "1e-4"],
        "surface-fit-bicubic-to-bilinear.json",
    );
    assert_eq!(code, Some(2), "{err}");
    assert!(
        err.contains("too much work") && err.lines().count() == 1,
        "{err}"
    );
}

/// A NURBS surface with coordinates up to 2e6 made polynomial within 0.5 asked for 883 000
/// patches: refused by the refinement's work cap (2^17 patches over its rounds).
#[test]
fn surface_to_polynomial_refused_by_the_work_cap() {
    let (code, err) = run(
        &["reduce", "--polynomial", "--tol", "0.5"],
        "surface-polynomial-883k-patches.json",
    );
    assert_eq!(code, Some(2), "{err}");
    assert!(
        err.contains("too much work") && err.lines().count() == 1,
        "{err}"
    );
}

/// The JSON report of a successful run.
fn report(args: &[&str], file: &str) -> serde_json::Value {
    let path = format!("{}/tests/data/fuzz/{file}", env!("CARGO_MANIFEST_DIR"));
    let out = Command::new(env!("CARGO_BIN_EXE_cagd"))
        .args(args)
        .args(["-i", &path])
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(0), "{err}");
    let json: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    json["report"].clone()
}

/// A (1, 3) tensor patch at coordinates ~5e6 to (1, 1) within 1e3 by `pinv-ends` was cut
/// into 65 536 squares (7 s in release): only `v` is reduced, so only `v` is cut (strips).
#[test]
fn tensor_reduced_in_one_direction_is_cut_into_strips() {
    let r = report(
        &[
            "reduce",
            "--to",
            "1,1",
            "--method",
            "pinv-ends",
            "--tol",
            "1e3",
        ],
        "tensor-1e6-scale-pinv-ends-tol-1e3.json",
    );
    let pieces = r["pieces"].as_u64().unwrap();
    assert!((2..=256).contains(&pieces), "{r}");
    let (bound, measured) = (
        r["error_bound"].as_f64().unwrap(),
        r["max_error"].as_f64().unwrap(),
    );
    assert!(measured <= bound && bound <= 1e3, "{r}");
}

/// A bicubic tensor patch with one control point far out, to (1, 1) by `pinv` (within
/// 1e-2 it measured 16 384 pieces in full, 8-18 s; 1e-1 here for the debug binary):
/// answered, certified, the measured maximum close below the (tight) bound.
#[test]
fn tensor_of_many_pieces_is_answered() {
    let r = report(
        &["reduce", "--to", "1,1", "--method", "pinv", "--tol", "1e-1"],
        "tensor-pinv-16384-pieces.json",
    );
    let (bound, measured) = (
        r["error_bound"].as_f64().unwrap(),
        r["max_error"].as_f64().unwrap(),
    );
    assert!(r["pieces"].as_u64().unwrap() >= 512, "{r}");
    assert!(measured <= bound && bound <= 1e-1, "{r}");
    assert!(measured >= 0.9 * bound, "{r}");
}

/// A NURBS surface with a weight of 1.8e19 by `--strategy segments` ran for minutes even at
/// `--tol 1e3`: refused by name (the rational bound at that weight ratio is out of reach).
#[test]
fn surface_segments_with_an_extreme_weight_is_refused() {
    for tol in ["1e3", "1e-2"] {
        let (code, err) = run(
            &[
                "reduce",
                "--to",
                "1,1",
                "--strategy",
                "segments",
                "--tol",
                tol,
            ],
            "surface-segments-weight-1e19.json",
        );
        assert_eq!(code, Some(2), "{err}");
        assert!(
            err.contains("no convergence") && err.lines().count() == 1,
            "{err}"
        );
    }
}

/// Conversions whose report overflowed (coordinates of 1e308; CLI fuzz, seed 23) wrote
/// `null` for a NaN: now one named line, exit 2.
#[test]
fn conversion_reports_that_overflow_are_refused() {
    let cases = [
        (
            vec!["convert", "--to", "bezier"],
            r#"{"degree":2,"knots":[-2.1049820820556753,-2.1049820820556753,-2.1049820820556753,-1.0451210958438035,-0.07679819945475197,0.7960488543499915,0.7960488543499915,0.7960488543499915],"points":[[-4359000.0,-3860000.0],[-1216000.0,-1e+308],[-1385000.0,-2000000.0],[-132000.0,-4341000.0],[-4657000.0,-896000.0]],"type":"bspline"}"#,
        ),
        (
            vec!["convert", "--to", "nurbs"],
            r#"{"segments":[[[2.15,0.502,0.86],[1.475,-4.723,3.189],[1.541,4.743,0.663],[-4.0,3.621,-3.015]],[[-4.0,-1e+308,-3.015],[1.199,-0.004,-0.202],[-1.822,4.734,-2.411],[1.575,1.341,4.737]],[[1.575,1.341,4.737],[-3.56,0.232,-3.375],[0.977,1.0,-1.166],[-0.537,-1.38,-1.276]],[[-0.537,-1.38,-1.276],[4.966,1.0,-1.566],[-3.041,-0.36,-4.23],[-1.823,-2.815,0.448]]],"type":"beziers","weights":[null,[2.1512932806545333,0.26867267595001865,0.44418452392272156,1.538012749219753],null,[2.1988537938713617,1.4295156828665312,1.431117141580208,0.7698638996450422]]}"#,
        ),
    ];
    for (args, input) in cases {
        let mut child = Command::new(env!("CARGO_BIN_EXE_cagd"))
            .args(&args)
            .stdin(std::process::Stdio::piped())
            .stdout(std::process::Stdio::piped())
            .stderr(std::process::Stdio::piped())
            .spawn()
            .unwrap();
        std::io::Write::write_all(&mut child.stdin.take().unwrap(), input.as_bytes()).unwrap();
        let out = child.wait_with_output().unwrap();
        let err = String::from_utf8_lossy(&out.stderr);
        let stdout = String::from_utf8_lossy(&out.stdout);
        assert!(!stdout.contains("null"), "{args:?}: {stdout}");
        if out.status.code() == Some(2) {
            assert!(
                err.lines().count() == 1 && err.starts_with("cagd: "),
                "{err}"
            );
        } else {
            assert_eq!(out.status.code(), Some(0), "{err}");
        }
    }
}
