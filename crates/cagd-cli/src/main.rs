//! The `cagd` command: degree reduction of Bézier / B-spline curves and patches from JSON
//! files, with SVG pictures, and `cagd demo`, the seeds' worked examples on built-in data.
//!
//! Exit codes: 0 success, 1 a computation failed (e.g. a tolerance that cannot be met),
//! 2 bad input or usage (one line on stderr naming the field and index).

mod args;
mod input;
mod shape;
mod svg;

use std::process::ExitCode;

fn main() -> ExitCode {
    let argv: Vec<String> = std::env::args().skip(1).collect();
    match args::parse(&argv) {
        Ok(args::Command::Help) => {
            print!("{}", args::USAGE);
            ExitCode::SUCCESS
        }
        Ok(_) => {
            eprintln!("cagd: this build has no reduction engine yet");
            ExitCode::from(1)
        }
        Err(msg) => {
            eprintln!("cagd: {msg}");
            eprint!("{}", args::USAGE);
            ExitCode::from(2)
        }
    }
}
