//! A fixed workload for instruction counts (callgrind) of [`pieces_to_nurbs`]: the
//! 1 000-span 3-D rational curve of the `nurbs_bezier` bench, of degree `DEGREE` (first
//! argument, default 7), split into pieces once and merged back `REPS` times (second
//! argument, default 10).
//!
//! ```text
//! cargo build --release -p cagd-convert --example pieces_to_nurbs_count
//! valgrind --tool=callgrind --callgrind-out-file=cg.out \
//!     target/release/examples/pieces_to_nurbs_count 7 10
//! callgrind_annotate --inclusive=yes cg.out | grep pieces_to_nurbs
//! ```
//!
//! Instructions per span = the inclusive count of `pieces_to_nurbs` / (REPS * 1000).

use std::hint::black_box;

use cagd_convert::{pieces_to_nurbs, to_bezier_pieces};
use cagd_core::BSplineCurve;
use cagd_testkit::bench::random_input;

const SPANS: usize = 1000;

fn main() {
    let mut args = std::env::args().skip(1);
    let p: usize = args.next().and_then(|a| a.parse().ok()).unwrap_or(7);
    let reps: usize = args.next().and_then(|a| a.parse().ok()).unwrap_or(10);
    let n = SPANS + p;
    let mut knots = vec![0.0; p + 1];
    knots.extend((1..SPANS).map(|i| i as f64));
    knots.extend(std::iter::repeat_n(SPANS as f64, p + 1));
    let pts: Vec<f64> = random_input(3 * n, p as u64)
        .iter()
        .map(|x| 10.0 * x)
        .collect();
    let w: Vec<f64> = random_input(n, 100 + p as u64)
        .iter()
        .map(|x| 1.25 + 0.75 * x)
        .collect();
    let curve = BSplineCurve::new_rational(p, knots, pts, w, 3).expect("valid curve");
    let pieces = to_bezier_pieces(&curve).expect("pieces");
    let mut same = true;
    for _ in 0..reps {
        let r = pieces_to_nurbs(black_box(&pieces), None).expect("merge");
        same &= r.curve.knots() == curve.knots();
        black_box(&r);
    }
    println!("degree {p}, {reps} x {SPANS} spans, same knots: {same}");
}
