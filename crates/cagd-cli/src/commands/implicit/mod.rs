//! `cagd implicitize` and `cagd intersect`: implicitization of a planar rational Bézier
//! curve (SPEC-convert §15.8) and curve–curve intersection through it (cagd-implicit).

pub(crate) mod intersect;

use std::path::PathBuf;

use cagd_core::{BezierCurve, Error};
use cagd_implicit::{
    BasePointPolicy, ImplicitCurve, ImplicitOptions, Intersection, implicitize_with, intersect,
};
use serde_json::{Value, json};

use crate::input::shape::{Shape, locate};
use crate::input::{InputError, parse_input};

/// Options of `cagd implicitize`.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct ImplicitizeArgs {
    pub(crate) input: Option<PathBuf>,
    pub(crate) output: Option<PathBuf>,
    pub(crate) svg: Option<PathBuf>,
    /// Divide base points out instead of refusing the curve.
    pub(crate) divide_base_points: bool,
}

/// Options of `cagd intersect`.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct IntersectArgs {
    pub(crate) a: PathBuf,
    pub(crate) b: PathBuf,
    pub(crate) output: Option<PathBuf>,
    pub(crate) svg: Option<PathBuf>,
}

/// Reads one planar `bezier` object (rational when it has `weights`).
pub(crate) fn read_bezier(text: &str, path: &str) -> Result<BezierCurve, InputError> {
    let mut raws = parse_input(text)?;
    if raws.len() != 1 {
        return Err(InputError::new(path, "expected one \"bezier\" object"));
    }
    match Shape::build(raws.remove(0), path)? {
        Shape::Bezier(c) => {
            cagd_implicit::check_planar(&c).map_err(|e| locate(path, &e))?;
            Ok(c)
        }
        _ => Err(InputError::new(
            format!("{path}.type"),
            "expected \"bezier\"",
        )),
    }
}

/// The JSON of `cagd implicitize` for `curve`, and the implicit curve for the picture.
pub(crate) fn implicitize_json(
    curve: &BezierCurve,
    divide: bool,
) -> Result<(Value, ImplicitCurve), Error> {
    let options = ImplicitOptions {
        base_points: if divide {
            BasePointPolicy::DivideOut
        } else {
            BasePointPolicy::Reject
        },
    };
    let imp = implicitize_with(curve, &options)?;
    let curve_imp = ImplicitCurve::with_options(curve, &options)?;
    let p = &imp.polynomial;
    let r = &imp.report;
    let json = json!({
        "degree": p.degree(),
        "monomials": p.monomials().iter().map(|&(i, j, c)| json!([i, j, c])).collect::<Vec<_>>(),
        "monomials_exact": p.exact_strings().iter().map(|(i, j, c)| json!([i, j, c])).collect::<Vec<_>>(),
        "report": {
            "input_degree": r.input_degree,
            "degree": r.degree,
            "base_points": r.base_points,
            "proper": r.proper(),
            "power": r.power,
            "max_abs_coef": p.max_abs_coef(),
            "convention": "f(x,y) = det F, F = x A + y B + C0 (SPEC-convert 15.8.2-15.8.5), det F = (-1)^(n(n+1)/2) Res_t(W x - X, W y - Y)",
        },
    });
    Ok((json, curve_imp))
}

/// The JSON of one intersection.
fn hit_json(h: &Intersection) -> Value {
    json!({"s": h.s, "t": h.t, "point": [h.point[0], h.point[1]], "tangential": h.tangential})
}

/// The JSON of `cagd intersect`: intersections sorted by `s`, or a `"coincident"` report
/// when the curves overlap along an arc.
pub(crate) fn intersect_json(
    a: &BezierCurve,
    b: &BezierCurve,
) -> Result<(Value, Vec<Intersection>), Error> {
    match intersect(a, b) {
        Ok(hits) => Ok((
            json!({
                "intersections": hits.iter().map(hit_json).collect::<Vec<_>>(),
                "report": {
                    "count": hits.len(),
                    "degree_a": a.degree(),
                    "degree_b": b.degree(),
                    "coincident": false,
                    "method": "implicitize the lower-degree curve, Bernstein root isolation of the substituted polynomial, inversion, Newton polish",
                },
            }),
            hits,
        )),
        Err(Error::Coincident { s0, s1 }) => Ok((
            json!({
                "intersections": [],
                "report": {
                    "count": 0,
                    "degree_a": a.degree(),
                    "degree_b": b.degree(),
                    "coincident": true,
                    "overlap_s": [s0, s1],
                },
            }),
            Vec::new(),
        )),
        Err(e) => Err(e),
    }
}
