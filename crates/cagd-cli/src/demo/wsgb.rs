//! The WSGB part of `cagd demo`: seed 003's example (SPEC-reduce §9.6), r(u;7,1), r(u;6,0)
//! and r(u;6,1) (degree 6 with the erratum p_0 = (200,130)) reduced by one degree with the
//! perturbation and the best uniform methods, and the degree-7 curve by the L2 method through
//! the Bézier form. Prints the certified Euclidean bound and measured error like every other
//! row, then the seed's figures: bound (11) (its printed perturbation "errors"), the true
//! max-abs error, and (12); and the evaluation time per point, WSGB peeling against
//! de Casteljau on the Bézier form of the same curve.

use std::fmt::Write as _;
use std::path::Path;
use std::time::Instant;

use cagd_core::WsgbCurve;
use cagd_reduce::{Method, WsgbMethod, reduce_wsgb, reduce_wsgb_with};

use crate::input::shape::Shape;
use crate::output::picture::panels;
use crate::output::svg;

const P7: [f64; 16] = [
    220., 110., 160., 220., 180., 340., 260., 400., 355., 425., 470., 320., 490., 200., 420., 100.,
];
const P6: [f64; 14] = [
    200., 130., 160., 220., 220., 340., 300., 400., 370., 350., 420., 200., 400., 160.,
];

/// Median time of `reps` runs of `f`, in microseconds (kept here so that this module does
/// not import `demo`, which calls it).
fn time_us(reps: usize, mut f: impl FnMut()) -> f64 {
    let mut t: Vec<f64> = (0..reps)
        .map(|_| {
            let s = Instant::now();
            f();
            s.elapsed().as_secs_f64() * 1e6
        })
        .collect();
    t.sort_by(f64::total_cmp);
    t[t.len() / 2]
}

/// Appends the WSGB rows to `table` and writes `wsgb.svg` into `out`.
pub(crate) fn run(out: &Path, table: &mut String) -> Result<(), String> {
    let _ = writeln!(
        table,
        "-- seed 003, WSGB curves (degree 6 with p_0 = (200,130), SPEC-reduce §9.6); \
         seed's figures in the max-abs norm: bound (11) | true error | (12)"
    );
    let err = |e: cagd_core::Error| e.to_string();
    let cases = [
        ("wsgb-r(u;7,1)", &P7[..], 1),
        ("wsgb-r(u;6,0)", &P6[..], 0),
        ("wsgb-r(u;6,1)", &P6[..], 1),
    ];
    let mut rows = Vec::new();
    for (id, pts, l) in cases {
        let c = WsgbCurve::new(pts.to_vec(), 2, l).map_err(err)?;
        let n = c.degree();
        let methods = [
            ("perturbation", WsgbMethod::Perturbation),
            ("uniform", WsgbMethod::Uniform),
            (
                "l2 (via Bézier)",
                WsgbMethod::Bezier(Method::L2 { r: 0, p: 0 }),
            ),
        ];
        for (label, method) in methods {
            let red = reduce_wsgb(&c, n - 1, method).map_err(err)?;
            let us = time_us(11, || {
                let _ = reduce_wsgb_with(&c, n - 1, method, false);
            });
            let r = &red.report;
            let _ = write!(
                table,
                "{id:<22} {label:<24} {:>8} {:>12.4e} {:>12.4e} {us:>10.2}",
                format!("{n} -> {}", n - 1),
                r.error_bound,
                r.max_error.unwrap_or(f64::NAN),
            );
            if let Some(s) = r.steps.first() {
                let _ = write!(
                    table,
                    "   (11) {:.3} | {:.4} | (12) {:.3}",
                    s.paper_bound_11, s.error_inf, s.uniform_error_12
                );
            }
            let _ = writeln!(table);
            rows.push(panels(
                &format!("{id} {label}"),
                &Shape::Wsgb(c.clone()),
                &Shape::Wsgb(red.curve),
            ));
        }
        // Evaluation per point: peeling against de Casteljau on the same curve.
        let b = c.to_bezier().map_err(err)?;
        let mut o = [0.0; 2];
        let mut work = vec![0.0; b.points().len()];
        let per = |total: f64| total / 1001.0 * 1e3;
        let t_ball = time_us(11, || {
            for k in 0..=1000 {
                c.eval_into(std::hint::black_box(k as f64 / 1000.0), &mut o);
            }
        });
        let t_dc = time_us(11, || {
            for k in 0..=1000 {
                cagd_core::kernel::de_casteljau(
                    b.points(),
                    2,
                    std::hint::black_box(k as f64 / 1000.0),
                    &mut work,
                    &mut o,
                );
            }
        });
        let _ = writeln!(
            table,
            "{:<22} evaluation per point: WSGB {:.1} ns, de Casteljau {:.1} ns",
            "",
            per(t_ball),
            per(t_dc)
        );
    }
    let file = out.join("wsgb.svg");
    std::fs::write(&file, svg::render(&rows)).map_err(|e| format!("{}: {e}", file.display()))?;
    let _ = writeln!(table, "{:<22} pictures: {}", "", file.display());
    Ok(())
}
