//! `cagd convert` on `triangle` / `tensor` inputs: triangular ↔ rectangular patches and
//! exact subdivision along a line, a curve or a trimming chain (SPEC-convert §15.4–15.7).
//!
//! Input: `{"type":"triangle","degree":n,"points":[...]}` or
//! `{"type":"tensor","degree":[m,n],"points":[...]}` (i-major), with optional `"weights"`
//! in the order of the points (a rational patch).
//!
//! Operations (one per call):
//! - triangle `--to rectangle`: one degenerate `n x n` tensor (§15.4);
//! - triangle `--to rectangles3 [--inner U,V] [--edges G,K,H]`: three `n x n` tensors
//!   (§15.5) through the inner point `(U, V)` (default the centroid) and the edge points
//!   `(G, 0)` on `v = 0`, `(K, 1 - K)` on `u + v = 1`, `(0, H)` on `u = 0` (default the
//!   midpoints, `0.5,0.5,0.5`);
//! - tensor `--to triangles`: two triangles of degree `m + n` (§15.6.3);
//! - tensor `--to triangle [--tol T]`: an `n x n` degenerate rectangle back to its triangle
//!   (Theorem 15.4.2; refused with the residual when it is not degenerate within `T`,
//!   default 1e-12 relative);
//! - tensor `--split-line F1,F0`: the pieces on either side of `u = F1 v + F0` (§15.6);
//! - tensor `--split-curve A0,A1,…`: both sides of `u = f(v)`, `f` with Bernstein
//!   coefficients `A0..Ak` (§15.7);
//! - tensor `--trim FILE`: the untrimmed pieces of the kept region (§15.7.3), FILE as
//!   described in [`crate::commands::convert::patch::trim`].
//!
//! Output: each piece is the input's JSON form plus `"domain"` — `{"bilinear":[X00, X10,
//! X01, X11]}` (piece `(s,t)` ↦ `(1-s)(1-t)X00 + s(1-t)X10 + (1-s)t X01 + st X11`),
//! `{"triangle":[A, B, C]}` (piece `(u',v')` ↦ `C + u'(A-C) + v'(B-C)`) or, for curved
//! pieces, `{"ruled":{"s0":[...], "s1":[...]}}` (piece `(s,t)` ↦ `(1-s)L(t) + sR(t)`,
//! `L`, `R` the Bézier curves of the `(u,v)` plane with control points `s0`, `s1`) — and
//! `"report"`: `{"max_difference": d, "samples": N}`, the largest coordinate difference
//! between the piece and the input at the mapped points of a 21 x 21 grid of the piece's
//! domain. `--to rectangle` and `--to triangle` print one object, the others an array.

mod svg;
mod trim;

use cagd_convert::{
    PatchPiece, PatchSurface, PieceDomain, TensorSurface, TriSplitPoints, TriSurface,
};
use serde_json::{Value, json};

use crate::commands::args::ConvertArgs;
use crate::input::shape::rows;
use crate::input::{RawShape, parse_input};

/// Grid size of the report's measurement (`(GRID + 1)^2` samples per piece).
const GRID: usize = 20;

/// The input patch, with its weights.
fn read_patch(shape_json: &Value) -> Result<PatchSurface, String> {
    let raw = parse_input(&shape_json.to_string()).map_err(|e| e.to_string())?;
    let weights = match shape_json.get("weights") {
        None | Some(Value::Null) => None,
        Some(w) => Some(crate::input::numbers(w, "input.weights").map_err(|e| e.to_string())?),
    };
    let locate = |e: cagd_core::Error| crate::input::shape::locate("input", &e).to_string();
    match raw.into_iter().next() {
        Some(RawShape::Triangle { degree, points }) => Ok(PatchSurface::Tri(
            TriSurface::new(points.coords, degree, points.dim, weights).map_err(locate)?,
        )),
        Some(RawShape::Tensor { degree, points }) => Ok(PatchSurface::Tensor(
            TensorSurface::new(points.coords, degree.0, degree.1, points.dim, weights)
                .map_err(locate)?,
        )),
        _ => Err("input: cagd convert on patches takes a \"triangle\" or a \"tensor\"".into()),
    }
}

/// A patch in the input JSON form.
pub(crate) fn surface_json(s: &PatchSurface) -> Value {
    let (mut v, w) = match s {
        PatchSurface::Tensor(p) => {
            let (m, n) = p.degrees();
            (
                json!({"type": "tensor", "degree": [m, n], "points": rows(p.net().points(), p.dim())}),
                p.weights(),
            )
        }
        PatchSurface::Tri(t) => (
            json!({"type": "triangle", "degree": t.degree(), "points": rows(t.net().points(), t.dim())}),
            t.weights(),
        ),
    };
    if let Some(w) = w {
        v["weights"] = json!(w);
    }
    v
}

/// A domain as JSON.
pub(crate) fn domain_json(d: &PieceDomain) -> Value {
    match d {
        PieceDomain::Bilinear(x) => json!({ "bilinear": x }),
        PieceDomain::Triangle(x) => json!({ "triangle": x }),
        PieceDomain::Ruled { s0, s1 } => json!({"ruled": {"s0": s0, "s1": s1}}),
    }
}

/// A piece with its domain and measured report.
fn piece_json(input: &PatchSurface, p: &PatchPiece) -> Value {
    let mut v = surface_json(&p.surface);
    v["domain"] = domain_json(&p.domain);
    let d = cagd_convert::max_piece_difference(input, p, GRID);
    let samples = if p.domain.is_triangle() {
        (GRID + 1) * (GRID + 2) / 2
    } else {
        (GRID + 1) * (GRID + 1)
    };
    v["report"] = json!({"max_difference": d, "samples": samples});
    v
}

/// What to do, from the options (exactly one operation).
enum Op {
    Rectangle,
    Rectangles3(TriSplitPoints),
    Triangles,
    Triangle(f64),
    Line(f64, f64),
    Curve(Vec<f64>),
    Trim(std::path::PathBuf),
}

fn operation(args: &ConvertArgs) -> Result<Op, String> {
    let mut ops = Vec::new();
    if let Some(to) = &args.to {
        ops.push(match to.as_str() {
            "rectangle" => Op::Rectangle,
            "rectangles3" => {
                let mut s = TriSplitPoints::default();
                if let Some((u, v)) = args.inner {
                    s.p = [u, v];
                }
                if let Some(e) = &args.edges {
                    let [g, k, h] = e[..] else {
                        return Err(format!("--edges: expected 3 numbers G,K,H, got {}", e.len()));
                    };
                    (s.g, s.k, s.h) = (g, k, h);
                }
                Op::Rectangles3(s)
            }
            "triangles" => Op::Triangles,
            "triangle" => Op::Triangle(args.tol.unwrap_or(1e-12)),
            other => {
                return Err(format!(
                    "--to: {other:?} is not a patch conversion (rectangle, rectangles3, triangles, triangle)"
                ));
            }
        });
    }
    if let Some((f1, f0)) = args.split_line {
        ops.push(Op::Line(f1, f0));
    }
    if let Some(a) = &args.split_curve {
        ops.push(Op::Curve(a.clone()));
    }
    if let Some(f) = &args.trim {
        ops.push(Op::Trim(f.clone()));
    }
    if (args.inner.is_some() || args.edges.is_some())
        && !matches!(ops.first(), Some(Op::Rectangles3(_)))
    {
        return Err("--inner / --edges go with --to rectangles3".into());
    }
    match ops.len() {
        1 => Ok(ops.remove(0)),
        0 => Err("convert: give one of --to, --split-line, --split-curve, --trim".into()),
        _ => Err("convert: give only one of --to, --split-line, --split-curve, --trim".into()),
    }
}

/// Runs the conversion of one `triangle` / `tensor` object; writes the SVG when asked.
pub(crate) fn run(shape_json: &Value, args: &ConvertArgs) -> Result<Value, String> {
    let input = read_patch(shape_json)?;
    let op = operation(args)?;
    let lib = |e: cagd_core::Error| e.to_string();
    let need_tri = |what: &str| format!("{what} needs a \"triangle\" input");
    let need_rect = |what: &str| format!("{what} needs a \"tensor\" input");
    let (pieces, single) = match (&input, op) {
        (PatchSurface::Tri(t), Op::Rectangle) => (
            vec![cagd_convert::triangle_to_degenerate_rect(t, t.degree()).map_err(lib)?],
            true,
        ),
        (PatchSurface::Tri(t), Op::Rectangles3(s)) => (
            cagd_convert::triangle_to_three_rects(t, s)
                .map_err(lib)?
                .to_vec(),
            false,
        ),
        (PatchSurface::Tensor(p), Op::Triangles) => (
            cagd_convert::rect_to_two_triangle_pieces(p).map_err(lib)?,
            false,
        ),
        (PatchSurface::Tensor(p), Op::Triangle(tol)) => {
            let t = cagd_convert::degenerate_rect_to_triangle(p, tol).map_err(lib)?;
            let piece = PatchPiece {
                surface: PatchSurface::Tri(t),
                domain: PieceDomain::Triangle([[1.0, 0.0], [0.0, 1.0], [0.0, 0.0]]),
            };
            // The triangle covers the rectangle's (s, t) square through s = u,
            // t = v / (1 - u): report its difference in the rectangle's parameters.
            let d = inverse_difference(p, &piece);
            let mut v = surface_json(&piece.surface);
            v["domain"] = json!({"degenerate_rect": "u = s, v = (1 - s) t"});
            v["report"] = json!({"max_difference": d, "samples": (GRID + 1) * (GRID + 1)});
            svg::write(args.svg.as_deref(), &input, &[piece])?;
            return Ok(v);
        }
        (PatchSurface::Tensor(p), Op::Line(f1, f0)) => (
            cagd_convert::split_along_line(p, f1, f0).map_err(lib)?,
            false,
        ),
        (PatchSurface::Tensor(p), Op::Curve(a)) => {
            (cagd_convert::split_along_curve(p, &a).map_err(lib)?, false)
        }
        (PatchSurface::Tensor(p), Op::Trim(file)) => {
            let chain = trim::read(&file)?;
            (
                cagd_convert::trim_to_patches(p, &chain).map_err(lib)?,
                false,
            )
        }
        (PatchSurface::Tensor(_), Op::Rectangle) => return Err(need_tri("--to rectangle")),
        (PatchSurface::Tensor(_), Op::Rectangles3(_)) => return Err(need_tri("--to rectangles3")),
        (PatchSurface::Tri(_), Op::Triangles) => return Err(need_rect("--to triangles")),
        (PatchSurface::Tri(_), Op::Triangle(_)) => return Err(need_rect("--to triangle")),
        (PatchSurface::Tri(_), Op::Line(..)) => return Err(need_rect("--split-line")),
        (PatchSurface::Tri(_), Op::Curve(_)) => return Err(need_rect("--split-curve")),
        (PatchSurface::Tri(_), Op::Trim(_)) => return Err(need_rect("--trim")),
    };
    svg::write(args.svg.as_deref(), &input, &pieces)?;
    let mut out: Vec<Value> = pieces.iter().map(|p| piece_json(&input, p)).collect();
    Ok(if single {
        out.remove(0)
    } else {
        Value::Array(out)
    })
}

/// Largest difference between a degenerate rectangle and its triangle at `T(s, (1-s)t)`.
fn inverse_difference(p: &TensorSurface, piece: &PatchPiece) -> f64 {
    let mut worst: f64 = 0.0;
    for a in 0..=GRID {
        for b in 0..=GRID {
            let (s, t) = (a as f64 / GRID as f64, b as f64 / GRID as f64);
            let x = p.eval(s, t);
            let y = piece.surface.eval(s, (1.0 - s) * t);
            for (u, v) in x.iter().zip(&y) {
                worst = worst.max((u - v).abs());
            }
        }
    }
    worst
}
