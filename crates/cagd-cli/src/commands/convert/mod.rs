//! `cagd convert --to bezier|nurbs`: NURBS ↔ rational Bézier (SPEC-convert §15.1–15.3, the
//! general route of cagd-convert), on the command's JSON shapes.
//!
//! - `bspline --to bezier`: the pieces as the `"beziers"` object `cagd merge` reads
//!   (`segments`, `weights` — `null` when polynomial — and `breaks`, the distinct knot
//!   values of the domain; for an unclamped spline also `outer_knots`, `{"left": [...],
//!   "right": [...]}`, its knots before the last copy of the first break and after the
//!   first copy of the last one, which `--to nurbs` reads back so that the round trip
//!   gives the same knot vector), plus a `"report"` (pieces, continuity at each joint from the
//!   knot multiplicities, the largest evaluation difference measured);
//! - `beziers` (or one `bezier`) `--to nurbs`: one `"bspline"` (with `weights` when
//!   rational) with the highest continuity the pieces have at each joint (`--tol T`: the
//!   joint tolerance in homogeneous coordinates, default rounding level), plus a report;
//! - `bspline-surface --to bezier` gives a `"bezier-patches"` object (`degree`, `breaks_u`,
//!   `breaks_v`, `patches` u outer / v inner, each i-major, `weights` or `null`), which
//!   `--to nurbs` turns back into one `"bspline-surface"`;
//! - `--standard-form`: rational Bézier output (a `bezier`, or every piece) in standard form
//!   (end weights 1; the pieces are then only G1 where they were C1).
//!
//! Triangle and tensor inputs and the split / trim options are the patch conversions of
//! §15.4–15.7, routed to [`patch_conversion`].

pub(crate) mod patch;

use cagd_convert::{
    BezierPieces, patches_to_nurbs, pieces_to_nurbs, standard_form, surface_to_bezier_patches,
    to_bezier_pieces,
};
use cagd_core::{BSplineCurve, BSplineSurface, BezierCurve, SurfacePatchPiece, TensorPatch};
use std::process::ExitCode;

use serde_json::{Value, json};

use crate::commands::args::ConvertArgs;
use crate::input::shape::{Shape, locate, rows};
use crate::input::{InputError, count, field, numbers, parse_input, point_list};
use crate::output::svg::{Panel, project};

/// The output of a conversion: the JSON and, for `--svg`, the panels of a picture.
pub(crate) struct Converted {
    pub(crate) json: Value,
    pub(crate) picture: Vec<Panel>,
}

/// Samples per piece of the measured difference in the reports.
const SAMPLES: usize = 32;

/// Reads the input text and converts as `args` asks.
pub(crate) fn run(text: &str, args: &ConvertArgs) -> Result<Converted, InputError> {
    let value: Value = serde_json::from_str(text).map_err(|e| {
        let path = crate::input::json_path::path_at(text, e.line(), e.column(), "input");
        InputError::new(path, format!("not valid JSON: {e}"))
    })?;
    let ty = value.get("type").and_then(Value::as_str).unwrap_or("");
    let patch_flags = args.inner.is_some()
        || args.edges.is_some()
        || args.split_line.is_some()
        || args.split_curve.is_some()
        || args.trim.is_some();
    if patch_flags || matches!(ty, "triangle" | "tensor") {
        return patch_conversion(&value, args);
    }
    let to = args
        .to
        .as_deref()
        .ok_or_else(|| InputError::new("--to", "convert needs --to bezier or --to nurbs"))?;
    match (to, ty) {
        ("bezier", "bspline") => {
            let Shape::BSpline(c) = build(text)? else {
                return Err(InputError::new("input.type", "expected a bspline"));
            };
            spline_to_beziers(&c, args.standard_form)
        }
        ("bezier", "bezier") => {
            let Shape::Bezier(b) = build(text)? else {
                return Err(InputError::new("input.type", "expected a bezier"));
            };
            let out = if args.standard_form {
                standard(&b, "input")?
            } else {
                b
            };
            Ok(Converted {
                picture: Vec::new(),
                json: Shape::Bezier(out).to_json(),
            })
        }
        ("bezier", "bspline-surface") => {
            let Shape::BSplineSurface(s) = build(text)? else {
                return Err(InputError::new("input.type", "expected a bspline-surface"));
            };
            surface_to_patches(&s)
        }
        ("nurbs", "beziers") => {
            let b = crate::input::beziers::parse(text)?;
            let pieces = BezierPieces::from_segments(&b.segments, &b.breaks)
                .map_err(|e| InputError::new("input", e.to_string()))?;
            let pieces = with_outer_knots(&value, pieces)?;
            beziers_to_spline(&pieces, args.tol)
        }
        ("nurbs", "bezier") => {
            let Shape::Bezier(b) = build(text)? else {
                return Err(InputError::new("input.type", "expected a bezier"));
            };
            let pieces = BezierPieces::from_segments(&[b], &[0.0, 1.0])
                .map_err(|e| InputError::new("input", e.to_string()))?;
            beziers_to_spline(&pieces, args.tol)
        }
        ("nurbs", "bspline") => {
            let Shape::BSpline(c) = build(text)? else {
                return Err(InputError::new("input.type", "expected a bspline"));
            };
            let pieces =
                to_bezier_pieces(&c).map_err(|e| InputError::new("input", e.to_string()))?;
            beziers_to_spline(&pieces, args.tol)
        }
        ("nurbs", "bezier-patches") => patches_to_surface(&value, args.tol),
        ("bezier" | "nurbs", other) => Err(InputError::new(
            "input.type",
            format!(
                "convert --to {to} does not take {other:?} (bspline, bezier, beziers, \
                 bspline-surface or bezier-patches)"
            ),
        )),
        (other, _) => Err(InputError::new(
            "--to",
            format!("{other:?} is not bezier or nurbs"),
        )),
    }
}

/// The patch conversions of SPEC-convert §15.4–15.7 (triangle ↔ tensor, splits along a
/// line or a curve, trimmed → untrimmed): the single entry point the patch conversions
/// (issue 11) replace.
pub(crate) fn patch_conversion(value: &Value, args: &ConvertArgs) -> Result<Converted, InputError> {
    let json = patch::run(value, args).map_err(|e| match e.split_once(": ") {
        Some((path, message)) => InputError::new(path, message),
        None => InputError::new("input", e),
    })?;
    // The patch conversions draw their own picture (the domain tiling and the nets).
    Ok(Converted {
        json,
        picture: Vec::new(),
    })
}

/// One shape of the input, validated by the shared readers.
fn build(text: &str) -> Result<Shape, InputError> {
    let raw = parse_input(text)?
        .into_iter()
        .next()
        .ok_or_else(|| InputError::new("input", "expected one object"))?;
    Shape::build(raw, "input")
}

fn standard(b: &BezierCurve, path: &str) -> Result<BezierCurve, InputError> {
    standard_form(b)
        .map(|s| s.curve)
        .map_err(|e| locate(path, &e))
}

fn dist(a: &[f64], b: &[f64]) -> f64 {
    a.iter()
        .zip(b)
        .map(|(x, y)| (x - y) * (x - y))
        .sum::<f64>()
        .sqrt()
}

/// The largest difference between the pieces and `eval` at `SAMPLES` parameters per piece
/// (`s = i / SAMPLES`, `i < SAMPLES`, and `s = 1` on the last piece: a spline takes the
/// right piece's value at a break, which differs from the left piece's end where the
/// pieces do not meet).
fn measured(pieces: &BezierPieces, eval: &dyn Fn(f64) -> Option<Vec<f64>>) -> f64 {
    let b = pieces.breaks();
    let mut worst = 0.0f64;
    for k in 0..pieces.len() {
        let Ok(seg) = pieces.piece(k) else { continue };
        let top = if k + 1 == pieces.len() {
            SAMPLES
        } else {
            SAMPLES - 1
        };
        for i in 0..=top {
            let s = i as f64 / SAMPLES as f64;
            let t = b[k] + s * (b[k + 1] - b[k]);
            match eval(t) {
                Some(y) => worst = worst.max(dist(&seg.eval(s), &y)),
                None => worst = f64::INFINITY,
            }
        }
    }
    worst
}

/// Continuity at each interior break of a spline: `p - multiplicity`.
fn knot_continuity(c: &BSplineCurve, breaks: &[f64]) -> Vec<i64> {
    let p = i64::try_from(c.degree()).unwrap_or(i64::MAX);
    breaks[1..breaks.len() - 1]
        .iter()
        .map(|b| p - i64::try_from(cagd_core::knot_multiplicity(c.knots(), *b)).unwrap_or(0))
        .collect()
}

/// The optional `"outer_knots": {"left": [...], "right": [...]}` of a `"beziers"` object
/// (the knots of an unclamped spline beyond its first and last break, see
/// [`cagd_convert::OuterKnots`]), attached to the pieces; absent or `null`: clamped.
fn with_outer_knots(obj: &Value, pieces: BezierPieces) -> Result<BezierPieces, InputError> {
    let o = match obj.get("outer_knots") {
        None | Some(Value::Null) => return Ok(pieces),
        Some(o) if o.is_object() => o,
        Some(_) => {
            return Err(InputError::new(
                "input.outer_knots",
                "expected {\"left\": [...], \"right\": [...]} or null",
            ));
        }
    };
    let left = numbers(
        field(o, "input.outer_knots", "left")?,
        "input.outer_knots.left",
    )?;
    let right = numbers(
        field(o, "input.outer_knots", "right")?,
        "input.outer_knots.right",
    )?;
    pieces.with_outer_knots(left, right).map_err(|e| {
        let side = match &e {
            cagd_core::Error::BadParameter { name, .. } => name.trim_start_matches("outer_knots"),
            _ => "",
        };
        InputError::new(format!("input.outer_knots{side}"), e.to_string())
    })
}

/// The `"beziers"` object of pieces (with `"outer_knots"` when they come from an
/// unclamped spline).
fn beziers_json(pieces: &BezierPieces, segs: &[BezierCurve]) -> Value {
    let dim = pieces.dim();
    let weights = if segs.iter().any(BezierCurve::is_rational) {
        json!(
            segs.iter()
                .map(|s| json!(s.weights().unwrap_or(&[])))
                .collect::<Vec<_>>()
        )
    } else {
        Value::Null
    };
    let mut json = json!({
        "type": "beziers",
        "degree": pieces.degree(),
        "segments": segs.iter().map(|s| rows(s.points(), dim)).collect::<Vec<_>>(),
        "weights": weights,
        "breaks": pieces.breaks(),
    });
    if let Some(o) = pieces.outer_knots() {
        json["outer_knots"] = json!({"left": o.left(), "right": o.right()});
    }
    json
}

/// `x`, or the error naming `what` when it is not finite: a report never carries a NaN or
/// an infinity (issue 18: coordinates of 1e308 overflowed the measured difference and the
/// certified bound of a conversion, written as `null`).
fn finite(x: f64, what: &str) -> Result<f64, InputError> {
    if x.is_finite() {
        Ok(x)
    } else {
        Err(InputError::new(
            "input",
            format!("the conversion's {what} is {x} (coordinates too large: it overflows)"),
        ))
    }
}

fn spline_to_beziers(c: &BSplineCurve, standard_form: bool) -> Result<Converted, InputError> {
    let pieces = to_bezier_pieces(c).map_err(|e| InputError::new("input", e.to_string()))?;
    let mut segs = pieces
        .to_segments()
        .map_err(|e| InputError::new("input", e.to_string()))?;
    let diff = finite(measured(&pieces, &|t| c.eval(t).ok()), "max_difference")?;
    if standard_form {
        for (k, s) in segs.iter_mut().enumerate() {
            *s = standard(s, &format!("pieces[{k}]"))?;
        }
    }
    let mut json = beziers_json(&pieces, &segs);
    json["report"] = json!({
        "conversion": "nurbs -> bezier (Böhm knot insertion, SPEC-convert §15.1-15.3 general route)",
        "pieces": pieces.len(),
        "continuity": knot_continuity(c, pieces.breaks()),
        "max_difference": diff,
        "standard_form": standard_form,
    });
    Ok(Converted {
        picture: picture(c, &pieces, "nurbs -> bezier"),
        json,
    })
}

fn beziers_to_spline(pieces: &BezierPieces, tol: Option<f64>) -> Result<Converted, InputError> {
    let r = pieces_to_nurbs(pieces, tol).map_err(|e| InputError::new("input", e.to_string()))?;
    let diff = finite(
        measured(pieces, &|t| r.curve.eval(t).ok()),
        "max_difference",
    )?;
    finite(r.bound, "certified_bound")?;
    let picture = picture(&r.curve, pieces, "bezier -> nurbs");
    let mut json = Shape::BSpline(r.curve).to_json();
    json["report"] = json!({
        "conversion": "bezier -> nurbs (exact merge, knot removal at each joint, blossoms)",
        "pieces": pieces.len(),
        "continuity": r.continuity,
        "tolerance": r.tolerance,
        "certified_bound": r.bound,
        "max_difference": diff,
    });
    Ok(Converted { json, picture })
}

/// The picture: the curve, its B-spline control polygon (grey) and every piece's Bézier
/// control polygon (red).
fn picture(c: &BSplineCurve, pieces: &BezierPieces, title: &str) -> Vec<Panel> {
    let mut geo = Panel {
        title: format!(
            "{title}: degree {}, {} pieces; B-spline polygon (grey), Bézier polygons (red)",
            c.degree(),
            pieces.len()
        ),
        equal_aspect: true,
        ..Panel::default()
    };
    geo.polygon(c.points().chunks(c.dim()).map(project).collect(), "#888888");
    for k in 0..pieces.len() {
        geo.polygon(
            pieces
                .piece_points(k)
                .chunks(pieces.dim())
                .map(project)
                .collect(),
            "#e08080",
        );
    }
    let (lo, hi) = c.domain();
    let n = 40 * pieces.len().clamp(10, 100);
    let line = (0..=n)
        .filter_map(|i| c.eval(lo + (hi - lo) * i as f64 / n as f64).ok())
        .map(|p| project(&p))
        .collect();
    geo.line(line, "black", 1.4);
    vec![geo]
}

fn surface_to_patches(s: &BSplineSurface) -> Result<Converted, InputError> {
    let patches =
        surface_to_bezier_patches(s).map_err(|e| InputError::new("input", e.to_string()))?;
    let nv = patches
        .iter()
        .take_while(|pc| patches.first().is_some_and(|f| f.u == pc.u))
        .count()
        .max(1);
    let mut bu: Vec<f64> = patches.iter().step_by(nv).map(|pc| pc.u.0).collect();
    let mut bv: Vec<f64> = patches[..nv.min(patches.len())]
        .iter()
        .map(|pc| pc.v.0)
        .collect();
    if let Some(last) = patches.last() {
        bu.push(last.u.1);
        bv.push(last.v.1);
    }
    let dim = s.dim();
    let weights = if s.is_rational() {
        json!(
            patches
                .iter()
                .map(|p| json!(p.weights.as_deref().unwrap_or(&[])))
                .collect::<Vec<_>>()
        )
    } else {
        Value::Null
    };
    let (p, q) = s.degrees();
    let json = json!({
        "type": "bezier-patches",
        "degree": [p, q],
        "breaks_u": bu,
        "breaks_v": bv,
        "patches": patches.iter().map(|pc| rows(pc.patch.points(), dim)).collect::<Vec<_>>(),
        "weights": weights,
        "report": {
            "conversion": "nurbs surface -> bezier patches (Böhm knot insertion in u, then v)",
            "patches": patches.len(),
        },
    });
    Ok(Converted {
        json,
        picture: Vec::new(),
    })
}

/// Reads a `"bezier-patches"` object and merges it into one surface.
fn patches_to_surface(obj: &Value, tol: Option<f64>) -> Result<Converted, InputError> {
    let dp = "input.degree";
    let d = field(obj, "input", "degree")?
        .as_array()
        .filter(|a| a.len() == 2)
        .ok_or_else(|| InputError::new(dp, "expected [p, q]"))?;
    let (p, q) = (
        count(&d[0], "input.degree[0]")?,
        count(&d[1], "input.degree[1]")?,
    );
    let bu = numbers(field(obj, "input", "breaks_u")?, "input.breaks_u")?;
    let bv = numbers(field(obj, "input", "breaks_v")?, "input.breaks_v")?;
    let list = field(obj, "input", "patches")?
        .as_array()
        .ok_or_else(|| InputError::new("input.patches", "expected an array of patches"))?;
    let (nu, nv) = (bu.len().saturating_sub(1), bv.len().saturating_sub(1));
    if list.len() != nu * nv || nu == 0 || nv == 0 {
        return Err(InputError::new(
            "input.patches",
            format!(
                "has {} patches, expected (breaks_u - 1) (breaks_v - 1) = {}",
                list.len(),
                nu * nv
            ),
        ));
    }
    let weights = match obj.get("weights") {
        None | Some(Value::Null) => None,
        Some(w) => Some(
            w.as_array()
                .ok_or_else(|| InputError::new("input.weights", "expected one list per patch"))?,
        ),
    };
    let mut pieces = Vec::with_capacity(list.len());
    for (k, pv) in list.iter().enumerate() {
        let path = format!("input.patches[{k}]");
        let pts = point_list(pv, &path)?;
        let patch = TensorPatch::new(pts.coords, p, q, pts.dim).map_err(|e| locate(&path, &e))?;
        let w = match weights {
            None => None,
            Some(ws) => {
                let wp = format!("input.weights[{k}]");
                let w = numbers(
                    ws.get(k).ok_or_else(|| InputError::new(&wp, "missing"))?,
                    &wp,
                )?;
                cagd_core::check_weights(&w, (p + 1) * (q + 1)).map_err(|e| locate(&wp, &e))?;
                Some(w)
            }
        };
        pieces.push(SurfacePatchPiece {
            u: (bu[k / nv], bu[k / nv + 1]),
            v: (bv[k % nv], bv[k % nv + 1]),
            patch,
            weights: w,
        });
    }
    let r = patches_to_nurbs(&pieces, tol).map_err(|e| InputError::new("input", e.to_string()))?;
    let mut json = Shape::BSplineSurface(r.surface).to_json();
    json["report"] = json!({
        "conversion": "bezier patches -> nurbs surface",
        "patches": pieces.len(),
        "continuity_u": r.continuity_u,
        "continuity_v": r.continuity_v,
        "tolerance": r.tolerance,
        "certified_bound": r.bound,
    });
    Ok(Converted {
        json,
        picture: Vec::new(),
    })
}

/// `cagd convert`: one object in, its other form out (and a picture with `--svg`).
pub(crate) fn command(args: &ConvertArgs) -> ExitCode {
    let result = crate::input::read_input(args.input.as_deref())
        .and_then(|text| run(&text, args).map_err(|e| e.to_string()));
    let out = match result {
        Ok(v) => v,
        Err(e) => {
            eprintln!("cagd: {e}");
            return ExitCode::from(2);
        }
    };
    // An empty picture: the conversion wrote its own (the patch conversions).
    if let Some(svg_path) = args.svg.as_ref().filter(|_| !out.picture.is_empty()) {
        if let Err(e) = crate::output::json::write_output(
            Some(svg_path),
            &crate::output::svg::render(&[out.picture]),
        ) {
            eprintln!("cagd: {e}");
            return ExitCode::from(1);
        }
    }
    crate::output::json::write_json(args.output.as_deref(), &out.json)
}
