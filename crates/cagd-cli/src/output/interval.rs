//! Pictures of an interval-triangle reduction (seed 004): lower and upper control nets and
//! the box width along a median.

use cagd_core::tri_count;
use cagd_reduce::IntervalTriPatch;

use crate::output::svg::{Panel, project};

/// The control-net lines of a triangular net (rows along i, j and k), projected.
fn net_lines(net: &[f64], n: usize, dim: usize) -> Vec<Vec<(f64, f64)>> {
    let at = |i: usize, j: usize| project(&net[cagd_core::tri_index(n, i, j) * dim..][..dim]);
    let mut lines = Vec::new();
    for a in 0..n {
        lines.push((0..=n - a).map(|j| at(a, j)).collect()); // i = a
        lines.push((0..=n - a).map(|i| at(i, a)).collect()); // j = a
        lines.push((0..=n - a).map(|i| at(i, n - a - i)).collect()); // k = a
    }
    lines
}

/// The mean box width (over coordinates) of the surface at `(u, v)`.
fn width_at(t: &IntervalTriPatch, u: f64, v: f64) -> f64 {
    t.eval(u, v)
        .map(|(l, h)| h.iter().zip(&l).map(|(a, b)| a - b).sum::<f64>() / t.dim() as f64)
        .unwrap_or(0.0)
}

/// Two panels: the lower and upper control nets of input (grey / black) and result (light /
/// dark red); the mean box width of both surfaces along the median from the vertex `w = 1`
/// to the midpoint of the opposite edge, with the thicknesses in the title.
pub(crate) fn panels(title: &str, a: &IntervalTriPatch, b: &IntervalTriPatch) -> Vec<Panel> {
    let mut nets = Panel {
        title: format!(
            "{title}: {} (black) -> {} (red), lower nets dashed",
            a.degree(),
            b.degree()
        ),
        equal_aspect: true,
        ..Panel::default()
    };
    for (t, lo_color, hi_color) in [(a, "#888888", "black"), (b, "#e08080", "#d01010")] {
        for l in net_lines(t.lo(), t.degree(), t.dim()) {
            nets.polygon(l, lo_color);
        }
        for l in net_lines(t.hi(), t.degree(), t.dim()) {
            nets.line(l, hi_color, 0.9);
        }
    }
    let mut width = Panel {
        title: format!(
            "box width on the median u = v; thickness {:.4} -> {:.4}",
            a.thickness(),
            b.thickness()
        ),
        equal_aspect: false,
        ..Panel::default()
    };
    const STEPS: usize = 200;
    // The axis w = 0, so that the widths are seen against zero.
    width.line(vec![(0.0, 0.0), (1.0, 0.0)], "#bbbbbb", 0.6);
    for (t, color) in [(a, "black"), (b, "#d01010")] {
        let pts = (0..=STEPS)
            .map(|s| {
                let x = s as f64 / STEPS as f64;
                (x, width_at(t, x / 2.0, x / 2.0))
            })
            .collect();
        width.line(pts, color, 1.2);
    }
    debug_assert_eq!(a.lo().len(), tri_count(a.degree()) * a.dim());
    vec![nets, width]
}
