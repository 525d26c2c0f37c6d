//! `cagd check`: the conformance runner over spec-vector files.

#[allow(dead_code, reason = "shared test helpers; this file uses some of them")]
mod common;

use cagd_testkit::serde_json::{self, Value, json};
use cagd_testkit::{load_vectors, spec_path};
use common::cagd;

/// Writes `vectors` to a temporary file and runs `cagd check` on it.
fn check(name: &str, vectors: &[Value]) -> (bool, String) {
    let dir = std::env::temp_dir().join(format!("cagd-check-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join(name);
    std::fs::write(&path, serde_json::to_string(vectors).unwrap()).unwrap();
    let o = cagd(&["check", path.to_str().unwrap()], "");
    (
        o.status.success(),
        String::from_utf8_lossy(&o.stdout).into_owned(),
    )
}

/// Every public vector of both spec files passes, one line per vector and a count line.
#[test]
fn public_vector_files_pass() {
    for file in ["vectors-reduce.json", "vectors-convert.json"] {
        let n = load_vectors(file).len();
        let path = spec_path(file);
        let o = cagd(&["check", path.to_str().unwrap()], "");
        let out = String::from_utf8_lossy(&o.stdout);
        assert!(o.status.success(), "{file}:\n{out}");
        assert_eq!(
            out.lines().filter(|l| l.starts_with("pass ")).count(),
            n,
            "{out}"
        );
        assert!(out.ends_with(&format!("{n} passed, 0 failed\n")), "{out}");
    }
}

/// Changing one expected number of a vector makes exactly that vector fail, for every
/// vector that has a number to change (the checker compares what it says it compares).
#[test]
fn altered_expected_values_fail() {
    for file in ["vectors-reduce.json", "vectors-convert.json"] {
        for v in load_vectors(file) {
            if v["expected"].get("error").is_some() {
                continue;
            }
            let mut altered = v.clone();
            if !perturb_first_number(&mut altered["expected"]) {
                continue;
            }
            let (ok, out) = check("altered.json", &[altered]);
            assert!(!ok, "{file} {}: altered vector passed:\n{out}", v["id"]);
            assert!(out.contains("0 passed, 1 failed"), "{out}");
        }
    }
}

/// Adds 1 (relative 1e-3 at least) to the first number or rational string found in `v`.
fn perturb_first_number(v: &mut Value) -> bool {
    match v {
        Value::Number(n) => {
            let x = n.as_f64().unwrap();
            *v = json!(x + 1.0 + x.abs() * 1e-3);
            true
        }
        Value::String(s) if s.parse::<f64>().is_ok() || s.contains('/') => {
            *s = format!("{s}0001");
            true
        }
        Value::Array(a) => a.iter_mut().any(perturb_first_number),
        Value::Object(o) => o.values_mut().any(perturb_first_number),
        _ => false,
    }
}

#[test]
fn unknown_algorithms_and_bad_vectors_fail() {
    let v = json!({"id": "x", "algorithm": "no_such_algorithm", "params": {}, "input": {},
                   "expected": {"Q": [1.0]}, "tol": 1e-12});
    let (ok, out) = check("unknown.json", &[v]);
    assert!(!ok);
    assert!(
        out.contains("FAIL x [no_such_algorithm]") && out.contains("unknown algorithm"),
        "{out}"
    );
    // An expected error that the library does not raise fails; a produced result missing a
    // key of expected fails.
    let mut v = load_vectors("vectors-reduce.json")
        .into_iter()
        .find(|v| v["id"] == "forrest-1")
        .unwrap();
    v["expected"]["no_such_key"] = json!(1.0);
    let (ok, out) = check("missing.json", &[v.clone()]);
    assert!(!ok && out.contains("no_such_key: not produced"), "{out}");
    v["expected"] = json!({"error": "something"});
    let (ok, out) = check("error.json", &[v]);
    assert!(!ok && out.contains("expected an error"), "{out}");
}

#[test]
fn expected_errors_pass_only_when_refused() {
    // A degree-1 curve cannot be reduced by the perturbation method (n >= 2).
    let v = json!({"id": "e", "algorithm": "perturb_reduce_14.2", "params": {"n": 1},
                   "input": {"P": [[0.0, 0.0], [1.0, 1.0]]}, "expected": {"error": "degree"},
                   "tol": 1e-12});
    let (ok, out) = check("refused.json", &[v]);
    assert!(ok, "{out}");
}

#[test]
fn unreadable_files_exit_2() {
    let o = cagd(&["check", "/nonexistent/vectors.json"], "");
    assert_eq!(o.status.code(), Some(2));
    let o = cagd(&["check"], "");
    assert_eq!(o.status.code(), Some(2));
}

/// An empty path argument (the CLI fuzzer's case 3271, seed 2026112723: `cagd intersect ""
/// F`) is refused with a line that names the field, not `cagd: : No such file ...`.
#[test]
fn empty_paths_are_named() {
    for args in [
        &["check", ""][..],
        &["intersect", "", ""][..],
        &["reduce", "--to", "1", "-i", ""][..],
    ] {
        let o = cagd(args, "");
        assert_eq!(o.status.code(), Some(2), "{args:?}");
        let err = String::from_utf8_lossy(&o.stderr);
        assert!(
            err.contains("input file: the path is empty"),
            "{args:?}: {err}"
        );
        assert!(!err.starts_with("cagd: :"), "{args:?}: {err}");
    }
    let line = r#"{"type":"bezier","points":[[0,0],[1,2],[2,0]]}"#;
    // An output that cannot be written is an I/O failure: exit 1, the line names it.
    let o = cagd(&["reduce", "--to", "1", "-o", ""], line);
    assert_eq!(o.status.code(), Some(1));
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(
        err.starts_with("cagd: output file: the path is empty"),
        "{err}"
    );
}
