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
