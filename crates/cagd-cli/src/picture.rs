//! Pictures of a reduction: original and result with their control polygons, and the error
//! `|P(t) - Q(t)|` along the parameter.

use cagd_core::BezierCurve;

use crate::shape::Shape;
use crate::svg::{Panel, project};

const SAMPLES: usize = 400;

fn curve_line(c: &BezierCurve) -> Vec<(f64, f64)> {
    (0..=SAMPLES)
        .map(|i| project(&c.eval(i as f64 / SAMPLES as f64)))
        .collect()
}

fn polygon(c: &BezierCurve) -> Vec<(f64, f64)> {
    c.points().chunks(c.dim()).map(project).collect()
}

/// Two panels for a curve reduction: geometry and error along the parameter.
pub(crate) fn curve_panels(
    title: &str,
    original: &BezierCurve,
    result: &BezierCurve,
) -> [Panel; 2] {
    let mut geo = Panel {
        title: format!(
            "{title}: degree {} (black) -> {} (red)",
            original.degree(),
            result.degree()
        ),
        equal_aspect: true,
        ..Panel::default()
    };
    geo.polygon(polygon(original), "#888888");
    geo.polygon(polygon(result), "#e08080");
    geo.line(curve_line(original), "black", 1.6);
    geo.line(curve_line(result), "#d01010", 1.2);
    let mut err = Panel {
        title: "error |P(t) - Q(t)| over t in [0, 1]".into(),
        equal_aspect: false,
        ..Panel::default()
    };
    let pts = (0..=SAMPLES)
        .map(|i| {
            let t = i as f64 / SAMPLES as f64;
            let (p, q) = (original.eval(t), result.eval(t));
            let d = p
                .iter()
                .zip(&q)
                .map(|(a, b)| (a - b) * (a - b))
                .sum::<f64>()
                .sqrt();
            (t, d)
        })
        .collect();
    err.line(pts, "#1050c0", 1.2);
    [geo, err]
}

/// The panels for one input/output pair, or none when the shapes cannot be drawn.
pub(crate) fn panels(title: &str, input: &Shape, output: &Shape) -> Vec<Panel> {
    match (input, output) {
        (Shape::Bezier(a), Shape::Bezier(b)) => curve_panels(title, a, b).to_vec(),
        _ => Vec::new(),
    }
}
