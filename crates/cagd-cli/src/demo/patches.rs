//! The patch part of `cagd demo`: a bicubic-like 5 x 5 tensor patch and a degree-8 triangle
//! (smooth built-in surfaces), reduced by the seed's one-degree perturbation methods
//! (§14.3.1, §14.3.2) and by the multi-degree ones.

use std::fmt::Write as _;
use std::path::Path;

use cagd_core::{TensorPatch, TriPatch};
use cagd_reduce::{PatchOptions, TriOptions, reduce_tensor, reduce_triangle};

use crate::commands::reduce::methods::plan;
use crate::commands::reduce::patch::{tensor, tensor_method, tri_method, triangle};
use crate::demo::timing::time_us;
use crate::input::shape::Shape;
use crate::output::picture::panels;
use crate::output::svg;

/// A smooth height field sampled as control points: `z = sin(2x) cos(3y) / 2 + x y`.
fn height(x: f64, y: f64) -> f64 {
    (2.0 * x).sin() * (3.0 * y).cos() / 2.0 + x * y
}

fn tensor_demo() -> Result<TensorPatch, String> {
    let (m, n) = (5usize, 5usize);
    let mut pts = Vec::new();
    for i in 0..=m {
        for j in 0..=n {
            let (x, y) = (i as f64 / m as f64, j as f64 / n as f64);
            pts.extend([x, y, height(x, y)]);
        }
    }
    TensorPatch::new(pts, m, n, 3).map_err(|e| e.to_string())
}

fn triangle_demo() -> Result<TriPatch, String> {
    let n = 8usize;
    let mut pts = Vec::new();
    for i in 0..=n {
        for j in 0..=n - i {
            let (x, y) = (i as f64 / n as f64, j as f64 / n as f64);
            pts.extend([x, y, height(x, y)]);
        }
    }
    TriPatch::new(pts, n, 3).map_err(|e| e.to_string())
}

/// One demo case: method name, target degree(s), end orders for `l2` / `chebyshev`.
struct Case<T> {
    name: &'static str,
    target: T,
    orders: Option<(i64, i64)>,
}

/// Appends the patch rows to `table` and writes `patches.svg` into `out`.
pub(crate) fn run(out: &Path, table: &mut String) -> Result<(), String> {
    let _ = writeln!(table, "-- seed 000 §14.3, patches");
    let tp = tensor_demo()?;
    let tri = triangle_demo()?;
    let mut rows = Vec::new();
    let tensor_cases = [
        Case {
            name: "perturbation",
            target: (4, 4),
            orders: None,
        },
        Case {
            name: "l2",
            target: (3, 3),
            orders: Some((0, 0)),
        },
        Case {
            name: "chebyshev",
            target: (3, 3),
            orders: Some((0, 0)),
        },
    ];
    for Case {
        name,
        target,
        orders,
    } in tensor_cases
    {
        let how = plan(name, orders.map(|o| o.0), orders.map(|o| o.1))?;
        let method = tensor_method(name, how)?;
        let (json, result) = tensor(&tp, target, method, None).map_err(|e| e.to_string())?;
        let opts = PatchOptions::new(method);
        let us = time_us(11, || {
            let _ = reduce_tensor(&tp, target, &opts);
        });
        row(
            table,
            "tensor-5x5",
            name,
            &format!("5x5 -> {}x{}", target.0, target.1),
            &json,
            us,
        );
        if let Some(r) = result {
            rows.push(panels(name, &Shape::Tensor(tp.clone()), &r));
        }
    }
    let tri_cases = [
        Case {
            name: "perturbation",
            target: 7,
            orders: None,
        },
        Case {
            name: "l2",
            target: 4,
            orders: Some((0, 0)),
        },
        Case {
            name: "l2",
            target: 4,
            orders: Some((-1, -1)),
        },
    ];
    for Case {
        name,
        target,
        orders,
    } in tri_cases
    {
        let how = plan(name, orders.map(|o| o.0), orders.map(|o| o.1))?;
        let method = tri_method(name, how)?;
        let label = match orders {
            Some((-1, _)) => format!("{name} (free boundary)"),
            Some(_) => format!("{name} (boundary kept)"),
            None => name.to_string(),
        };
        let (json, result) = triangle(&tri, target, method, None).map_err(|e| e.to_string())?;
        let opts = TriOptions::new(method);
        let us = time_us(11, || {
            let _ = reduce_triangle(&tri, target, &opts);
        });
        row(
            table,
            "triangle-8",
            &label,
            &format!("8 -> {target}"),
            &json,
            us,
        );
        if let Some(r) = result {
            rows.push(panels(&label, &Shape::Triangle(tri.clone()), &r));
        }
    }
    let file = out.join("patches.svg");
    std::fs::write(&file, svg::render(&rows)).map_err(|e| format!("{}: {e}", file.display()))?;
    let _ = writeln!(table, "{:<22} pictures: {}", "", file.display());
    Ok(())
}

fn row(table: &mut String, id: &str, label: &str, nm: &str, json: &serde_json::Value, us: f64) {
    let r = &json["report"];
    let _ = writeln!(
        table,
        "{:<22} {:<24} {:>8} {:>12.4e} {:>12.4e} {:>10.2}",
        id,
        label,
        nm,
        r["error_bound"].as_f64().unwrap_or(f64::NAN),
        r["max_error"].as_f64().unwrap_or(f64::NAN),
        us
    );
}
