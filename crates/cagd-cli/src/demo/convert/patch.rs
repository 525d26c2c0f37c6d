//! The patch-conversion part of `cagd demo` (SPEC-convert §15.4–15.7): a rational quartic
//! triangle and a polynomial 3 x 3 tensor patch through every `cagd convert` operation,
//! with the largest difference measured and a picture of each tiling.

use std::fmt::Write as _;
use std::path::Path;

use serde_json::{Value, json};

use crate::commands::args::ConvertArgs;
use crate::commands::convert::patch::run as convert;
use crate::demo::timing::time_us;

/// A smooth height field: `z = sin(2x) cos(3y) / 2 + x y`.
fn height(x: f64, y: f64) -> f64 {
    (2.0 * x).sin() * (3.0 * y).cos() / 2.0 + x * y
}

/// The demo triangle (degree 4, weights 1 + (i j) / 8) and tensor (3 x 3).
fn inputs() -> (Value, Value) {
    let n = 4;
    let (mut tp, mut tw) = (Vec::new(), Vec::new());
    for i in 0..=n {
        for j in 0..=n - i {
            let (x, y) = (i as f64 / n as f64, j as f64 / n as f64);
            tp.push(json!([x, y, height(x, y)]));
            tw.push(1.0 + (i * j) as f64 / 8.0);
        }
    }
    let mut rp = Vec::new();
    for i in 0..=3 {
        for j in 0..=3 {
            let (x, y) = (i as f64 / 3.0, j as f64 / 3.0);
            rp.push(json!([x, y, height(x, y)]));
        }
    }
    (
        json!({"type": "triangle", "degree": n, "points": tp, "weights": tw}),
        json!({"type": "tensor", "degree": [3, 3], "points": rp}),
    )
}

fn base() -> ConvertArgs {
    ConvertArgs {
        to: None,
        inner: None,
        edges: None,
        split_line: None,
        split_curve: None,
        trim: None,
        standard_form: false,
        tol: None,
        input: None,
        output: None,
        svg: None,
    }
}

/// Runs each conversion; appends one table row per operation, pictures in `out`.
pub(crate) fn run(out: &Path, table: &mut String) -> Result<(), String> {
    let (tri, rect) = inputs();
    let trim_file = out.join("convert-trim.json");
    let trim = json!({"direction": "u_of_v", "keep": "above",
        "segments": [{"interval": [0.0, 0.7], "bezier": [0.6, 0.5, 0.2, 0.0]}]});
    std::fs::write(&trim_file, trim.to_string())
        .map_err(|e| format!("{}: {e}", trim_file.display()))?;
    let cases: Vec<(&str, &Value, ConvertArgs)> = vec![
        (
            "to-rectangle",
            &tri,
            ConvertArgs {
                to: Some("rectangle".into()),
                ..base()
            },
        ),
        (
            "to-rectangles3",
            &tri,
            ConvertArgs {
                to: Some("rectangles3".into()),
                ..base()
            },
        ),
        (
            "to-rectangles3-skew",
            &tri,
            ConvertArgs {
                to: Some("rectangles3".into()),
                inner: Some((0.2, 0.5)),
                edges: Some(vec![0.3, 0.6, 0.7]),
                ..base()
            },
        ),
        (
            "to-triangles",
            &rect,
            ConvertArgs {
                to: Some("triangles".into()),
                ..base()
            },
        ),
        (
            "split-line",
            &rect,
            ConvertArgs {
                split_line: Some((0.5, 0.2)),
                ..base()
            },
        ),
        (
            "split-line-corner",
            &rect,
            ConvertArgs {
                split_line: Some((-1.5, 0.6)),
                ..base()
            },
        ),
        (
            "split-curve",
            &rect,
            ConvertArgs {
                split_curve: Some(vec![0.5, 1.0, 0.25]),
                ..base()
            },
        ),
        (
            "trim",
            &rect,
            ConvertArgs {
                trim: Some(trim_file.clone()),
                ..base()
            },
        ),
    ];
    let _ = writeln!(
        table,
        "-- patch conversions (SPEC-convert 15.4-15.7), exact: max difference at mapped points"
    );
    for (id, input, args) in cases {
        let file = out.join(format!("convert-{id}.svg"));
        let with_svg = ConvertArgs {
            svg: Some(file.clone()),
            ..args.clone()
        };
        let result = convert(input, &with_svg)?;
        let pieces = match &result {
            Value::Array(a) => a.clone(),
            one => vec![one.clone()],
        };
        let worst = pieces
            .iter()
            .filter_map(|p| p["report"]["max_difference"].as_f64())
            .fold(0.0_f64, f64::max);
        let us = time_us(5, || {
            let _ = convert(input, &args);
        });
        let _ = writeln!(
            table,
            "{:<22} {:<24} {:>8} {:>12} {:>12.4e} {:>10.2}",
            id,
            format!("{} pieces", pieces.len()),
            "",
            "exact",
            worst,
            us
        );
        let _ = writeln!(table, "{:<22} picture: {}", "", file.display());
    }
    Ok(())
}
