//! `cagd convert --svg` for patch conversions: the tiling of the input's parameter domain
//! by the pieces' declared domains, and the control nets of the input and of the pieces
//! in a projection.

use std::path::Path;

use cagd_convert::{PatchPiece, PatchSurface};

use crate::output::svg::{Panel, project, render};

const COLORS: [&str; 6] = [
    "#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e", "#17becf",
];

/// The boundary of a piece's own domain (unit square or triangle), 4 x 24 samples.
fn boundary(p: &PatchPiece) -> Vec<(f64, f64)> {
    let k = 24;
    let mut st = Vec::new();
    let f = |i: usize| i as f64 / k as f64;
    if p.domain.is_triangle() {
        st.extend((0..k).map(|i| (f(i), 0.0)));
        st.extend((0..k).map(|i| (1.0 - f(i), f(i))));
        st.extend((0..=k).map(|i| (0.0, 1.0 - f(i))));
    } else {
        st.extend((0..k).map(|i| (f(i), 0.0)));
        st.extend((0..k).map(|i| (1.0, f(i))));
        st.extend((0..k).map(|i| (1.0 - f(i), 1.0)));
        st.extend((0..=k).map(|i| (0.0, 1.0 - f(i))));
    }
    st.into_iter()
        .map(|(s, t)| {
            let [u, v] = p.domain.map(s, t);
            (u, v)
        })
        .collect()
}

/// The control-net lines of a patch (rows and columns), projected.
fn net_lines(s: &PatchSurface) -> Vec<Vec<(f64, f64)>> {
    let mut out = Vec::new();
    match s {
        PatchSurface::Tensor(p) => {
            let (m, n) = p.degrees();
            let net = p.net();
            for i in 0..=m {
                out.push((0..=n).map(|j| project(net.point(i, j))).collect());
            }
            for j in 0..=n {
                out.push((0..=m).map(|i| project(net.point(i, j))).collect());
            }
        }
        PatchSurface::Tri(t) => {
            let n = t.degree();
            let net = t.net();
            for i in 0..=n {
                out.push((0..=n - i).map(|j| project(net.point(i, j))).collect());
                out.push((0..=n - i).map(|j| project(net.point(j, i))).collect());
                out.push(
                    (0..=n - i)
                        .map(|j| project(net.point(j, n - i - j)))
                        .collect(),
                );
            }
        }
    }
    out
}

/// Writes the picture to `path` when given.
pub(crate) fn write(
    path: Option<&Path>,
    input: &PatchSurface,
    pieces: &[PatchPiece],
) -> Result<(), String> {
    let Some(path) = path else { return Ok(()) };
    let mut tiling = Panel {
        title: "parameter domain tiling (u, v)".into(),
        equal_aspect: true,
        ..Default::default()
    };
    let outline = match input {
        PatchSurface::Tri(_) => vec![(0.0, 0.0), (1.0, 0.0), (0.0, 1.0), (0.0, 0.0)],
        PatchSurface::Tensor(_) => vec![(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0), (0.0, 0.0)],
    };
    tiling.line(outline, "#000000", 1.5);
    let mut nets = Panel {
        title: "control nets (input dashed)".into(),
        equal_aspect: true,
        ..Default::default()
    };
    for l in net_lines(input) {
        nets.polygon(l, "#888888");
    }
    for (k, p) in pieces.iter().enumerate() {
        let c = COLORS[k % COLORS.len()];
        tiling.line(boundary(p), c, 1.2);
        for l in net_lines(&p.surface) {
            nets.line(l, c, 0.8);
        }
    }
    std::fs::write(path, render(&[vec![tiling, nets]]))
        .map_err(|e| format!("{}: {e}", path.display()))
}
