//! Pictures of a reduction: original and result with their control polygons, and the error
//! `|P(t) - Q(t)|` along the parameter.

use cagd_core::{BSplineCurve, BezierCurve, TriPatch};

use crate::input::shape::Shape;
use crate::output::svg::{Panel, project};

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
        (Shape::Wsgb(a), Shape::Wsgb(b)) => a
            .to_bezier()
            .and_then(|a| Ok((a, b.to_bezier()?)))
            .map(|(a, b)| curve_panels(title, &a, &b).to_vec())
            .unwrap_or_default(),
        (Shape::Bezier(a), Shape::BSpline(b)) => {
            spline_panels(title, &|t| a.eval(t), polygon(a), a.degree(), b).to_vec()
        }
        (Shape::BSpline(a), Shape::BSpline(b)) => spline_panels(
            title,
            &|t| a.eval(t).unwrap_or_else(|_| vec![0.0; a.dim()]),
            a.points().chunks(a.dim()).map(project).collect(),
            a.degree(),
            b,
        )
        .to_vec(),
        (Shape::Tensor(a), Shape::Tensor(b)) => vec![wireframe(
            format!(
                "{title}: tensor {:?} (black) -> {:?} (red)",
                a.degrees(),
                b.degrees()
            ),
            &|u, v| a.eval(u, v).ok(),
            &|u, v| b.eval(u, v).ok(),
            false,
        )],
        (Shape::Triangle(a), Shape::Triangle(b)) => vec![wireframe(
            format!(
                "{title}: triangle {} (black) -> {} (red)",
                a.degree(),
                b.degree()
            ),
            &|u, v| tri_eval(a, u, v),
            &|u, v| tri_eval(b, u, v),
            true,
        )],
        (Shape::BSplineSurface(a), Shape::BSplineSurface(b)) => {
            // The wireframe's parameters in [0, 1]^2 mapped onto the input's domain.
            let ((u0, u1), (v0, v1)) = a.domain();
            let at = move |u: f64, v: f64| (u0 + (u1 - u0) * u, v0 + (v1 - v0) * v);
            vec![wireframe(
                format!(
                    "{title}: B-spline surface {:?} (black) -> {:?} (red)",
                    a.degrees(),
                    b.degrees()
                ),
                &|u, v| a.eval(at(u, v).0, at(u, v).1).ok(),
                &|u, v| b.eval(at(u, v).0, at(u, v).1).ok(),
                false,
            )]
        }
        (Shape::IntervalTriangle(a), Shape::IntervalTriangle(b)) => {
            crate::output::interval::panels(title, a, b)
        }
        _ => Vec::new(),
    }
}

/// Two panels for a reduction whose result is a B-spline: the original (a Bézier curve or a
/// B-spline, evaluated by `orig` on the result's domain) and the B-spline with their control
/// polygons, and the error along the parameter.
fn spline_panels(
    title: &str,
    orig: &dyn Fn(f64) -> Vec<f64>,
    orig_polygon: Vec<(f64, f64)>,
    degree_from: usize,
    result: &BSplineCurve,
) -> [Panel; 2] {
    let (lo, hi) = result.domain();
    let eval = |t: f64| result.eval(t).unwrap_or_else(|_| vec![0.0; result.dim()]);
    let param = |i: usize| lo + (hi - lo) * i as f64 / (4 * SAMPLES) as f64;
    let mut geo = Panel {
        title: format!(
            "{title}: degree {degree_from} (black) -> degree-{} B-spline (red)",
            result.degree()
        ),
        equal_aspect: true,
        ..Panel::default()
    };
    geo.polygon(orig_polygon, "#888888");
    geo.polygon(
        result.points().chunks(result.dim()).map(project).collect(),
        "#e08080",
    );
    geo.line(
        (0..=4 * SAMPLES)
            .map(|i| project(&orig(param(i))))
            .collect(),
        "black",
        1.6,
    );
    geo.line(
        (0..=4 * SAMPLES)
            .map(|i| project(&eval(param(i))))
            .collect(),
        "#d01010",
        1.2,
    );
    let mut err = Panel {
        title: format!("error along the parameter, t in [{lo}, {hi}]"),
        equal_aspect: false,
        ..Panel::default()
    };
    let pts = (0..=4 * SAMPLES)
        .map(|i| {
            let t = param(i);
            let (p, q) = (orig(t), eval(t));
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

fn tri_eval(t: &TriPatch, u: f64, v: f64) -> Option<Vec<f64>> {
    let mut out = vec![0.0; t.dim()];
    t.eval_into(u, v, &mut out);
    Some(out)
}

type Surface<'a> = &'a dyn Fn(f64, f64) -> Option<Vec<f64>>;

/// A projected wireframe of two surfaces: iso-parameter lines `u = i/8` and `v = j/8`
/// (on a triangle, only where `u + v <= 1`).
fn wireframe(title: String, a: Surface<'_>, b: Surface<'_>, triangle: bool) -> Panel {
    const LINES: usize = 8;
    const STEPS: usize = 64;
    let mut panel = Panel {
        title,
        equal_aspect: true,
        ..Panel::default()
    };
    for (surface, color, width) in [(a, "black", 1.4), (b, "#d01010", 0.9)] {
        for i in 0..=LINES {
            let c = i as f64 / LINES as f64;
            let end = if triangle { 1.0 - c } else { 1.0 };
            for dir in 0..2 {
                let line: Vec<(f64, f64)> = (0..=STEPS)
                    .filter_map(|s| {
                        let x = end * s as f64 / STEPS as f64;
                        let (u, v) = if dir == 0 { (c, x) } else { (x, c) };
                        surface(u, v).map(|p| project(&p))
                    })
                    .collect();
                if line.len() > 1 {
                    panel.line(line, color, width);
                }
            }
        }
    }
    panel
}
