//! The input limits of the `cagd` command (`crate::limits`, README "Input limits"): big
//! inputs are refused with one line naming the field, or answered; `--help` after every
//! subcommand prints the usage and exits 0; regressions found by the fuzzer.

use std::io::Write;
use std::process::{Command, Output, Stdio};

fn cagd_bytes(args: &[&str], stdin: &[u8]) -> Output {
    let mut child = Command::new(env!("CARGO_BIN_EXE_cagd"))
        .args(args)
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("spawn cagd");
    let mut input = child.stdin.take().expect("stdin");
    let data = stdin.to_vec();
    // Write on a thread: the child may refuse (and stop reading) before the end.
    let writer = std::thread::spawn(move || {
        let _ = input.write_all(&data);
    });
    let out = child.wait_with_output().expect("wait");
    let _ = writer.join();
    out
}

/// Exit 2 and exactly one stderr line that starts with `want`.
fn refused(out: &Output, want: &str) {
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{err}");
    assert_eq!(err.lines().count(), 1, "{err}");
    assert!(err.starts_with(want), "got {err:?}, want {want:?}");
    assert!(out.stdout.is_empty());
}

fn points(n: usize) -> String {
    let p: Vec<String> = (0..n).map(|i| format!("[{i},{}]", i % 7)).collect();
    format!("[{}]", p.join(","))
}

#[test]
fn big_inputs_are_refused_naming_the_field() {
    // 10^5 + 1 control points in one object.
    let text = format!(r#"{{"type":"bezier","points":{}}}"#, points(100_001));
    refused(
        &cagd_bytes(&["reduce", "--to", "2"], text.as_bytes()),
        "cagd: input.points: has 100001 entries, above the limit of 100000",
    );
    // 10^5 points of a Bézier curve: under the count limit, refused by the degree range.
    let text = format!(r#"{{"type":"bezier","points":{}}}"#, points(100_000));
    refused(
        &cagd_bytes(&["reduce", "--to", "2"], text.as_bytes()),
        "cagd: input",
    );
    // Degree 200.
    let text = r#"{"type":"triangle","degree":200,"points":[[0]]}"#;
    refused(
        &cagd_bytes(&["reduce", "--to", "2"], text.as_bytes()),
        "cagd: input.degree: 200 is above the limit of 64",
    );
    let text = r#"{"type":"bspline","degree":18446744073709551615,"knots":[0],"points":[[0]]}"#;
    refused(
        &cagd_bytes(&["reduce", "--to", "2"], text.as_bytes()),
        "cagd: input.degree: 18446744073709551615 is above the limit of 64",
    );
    // 10^4 + 1 curves.
    let one = r#"{"type":"bezier","points":[[0],[1],[3]]}"#;
    let text = format!("[{}]", vec![one; 10_001].join(","));
    refused(
        &cagd_bytes(&["reduce", "--to", "1"], text.as_bytes()),
        "cagd: input: has 10001 objects, above the limit of 10000",
    );
    // Deep nesting: the parser's depth limit, a named error.
    let text = format!("{}{}", "[".repeat(5000), "]".repeat(5000));
    refused(
        &cagd_bytes(&["reduce", "--to", "1"], text.as_bytes()),
        "cagd: input",
    );
    // A point of 65 coordinates.
    let p: Vec<String> = (0..65).map(|i| i.to_string()).collect();
    let text = format!(r#"{{"type":"bezier","points":[[{}]]}}"#, p.join(","));
    refused(
        &cagd_bytes(&["reduce", "--to", "1"], text.as_bytes()),
        "cagd: input.points[0]: has 65 coordinates, above the limit of 64",
    );
    // More than 32 MiB on stdin.
    let text = vec![b' '; (32 << 20) + 1];
    refused(
        &cagd_bytes(&["reduce", "--to", "1"], &text),
        "cagd: stdin: input larger than the limit",
    );
    // A B-spline surface of 400 x 400 = 160 000 points.
    let row = points(400);
    let rows = vec![row.as_str(); 400].join(",");
    let text = format!(
        r#"{{"type":"bspline-surface","degree":[1,1],"knots_u":[],"knots_v":[],"points":[{rows}]}}"#
    );
    refused(
        &cagd_bytes(&["reduce", "--to", "1,1"], text.as_bytes()),
        "cagd: input.points[250]: 100400 control points in all, above the limit of 100000",
    );
}

#[test]
fn ten_thousand_curves_are_answered() {
    let one = r#"{"type":"bezier","points":[[0,0],[1,2],[3,1],[4,0]]}"#;
    let text = format!("[{}]", vec![one; 10_000].join(","));
    let out = cagd_bytes(&["reduce", "--to", "2"], text.as_bytes());
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).expect("JSON");
    assert_eq!(v.as_array().map(Vec::len), Some(10_000));
}

#[test]
fn a_long_bspline_is_answered() {
    // 10^4 control points of a uniform cubic B-spline (the fit strategy, to a tolerance).
    let n = 10_000;
    let mut knots = vec![0.0; 4];
    knots.extend((1..n - 3).map(|i| i as f64));
    knots.extend([(n - 3) as f64; 4]);
    let pts: Vec<[f64; 2]> = (0..n)
        .map(|i| [i as f64, ((i as f64) * 0.1).sin()])
        .collect();
    let text = serde_json::json!({"type": "bspline", "degree": 3, "knots": knots, "points": pts})
        .to_string();
    let out = cagd_bytes(&["reduce", "--to", "2", "--tol", "1e-2"], text.as_bytes());
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
}

#[test]
fn help_after_every_subcommand() {
    for cmd in [
        "reduce",
        "merge",
        "convert",
        "implicitize",
        "intersect",
        "check",
        "demo",
    ] {
        for flag in ["--help", "-h"] {
            let out = cagd_bytes(&[cmd, flag], b"");
            assert!(out.status.success(), "{cmd} {flag}");
            let text = String::from_utf8_lossy(&out.stdout);
            assert!(text.starts_with("usage:"), "{cmd} {flag}: {text}");
            assert!(text.contains(&format!("cagd {cmd}")), "{cmd} {flag}");
            assert!(text.contains("Input limits"), "{cmd} {flag}");
        }
    }
}

#[test]
fn usage_errors_are_one_line() {
    for (args, want) in [
        (&["reduce", "--to"][..], "cagd: --to: needs a value"),
        (&["frob"][..], "cagd: \"frob\": unknown command"),
        (
            &["check", "a.json", "--tol"][..],
            "cagd: check: unknown argument \"--tol\"",
        ),
    ] {
        refused(&cagd_bytes(args, b""), want);
    }
}
