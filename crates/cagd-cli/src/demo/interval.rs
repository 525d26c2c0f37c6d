//! The interval part of `cagd demo`: Example 1 of seed 004 (SPEC-convert I.4–I.5), a degree-4
//! interval triangle with boxes of width 2 wrapped by a cubic one (thickness 2 -> 125/36).

use std::fmt::Write as _;
use std::path::Path;

use cagd_reduce::{IntervalOptions, IntervalTriPatch, reduce_interval_triangle};

use crate::output::interval::panels;
use crate::output::svg;

/// Example 1's boxes `([x, x+2], [y, y+2], [z, z+2])`: `(i, j)` and `(x, y, z)`
/// (SPEC-convert I.4; 7 of the 15 reconstructed there).
const EXAMPLE_1: [((usize, usize), [f64; 3]); 15] = [
    ((4, 0), [55.0, 55.0, 70.0]),
    ((3, 1), [60.0, 50.0, 70.0]),
    ((2, 2), [80.0, 50.0, 70.0]),
    ((1, 3), [100.0, 50.0, 70.0]),
    ((0, 4), [105.0, 55.0, 70.0]),
    ((3, 0), [50.0, 60.0, 70.0]),
    ((2, 1), [70.0, 60.0, 50.0]),
    ((1, 2), [90.0, 60.0, 50.0]),
    ((0, 3), [110.0, 60.0, 70.0]),
    ((2, 0), [60.0, 70.0, 70.0]),
    ((1, 1), [80.0, 70.0, 40.0]),
    ((0, 2), [100.0, 70.0, 70.0]),
    ((1, 0), [70.0, 80.0, 70.0]),
    ((0, 1), [90.0, 80.0, 70.0]),
    ((0, 0), [80.0, 80.0, 70.0]),
];

/// Example 1 as an interval triangle.
pub(crate) fn example_1() -> Result<IntervalTriPatch, String> {
    let mut lo = vec![0.0; 45];
    for ((i, j), xyz) in EXAMPLE_1 {
        let q = cagd_core::tri_index(4, i, j);
        lo[3 * q..3 * q + 3].copy_from_slice(&xyz);
    }
    let hi = lo.iter().map(|x| x + 2.0).collect();
    IntervalTriPatch::new(lo, hi, 4, 3).map_err(|e| e.to_string())
}

/// Appends Example 1 (and its tighter models) to `table`; writes `interval.svg` into `out`.
pub(crate) fn run(out: &Path, table: &mut String) -> Result<(), String> {
    let _ = writeln!(
        table,
        "-- seed 004 example 1, interval triangle 4 -> 3 (thickness 2 -> 125/36 = 3.4722)"
    );
    let p = example_1()?;
    let mut rows = Vec::new();
    for big in [None, Some(6), Some(10), Some(16)] {
        let opts = IntervalOptions {
            containment_degree: big,
            ..IntervalOptions::new(3)
        };
        let r = reduce_interval_triangle(&p, &opts).map_err(|e| e.to_string())?;
        let bare = IntervalOptions {
            sample_grid: 0,
            ..opts
        };
        let t0 = std::time::Instant::now();
        for _ in 0..5 {
            let _ = reduce_interval_triangle(&p, &bare);
        }
        let us = t0.elapsed().as_secs_f64() * 1e6 / 5.0;
        let rep = &r.report;
        let label = format!("interval-lp N={}", rep.containment_degree);
        let _ = writeln!(
            table,
            "{:<22} {:<24} {:>8} thickness {:.4} -> {:.4} (ratio {:.4}), repair {:.1e}, \
             max violation {:.1e}, coupled {:?}, {:.0} us (mean of 5)",
            "seed-004-example-1",
            label,
            "4 -> 3",
            rep.thickness_in,
            rep.thickness_out,
            rep.ratio.unwrap_or(f64::NAN),
            rep.repair,
            rep.max_violation.unwrap_or(f64::NAN),
            rep.coupled,
            us
        );
        rows.push(panels(&label, &p, &r.patch));
    }
    let file = out.join("interval.svg");
    std::fs::write(&file, svg::render(&rows)).map_err(|e| format!("{}: {e}", file.display()))?;
    let _ = writeln!(table, "{:<22} pictures: {}", "", file.display());
    Ok(())
}
