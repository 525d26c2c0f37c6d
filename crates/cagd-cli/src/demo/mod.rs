//! `cagd demo`: the seeds' worked examples on built-in data, reduced with every method;
//! prints one table and writes SVG pictures into a folder.
//!
//! The seeds print their figures but not the control points behind them, so the examples
//! use stand-ins of the same degrees: the quartic and quintic of figure 14.2.1 are the inputs
//! of spec vectors `perturb-curve-1` and `forrest-1`; the two tenth-degree curves of §14.4.3
//! (figures 14.4.1 / 14.4.2: ends free / interpolated) are ours; the fifteenth-degree curve
//! of example 14.5.1 is the input of spec vectors `cheb-ends-n15-m10-*`.

mod convert;
mod implicit;
mod interval;
mod patches;
mod splines;
pub(crate) mod timing;
mod wsgb;

use std::fmt::Write as _;
use std::path::Path;

use cagd_core::BezierCurve;

use crate::commands::reduce::methods::{NAMES, Plan, plan};
use crate::commands::reduce::reduce_curve;
use crate::output::picture::curve_panels;
use crate::output::svg;
use timing::time_us;

struct Example {
    id: &'static str,
    title: &'static str,
    points: &'static [[f64; 2]],
    target: usize,
    /// The (r, p) pairs shown for `chebyshev` and `l2`.
    orders: &'static [(i64, i64)],
}

const EXAMPLES: &[Example] = &[
    Example {
        id: "fig-14.2.1-quartic",
        title: "seed 000 fig. 14.2.1, quartic -> cubic",
        points: &[[0.0, 0.0], [1.0, 3.0], [3.0, 4.0], [5.0, 1.0], [6.0, 5.0]],
        target: 3,
        orders: &[(0, 0), (1, 1)],
    },
    Example {
        id: "fig-14.2.1-quintic",
        title: "seed 000 fig. 14.2.1, quintic -> quartic",
        points: &[
            [0.0, 0.0],
            [1.0, 3.0],
            [3.0, 4.0],
            [5.0, 1.0],
            [6.0, 5.0],
            [8.0, 2.0],
        ],
        target: 4,
        orders: &[(0, 0), (1, 1)],
    },
    Example {
        id: "sec-14.4.3-tenth-a",
        title: "seed 000 §14.4.3, tenth degree -> 5",
        points: &[
            [0.0, 0.0],
            [1.0, 4.0],
            [2.0, 6.0],
            [4.0, 7.0],
            [6.0, 5.0],
            [7.0, 2.0],
            [9.0, 1.0],
            [11.0, 3.0],
            [12.0, 6.0],
            [14.0, 7.0],
            [16.0, 4.0],
        ],
        target: 5,
        orders: &[(-1, -1), (0, 0), (1, 1)],
    },
    Example {
        id: "sec-14.4.3-tenth-b",
        title: "seed 000 §14.4.3, tenth degree (loop) -> 5",
        points: &[
            [0.0, 0.0],
            [2.0, 5.0],
            [5.0, 8.0],
            [9.0, 8.0],
            [12.0, 5.0],
            [12.0, 1.0],
            [9.0, -1.0],
            [6.0, 1.0],
            [6.0, 5.0],
            [9.0, 8.0],
            [14.0, 9.0],
        ],
        target: 5,
        orders: &[(-1, -1), (0, 0), (1, 1)],
    },
    Example {
        id: "ex-14.5.1-fifteenth",
        title: "seed 000 example 14.5.1, fifteenth degree -> 10",
        points: &[
            [-15.0, -8.0],
            [-4.0, -2.0],
            [-1.0, -4.0],
            [-10.0, 19.0],
            [-13.0, -19.0],
            [-3.0, -6.0],
            [-6.0, 16.0],
            [-5.0, -17.0],
            [-20.0, 19.0],
            [-1.0, -3.0],
            [-12.0, 1.0],
            [18.0, 8.0],
            [-11.0, 20.0],
            [-3.0, 15.0],
            [7.0, -10.0],
            [-10.0, 5.0],
        ],
        target: 10,
        orders: &[(1, 1), (2, 2)],
    },
];

/// One table row per (example, method variant); pictures in `out`.
pub(crate) fn run(out: &Path) -> Result<(), String> {
    std::fs::create_dir_all(out).map_err(|e| format!("{}: {e}", out.display()))?;
    let mut table = String::new();
    let _ = writeln!(
        table,
        "{:<22} {:<24} {:>8} {:>12} {:>12} {:>10}",
        "example", "method", "n -> m", "bound", "measured", "time (us)"
    );
    for ex in EXAMPLES {
        let flat: Vec<f64> = ex.points.iter().flatten().copied().collect();
        let curve = BezierCurve::new(flat, 2).map_err(|e| format!("{}: {e}", ex.id))?;
        let _ = writeln!(table, "-- {}", ex.title);
        let mut rows = Vec::new();
        for name in NAMES {
            let variants: Vec<(String, Plan)> = if matches!(*name, "chebyshev" | "l2") {
                ex.orders
                    .iter()
                    .map(|&(r, p)| {
                        let how = plan(name, Some(r), Some(p)).map_err(|e| e.to_string());
                        how.map(|h| (format!("{name} (r,p)=({r},{p})"), h))
                    })
                    .collect::<Result<_, _>>()?
            } else {
                vec![(name.to_string(), plan(name, None, None)?)]
            };
            for (label, how) in variants {
                let nm = format!("{} -> {}", curve.degree(), ex.target);
                match reduce_curve(&curve, ex.target, how, true) {
                    Ok(red) => {
                        let us = time_us(21, || {
                            let _ = reduce_curve(&curve, ex.target, how, false);
                        });
                        let _ = writeln!(
                            table,
                            "{:<22} {:<24} {:>8} {:>12.4e} {:>12.4e} {:>10.2}",
                            ex.id,
                            label,
                            nm,
                            red.report.error_bound.unwrap_or(f64::NAN),
                            red.report.max_error.unwrap_or(f64::NAN),
                            us
                        );
                        rows.push(curve_panels(&label, &curve, &red.curve).to_vec());
                    }
                    Err(e) => {
                        let _ = writeln!(table, "{:<22} {:<24} {:>8}   n/a: {e}", ex.id, label, nm);
                    }
                }
            }
        }
        let file = out.join(format!("{}.svg", ex.id));
        std::fs::write(&file, svg::render(&rows))
            .map_err(|e| format!("{}: {e}", file.display()))?;
        let _ = writeln!(table, "{:<22} pictures: {}", "", file.display());
    }
    patches::run(out, &mut table)?;
    splines::run(out, &mut table)?;
    convert::patch::run(out, &mut table)?;
    convert::curve::run(out, &mut table)?;
    implicit::run(out, &mut table)?;
    interval::run(out, &mut table)?;
    wsgb::run(out, &mut table)?;
    print!("{table}");
    Ok(())
}
