//! A tiny SVG writer for the pictures of `cagd reduce --svg` and `cagd demo`: polylines in
//! model coordinates, fitted into a panel; 3-D points are drawn by an oblique projection.

use std::fmt::Write as _;

/// One polyline with its style.
#[derive(Debug, Clone)]
pub(crate) struct Line {
    pub(crate) points: Vec<(f64, f64)>,
    pub(crate) color: &'static str,
    pub(crate) width: f64,
    pub(crate) dashed: bool,
    pub(crate) dots: bool,
}

/// A panel: a title, lines, and whether the axes keep their aspect ratio (geometry) or not
/// (a graph such as the error along the parameter).
#[derive(Debug, Clone, Default)]
pub(crate) struct Panel {
    pub(crate) title: String,
    pub(crate) lines: Vec<Line>,
    pub(crate) equal_aspect: bool,
}

/// Projects a point of any dimension to the drawing plane: (x, y) for 2-D, an oblique
/// projection `(x + z/2 cos 30°, y + z/2 sin 30°)` for 3-D and above, (x, 0) for 1-D.
pub(crate) fn project(p: &[f64]) -> (f64, f64) {
    match p.len() {
        0 => (0.0, 0.0),
        1 => (p[0], 0.0),
        2 => (p[0], p[1]),
        _ => (p[0] + 0.433 * p[2], p[1] + 0.25 * p[2]),
    }
}

impl Panel {
    pub(crate) fn line(&mut self, points: Vec<(f64, f64)>, color: &'static str, width: f64) {
        self.lines.push(Line {
            points,
            color,
            width,
            dashed: false,
            dots: false,
        });
    }

    pub(crate) fn polygon(&mut self, points: Vec<(f64, f64)>, color: &'static str) {
        self.lines.push(Line {
            points,
            color,
            width: 0.8,
            dashed: true,
            dots: true,
        });
    }
}

const W: f64 = 480.0;
const H: f64 = 360.0;
const M: f64 = 28.0;

/// Renders rows of panels (side by side within a row) into one SVG document.
pub(crate) fn render(rows: &[Vec<Panel>]) -> String {
    let cols = rows.iter().map(Vec::len).max().unwrap_or(1).max(1);
    let (total_w, total_h) = (W * cols as f64, H * rows.len().max(1) as f64);
    let mut s = String::new();
    let _ = writeln!(
        s,
        r#"<svg xmlns="http://www.w3.org/2000/svg" width="{total_w}" height="{total_h}" viewBox="0 0 {total_w} {total_h}" font-family="sans-serif" font-size="12">"#
    );
    let _ = writeln!(s, r#"<rect width="100%" height="100%" fill="white"/>"#);
    for (r, row) in rows.iter().enumerate() {
        for (k, panel) in row.iter().enumerate() {
            render_panel(&mut s, panel, k as f64 * W, r as f64 * H);
        }
    }
    s.push_str("</svg>\n");
    s
}

fn render_panel(s: &mut String, panel: &Panel, x0: f64, y0: f64) {
    let all = panel.lines.iter().flat_map(|l| l.points.iter());
    let (mut lo_x, mut hi_x, mut lo_y, mut hi_y) = (f64::MAX, f64::MIN, f64::MAX, f64::MIN);
    for &(x, y) in all {
        lo_x = lo_x.min(x);
        hi_x = hi_x.max(x);
        lo_y = lo_y.min(y);
        hi_y = hi_y.max(y);
    }
    if lo_x > hi_x {
        return;
    }
    let span_x = (hi_x - lo_x).max(1e-300);
    let span_y = (hi_y - lo_y).max(1e-300);
    let (mut sx, mut sy) = ((W - 2.0 * M) / span_x, (H - 2.0 * M) / span_y);
    if panel.equal_aspect {
        let k = sx.min(sy);
        sx = k;
        sy = k;
    }
    let map = |(x, y): (f64, f64)| (x0 + M + (x - lo_x) * sx, y0 + H - M - (y - lo_y) * sy);
    let _ = writeln!(
        s,
        r#"<text x="{}" y="{}" fill="black">{}</text>"#,
        x0 + M,
        y0 + 16.0,
        escape(&panel.title)
    );
    if !panel.equal_aspect {
        let _ = writeln!(
            s,
            r##"<text x="{}" y="{}" fill="#555">max {:.3e}</text>"##,
            x0 + M,
            y0 + H - 8.0,
            hi_y
        );
    }
    for line in &panel.lines {
        let pts: Vec<String> = line
            .points
            .iter()
            .map(|&p| {
                let (x, y) = map(p);
                format!("{x:.2},{y:.2}")
            })
            .collect();
        let dash = if line.dashed {
            r#" stroke-dasharray="4 3""#
        } else {
            ""
        };
        let _ = writeln!(
            s,
            r#"<polyline fill="none" stroke="{}" stroke-width="{}"{dash} points="{}"/>"#,
            line.color,
            line.width,
            pts.join(" ")
        );
        if line.dots {
            for &p in &line.points {
                let (x, y) = map(p);
                let _ = writeln!(
                    s,
                    r#"<circle cx="{x:.2}" cy="{y:.2}" r="2.2" fill="{}"/>"#,
                    line.color
                );
            }
        }
    }
}

fn escape(t: &str) -> String {
    t.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn renders_a_panel() {
        let mut p = Panel {
            title: "a <b>".into(),
            equal_aspect: true,
            ..Panel::default()
        };
        p.line(vec![(0.0, 0.0), (1.0, 1.0)], "black", 1.5);
        p.polygon(vec![(0.0, 0.0), (1.0, 0.0)], "gray");
        let svg = render(&[vec![p]]);
        assert!(svg.starts_with("<svg"));
        assert!(svg.contains("a &lt;b&gt;"));
        assert_eq!(svg.matches("<polyline").count(), 2);
        assert_eq!(svg.matches("<circle").count(), 2);
        assert_eq!(project(&[1.0, 2.0, 0.0]), (1.0, 2.0));
    }
}
