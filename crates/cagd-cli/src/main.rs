//! The `cagd` command: degree reduction of Bézier / B-spline curves, patches and B-spline /
//! NURBS surfaces from JSON files, with SVG pictures; `cagd merge`, the exact merge of
//! Bézier segments into one B-spline (seed 001 §4.1); and `cagd demo`, the seeds' worked
//! examples on built-in data.
//!
//! `cagd implicitize` and `cagd intersect` implicitize planar rational Bézier curves and
//! intersect two of them (cagd-implicit).
//!
//! `cagd check FILE…` runs spec-vector files through the library (see [`check`]).
//!
//! Exit codes: 0 success; 2 bad input, bad usage or a reduction that cannot be done as asked
//! (one line on stderr naming the field or option and index); 1 an I/O failure.

mod args;
mod check;
mod convert_cmd;
mod convert_patch_cmd;
mod convert_patch_svg;
mod convert_patch_trim;
mod demo;
mod demo_convert;
mod demo_convert_patch;
mod demo_implicit;
mod demo_interval;
mod demo_patches;
mod demo_splines;
mod demo_wsgb;
mod implicit_cmd;
mod implicit_svg;
mod input;
mod input_beziers;
mod input_surface;
mod intersect_cmd;
mod interval_cmd;
mod json_path;
mod merge_cmd;
mod methods;
mod patch_cmd;
mod picture;
mod polynomial_cmd;
mod reduce_cmd;
mod shape;
mod spline_cmd;
mod surface_cmd;
mod surface_shape;
mod svg;
mod wsgb_cmd;

use std::io::{Read, Write};
use std::path::Path;
use std::process::ExitCode;

use serde_json::Value;

fn read_input(path: Option<&Path>) -> Result<String, String> {
    let mut text = String::new();
    match path {
        Some(p) => {
            text = std::fs::read_to_string(p).map_err(|e| format!("{}: {e}", p.display()))?;
        }
        None => {
            std::io::stdin()
                .read_to_string(&mut text)
                .map_err(|e| format!("stdin: {e}"))?;
        }
    }
    Ok(text)
}

fn write_output(path: Option<&Path>, text: &str) -> Result<(), String> {
    match path {
        Some(p) => std::fs::write(p, text).map_err(|e| format!("{}: {e}", p.display())),
        None => {
            let mut out = std::io::stdout().lock();
            out.write_all(text.as_bytes())
                .and_then(|()| out.flush())
                .map_err(|e| format!("stdout: {e}"))
        }
    }
}

fn reduce(args: &args::ReduceArgs) -> ExitCode {
    let text = match read_input(args.input.as_deref()) {
        Ok(t) => t,
        Err(e) => {
            eprintln!("cagd: {e}");
            return ExitCode::from(2);
        }
    };
    let single = text.trim_start().starts_with('{');
    let raws = match input::parse_input(&text) {
        Ok(r) => r,
        Err(e) => {
            eprintln!("cagd: {e}");
            return ExitCode::from(2);
        }
    };
    let mut shapes = Vec::with_capacity(raws.len());
    for (i, raw) in raws.into_iter().enumerate() {
        let path = if single {
            "input".to_string()
        } else {
            format!("input[{i}]")
        };
        match shape::Shape::build(raw, &path) {
            Ok(s) => shapes.push((path, s)),
            Err(e) => {
                eprintln!("cagd: {e}");
                return ExitCode::from(2);
            }
        }
    }
    let run = if args.polynomial {
        polynomial_cmd::run
    } else {
        reduce_cmd::run
    };
    let results = match run(&shapes, args) {
        Ok(r) => r,
        Err(f) => {
            eprintln!("cagd: {}: {}", f.path, f.message);
            return ExitCode::from(2);
        }
    };
    if let Some(svg_path) = &args.svg {
        let rows: Vec<_> = results
            .iter()
            .zip(&shapes)
            .filter_map(|(o, (path, _))| o.pair.as_ref().map(|(a, b)| picture::panels(path, a, b)))
            .filter(|row| !row.is_empty())
            .collect();
        if let Err(e) = write_output(Some(svg_path), &svg::render(&rows)) {
            eprintln!("cagd: {e}");
            return ExitCode::from(1);
        }
    }
    let values: Vec<Value> = results.into_iter().map(|o| o.json).collect();
    let json = if single && values.len() == 1 {
        values.into_iter().next().unwrap_or(Value::Null)
    } else {
        Value::Array(values)
    };
    write_json(args.output.as_deref(), &json)
}

/// Writes `json` (pretty, one trailing newline) to `path` or stdout; exit code 1 on an I/O
/// failure.
fn write_json(path: Option<&Path>, json: &Value) -> ExitCode {
    let mut text = serde_json::to_string_pretty(json).unwrap_or_default();
    text.push('\n');
    match write_output(path, &text) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("cagd: {e}");
            ExitCode::from(1)
        }
    }
}

/// `cagd merge`: one object in, one B-spline out.
fn merge(args: &args::MergeArgs) -> ExitCode {
    let result = read_input(args.input.as_deref())
        .and_then(|text| merge_cmd::run(&text, args).map_err(|e| e.to_string()));
    let json = match result {
        Ok(v) => v,
        Err(e) => {
            eprintln!("cagd: {e}");
            return ExitCode::from(2);
        }
    };
    write_json(args.output.as_deref(), &json)
}

/// `cagd convert`: one object in, its other form out (and a picture with `--svg`).
fn convert(args: &args::ConvertArgs) -> ExitCode {
    let result = read_input(args.input.as_deref())
        .and_then(|text| convert_cmd::run(&text, args).map_err(|e| e.to_string()));
    let out = match result {
        Ok(v) => v,
        Err(e) => {
            eprintln!("cagd: {e}");
            return ExitCode::from(2);
        }
    };
    // An empty picture: the conversion wrote its own (the patch conversions).
    if let Some(svg_path) = args.svg.as_ref().filter(|_| !out.picture.is_empty()) {
        if let Err(e) = write_output(Some(svg_path), &svg::render(&[out.picture])) {
            eprintln!("cagd: {e}");
            return ExitCode::from(1);
        }
    }
    write_json(args.output.as_deref(), &out.json)
}

fn main() -> ExitCode {
    let argv: Vec<String> = std::env::args().skip(1).collect();
    match args::parse(&argv) {
        Ok(args::Command::Help) => {
            print!("{}", args::USAGE);
            ExitCode::SUCCESS
        }
        Ok(args::Command::Reduce(r)) => reduce(&r),
        Ok(args::Command::Merge(m)) => merge(&m),
        Ok(args::Command::Convert(c)) => convert(&c),
        Ok(args::Command::Implicitize(a)) => intersect_cmd::implicitize(&a),
        Ok(args::Command::Intersect(a)) => intersect_cmd::intersect(&a),
        Ok(args::Command::Check { files }) => match check::run_files(&files) {
            Ok(true) => ExitCode::SUCCESS,
            Ok(false) => ExitCode::from(1),
            Err(e) => {
                eprintln!("cagd: check: {e}");
                ExitCode::from(2)
            }
        },
        Ok(args::Command::Demo { out }) => match demo::run(&out) {
            Ok(()) => ExitCode::SUCCESS,
            Err(e) => {
                eprintln!("cagd: demo: {e}");
                ExitCode::from(1)
            }
        },
        Err(msg) => {
            eprintln!("cagd: {msg}");
            eprint!("{}", args::USAGE);
            ExitCode::from(2)
        }
    }
}
