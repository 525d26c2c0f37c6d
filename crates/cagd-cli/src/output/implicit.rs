//! The pictures of `cagd implicitize --svg` and `cagd intersect --svg`: the sign of `f` on
//! a grid (two tints), its zero set (marching squares, grey), the curve (black), and for
//! intersections the second curve and the points.

use std::fmt::Write as _;

use cagd_core::BezierCurve;
use cagd_implicit::ImplicitCurve;

const SIZE: f64 = 480.0;
const GRID: usize = 96;

/// The drawing box: the curves' control points, widened by 15 %.
fn frame(curves: &[&BezierCurve]) -> (f64, f64, f64) {
    let (mut lo, mut hi) = ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]);
    for c in curves {
        for i in 0..=c.degree() {
            let p = c.point(i);
            for k in 0..2 {
                lo[k] = lo[k].min(p[k]);
                hi[k] = hi[k].max(p[k]);
            }
        }
    }
    let span = (hi[0] - lo[0]).max(hi[1] - lo[1]).max(1e-12) * 1.3;
    let cx = 0.5 * (lo[0] + hi[0]);
    let cy = 0.5 * (lo[1] + hi[1]);
    (cx - 0.5 * span, cy - 0.5 * span, span)
}

fn polyline(s: &mut String, c: &BezierCurve, map: &impl Fn(f64, f64) -> (f64, f64), color: &str) {
    let pts: Vec<String> = (0..=200)
        .map(|k| {
            let p = c.eval(k as f64 / 200.0);
            let (x, y) = map(p[0], p[1]);
            format!("{x:.2},{y:.2}")
        })
        .collect();
    let _ = writeln!(
        s,
        r#"<polyline fill="none" stroke="{color}" stroke-width="2" points="{}"/>"#,
        pts.join(" ")
    );
}

/// SVG of the implicit curve `imp` of `curve` (sign tints, zero set), `others` drawn on top
/// in blue and `points` as red dots.
pub(crate) fn render(
    curve: &BezierCurve,
    imp: &ImplicitCurve,
    others: &[&BezierCurve],
    points: &[[f64; 2]],
) -> String {
    let mut all = vec![curve];
    all.extend_from_slice(others);
    let (x0, y0, span) = frame(&all);
    let map = |x: f64, y: f64| ((x - x0) / span * SIZE, SIZE - (y - y0) / span * SIZE);
    let cell = span / GRID as f64;
    let mut s = String::new();
    let _ = writeln!(
        s,
        r#"<svg xmlns="http://www.w3.org/2000/svg" width="{SIZE}" height="{SIZE}" viewBox="0 0 {SIZE} {SIZE}">"#
    );
    // Sign of f at the grid nodes.
    let node = |i: usize, j: usize| (x0 + i as f64 * cell, y0 + j as f64 * cell);
    let f: Vec<f64> = (0..=GRID)
        .flat_map(|j| (0..=GRID).map(move |i| (i, j)))
        .map(|(i, j)| {
            let (x, y) = node(i, j);
            imp.classify(x, y).value
        })
        .collect();
    let at = |i: usize, j: usize| f[j * (GRID + 1) + i];
    // Sign of f at cell centres, one rectangle per run of equal sign in a row.
    let px = SIZE / GRID as f64;
    for j in 0..GRID {
        let signs: Vec<bool> = (0..GRID)
            .map(|i| {
                let (x, y) = node(i, j);
                imp.classify(x + 0.5 * cell, y + 0.5 * cell).value > 0.0
            })
            .collect();
        let mut start = 0;
        for i in 1..=GRID {
            if i == GRID || signs[i] != signs[start] {
                let color = if signs[start] { "#fde0d0" } else { "#d6e6f8" };
                let (x, y) = node(start, j);
                let (sx, sy) = map(x, y + cell);
                let _ = writeln!(
                    s,
                    r#"<rect x="{sx:.2}" y="{sy:.2}" width="{:.2}" height="{:.2}" fill="{color}"/>"#,
                    px * (i - start) as f64 + 0.3,
                    px + 0.3
                );
                start = i;
            }
        }
    }
    // Zero set by marching squares (one segment per sign-changing cell edge pair).
    let mut zero = String::new();
    for j in 0..GRID {
        for i in 0..GRID {
            let corners = [(i, j), (i + 1, j), (i + 1, j + 1), (i, j + 1)];
            let mut cuts = Vec::new();
            for e in 0..4 {
                let (a, b) = (corners[e], corners[(e + 1) % 4]);
                let (fa, fb) = (at(a.0, a.1), at(b.0, b.1));
                if (fa > 0.0) != (fb > 0.0) {
                    let u = fa / (fa - fb);
                    let (xa, ya) = node(a.0, a.1);
                    let (xb, yb) = node(b.0, b.1);
                    cuts.push(map(xa + u * (xb - xa), ya + u * (yb - ya)));
                }
            }
            for pair in cuts.chunks(2) {
                if let [p, q] = pair {
                    let _ = write!(zero, "M{:.1} {:.1}L{:.1} {:.1}", p.0, p.1, q.0, q.1);
                }
            }
        }
    }
    let _ = writeln!(
        s,
        r##"<path d="{zero}" fill="none" stroke="#888" stroke-width="1"/>"##
    );
    polyline(&mut s, curve, &map, "black");
    for o in others {
        polyline(&mut s, o, &map, "#1f5fbf");
    }
    for p in points {
        let (x, y) = map(p[0], p[1]);
        let _ = writeln!(s, r#"<circle cx="{x:.2}" cy="{y:.2}" r="4" fill="red"/>"#);
    }
    s.push_str("</svg>\n");
    s
}
