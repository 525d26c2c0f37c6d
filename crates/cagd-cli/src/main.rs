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
//! (one line on stderr naming the field or option and index); 1 an I/O failure. Inputs are
//! bounded by [`limits`]. `cagd --help` (or `-h`, or either after any subcommand) prints the
//! usage and exits 0.
//!
//! [`run`] is the whole command as a function of its arguments; [`console`] lets it run
//! in-process with buffers for its streams, as the fuzzer ([`fuzz`], tests only) does.
//!
//! Map: [`commands`] (the command line and one module per subcommand; `reduce` has one
//! part per shape), [`input`] (reading the JSON shapes), [`output`] (JSON, SVG and the
//! pictures), [`check`] (the spec-vector runner), [`demo`] (one part per demo family).

// First, with its macros: they replace print!/eprintln! in every module below.
#[macro_use]
mod console;
mod check;
mod commands;
mod demo;
#[cfg(test)]
mod fuzz;
#[cfg(test)]
mod fuzz_in_process;
mod input;
mod limits;
mod method_names;
mod output;

use std::process::ExitCode;

use commands::{args, convert, implicit, merge, reduce};

fn main() -> ExitCode {
    let argv: Vec<String> = std::env::args().skip(1).collect();
    run(&argv)
}

/// The command: `argv` without the program name; the exit code.
fn run(argv: &[String]) -> ExitCode {
    match args::parse(argv) {
        Ok(args::Command::Help) => {
            print!("{}\n{}", args::USAGE, limits::LIMITS_TEXT);
            ExitCode::SUCCESS
        }
        Ok(args::Command::Reduce(r)) => reduce::command(&r),
        Ok(args::Command::Merge(m)) => merge::command(&m),
        Ok(args::Command::Convert(c)) => convert::command(&c),
        Ok(args::Command::Implicitize(a)) => implicit::intersect::implicitize(&a),
        Ok(args::Command::Intersect(a)) => implicit::intersect::intersect(&a),
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
            eprintln!("cagd: {msg} (cagd --help prints the usage)");
            ExitCode::from(2)
        }
    }
}
