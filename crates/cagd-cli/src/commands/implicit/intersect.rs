//! Running `cagd implicitize` and `cagd intersect` (I/O and exit codes; the JSON is built in
//! [`crate::commands::implicit`]).

use std::process::ExitCode;

use crate::commands::implicit::{
    ImplicitizeArgs, IntersectArgs, implicitize_json, intersect_json, read_bezier,
};

/// `cagd implicitize`.
pub(crate) fn implicitize(args: &ImplicitizeArgs) -> ExitCode {
    let text = match crate::input::read_input(args.input.as_deref()) {
        Ok(t) => t,
        Err(e) => {
            eprintln!("cagd: {e}");
            return ExitCode::from(2);
        }
    };
    let curve = match read_bezier(&text, "input") {
        Ok(c) => c,
        Err(e) => {
            eprintln!("cagd: {e}");
            return ExitCode::from(2);
        }
    };
    let (json, imp) = match implicitize_json(&curve, args.divide_base_points) {
        Ok(r) => r,
        Err(e) => {
            eprintln!("cagd: input: {e}");
            return ExitCode::from(2);
        }
    };
    if let Some(svg) = &args.svg {
        let pic = crate::output::implicit::render(&curve, &imp, &[], &[]);
        if let Err(e) = crate::output::json::write_output(Some(svg), &pic) {
            eprintln!("cagd: {e}");
            return ExitCode::from(1);
        }
    }
    crate::output::json::write_json(args.output.as_deref(), &json)
}

/// `cagd intersect A.json B.json`.
pub(crate) fn intersect(args: &IntersectArgs) -> ExitCode {
    let mut curves = Vec::new();
    for (path, name) in [(&args.a, "a"), (&args.b, "b")] {
        let curve = crate::input::read_input(Some(path))
            .and_then(|t| read_bezier(&t, name).map_err(|e| format!("{}: {e}", path.display())));
        match curve {
            Ok(c) => curves.push(c),
            Err(e) => {
                eprintln!("cagd: {e}");
                return ExitCode::from(2);
            }
        }
    }
    let (a, b) = (&curves[0], &curves[1]);
    let (json, hits) = match intersect_json(a, b) {
        Ok(r) => r,
        Err(e) => {
            eprintln!("cagd: intersect: {e}");
            return ExitCode::from(2);
        }
    };
    if let Some(svg) = &args.svg {
        match cagd_implicit::ImplicitCurve::new(a) {
            Ok(imp) => {
                let pts: Vec<[f64; 2]> = hits.iter().map(|h| h.point).collect();
                let pic = crate::output::implicit::render(a, &imp, &[b], &pts);
                if let Err(e) = crate::output::json::write_output(Some(svg), &pic) {
                    eprintln!("cagd: {e}");
                    return ExitCode::from(1);
                }
            }
            Err(e) => {
                eprintln!("cagd: intersect: {e}");
                return ExitCode::from(2);
            }
        }
    }
    crate::output::json::write_json(args.output.as_deref(), &json)
}
