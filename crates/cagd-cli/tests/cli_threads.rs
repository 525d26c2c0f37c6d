//! `cagd reduce --threads N`: the objects of an input array reduced on N threads give the
//! same output, byte for byte, as one thread, and the same first failure; bad values of
//! the option are usage errors (exit 2).

mod common;

use cagd_testkit::bench::random_input;
use cagd_testkit::serde_json::{Value, json};
use common::{cagd, json_out};

/// `count` random planar Bézier curves of degree 7 (and, with `spline`, a clamped quintic
/// B-spline, which only a reduction to a tolerance takes).
fn objects(count: usize, spline: bool) -> Vec<Value> {
    let mut v: Vec<Value> = (0..count)
        .map(|i| {
            let p = random_input(16, i as u64);
            let pts: Vec<Value> = p.chunks(2).map(|q| json!([q[0], q[1]])).collect();
            json!({"type": "bezier", "points": pts})
        })
        .collect();
    if !spline {
        return v;
    }
    v.push(json!({
        "type": "bspline", "degree": 5,
        "knots": [0, 0, 0, 0, 0, 0, 0.5, 1, 1, 1, 1, 1, 1],
        "points": [[0, 0], [1, 2], [2, 3], [3, 1], [4, 0], [5, 2], [6, 1]],
    }));
    v
}

/// Runs `cagd` with `args` on `input`, returning (exit code, stdout, stderr).
fn run(args: &[&str], input: &Value) -> (Option<i32>, Vec<u8>, String) {
    let o = cagd(args, &input.to_string());
    (
        o.status.code(),
        o.stdout,
        String::from_utf8_lossy(&o.stderr).into_owned(),
    )
}

#[test]
fn threads_give_the_output_of_one_thread() {
    for (base, spline) in [
        (
            &[
                "reduce", "--to", "4", "--method", "l2", "--r", "1", "--p", "1",
            ][..],
            false,
        ),
        (
            &["reduce", "--to", "3", "--tol", "1e-3", "--continuity", "1"][..],
            true,
        ),
    ] {
        let input = Value::Array(objects(40, spline));
        let one = run(base, &input);
        assert_eq!(one.0, Some(0), "{}", one.2);
        let count = 40 + usize::from(spline);
        let parsed = json_out(&cagd(base, &input.to_string()));
        assert_eq!(parsed.as_array().map(Vec::len), Some(count));
        for threads in ["0", "1", "2", "3"] {
            let mut args = base.to_vec();
            args.extend(["--threads", threads]);
            let many = run(&args, &input);
            assert_eq!(many.0, Some(0), "{}", many.2);
            assert!(
                many.1 == one.1,
                "{args:?}: the output differs from one thread's"
            );
        }
    }
}

#[test]
fn threads_report_the_first_failure_in_input_order() {
    let mut v = objects(12, false);
    // Objects 4 and 9 cannot be reduced to degree 4 (degrees 2 and 3).
    v[4] = json!({"type": "bezier", "points": [[0, 0], [1, 1], [2, 0]]});
    v[9] = json!({"type": "bezier", "points": [[0, 0], [1, 1], [2, 0], [3, 3]]});
    let input = Value::Array(v);
    let one = run(&["reduce", "--to", "4"], &input);
    assert_eq!(one.0, Some(2));
    assert!(one.2.contains("input[4]"), "{}", one.2);
    for threads in ["2", "4"] {
        let many = run(&["reduce", "--to", "4", "--threads", threads], &input);
        assert_eq!((many.0, &many.1, &many.2), (one.0, &one.1, &one.2));
    }
}

#[test]
fn polynomial_runs_on_threads_too() {
    let h = std::f64::consts::FRAC_1_SQRT_2;
    let arc = json!({
        "type": "bspline", "degree": 2,
        "knots": [0, 0, 0, 0.5, 0.5, 1, 1, 1],
        "points": [[1, 0], [1, 1], [0, 1], [-1, 1], [-1, 0]],
        "weights": [1, h, 1, h, 1],
    });
    let input = Value::Array(vec![arc.clone(), arc.clone(), arc]);
    let base = ["reduce", "--polynomial", "--tol", "1e-4"];
    let one = run(&base, &input);
    assert_eq!(one.0, Some(0), "{}", one.2);
    let mut args = base.to_vec();
    args.extend(["--threads", "2"]);
    assert_eq!(run(&args, &input), one);
}

#[test]
fn bad_thread_counts_are_usage_errors() {
    let input = Value::Array(objects(2, false));
    for (value, says) in [
        ("257", "--threads"),
        ("-1", "--threads"),
        ("two", "--threads"),
    ] {
        let (code, _, err) = run(&["reduce", "--to", "3", "--threads", value], &input);
        assert_eq!(code, Some(2), "{value}");
        assert!(
            err.lines().next().is_some_and(|l| l.contains(says)),
            "{value}: {err}"
        );
    }
}
