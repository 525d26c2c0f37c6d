//! The fuzz cases: a mutated input of some shape and a command line that reads it (every
//! subcommand and its main options), sometimes with a mutated command line too.

use serde_json::Value;

use super::mutate::{mutate, option_value};
use super::rng::Rng;
use super::seeds::{SHAPES, make};

/// One run of the command. `args` may name the placeholders `{F0}`, `{F1}` (files holding
/// `files[0]`, `files[1]`), `{OUT}` (an output file) and `{SVG}` (a picture file).
#[derive(Debug, Clone)]
pub(crate) struct Case {
    /// The shape the input started from (see [`SHAPES`]).
    pub(crate) shape: &'static str,
    /// The arguments after the program name.
    pub(crate) args: Vec<String>,
    /// What the command reads on stdin.
    pub(crate) stdin: Vec<u8>,
    /// The contents of the input files `{F0}`, `{F1}`.
    pub(crate) files: Vec<Vec<u8>>,
}

impl Case {
    /// The first subcommand word (`reduce`, `check`, ...).
    pub(crate) fn command(&self) -> &str {
        self.args.first().map_or("", String::as_str)
    }

    /// A reproducer: the command line and the inputs (cut to 600 bytes each unless
    /// `CAGD_FUZZ_FULL` is set).
    pub(crate) fn describe(&self) -> String {
        let full = std::env::var_os("CAGD_FUZZ_FULL").is_some();
        let cut = |b: &[u8]| {
            let s = String::from_utf8_lossy(b);
            if s.len() > 600 && !full {
                let mut end = 600;
                while !s.is_char_boundary(end) {
                    end -= 1;
                }
                format!("{}... ({} bytes)", &s[..end], b.len())
            } else {
                s.into_owned()
            }
        };
        let mut d = format!(
            "[{}] cagd {} <<< {}",
            self.shape,
            self.args.join(" "),
            cut(&self.stdin)
        );
        for (i, f) in self.files.iter().enumerate() {
            d.push_str(&format!("\n  {{F{i}}} = {}", cut(f)));
        }
        d
    }
}

/// The method names the command accepts (its own table).
const METHODS: &[&str] = crate::method_names::NAMES;

fn s(x: impl ToString) -> String {
    x.to_string()
}

/// The degree of the seed `v` (its `degree`, first entry of a pair, or points - 1).
fn degree_of(v: &Value) -> usize {
    let d = match v.get("degree") {
        Some(Value::Array(a)) => a.first().and_then(Value::as_u64),
        Some(d) => d.as_u64(),
        None => v
            .get("points")
            .and_then(Value::as_array)
            .map(|p| p.len().saturating_sub(1) as u64),
    };
    usize::try_from(d.unwrap_or(3)).unwrap_or(3)
}

/// A target degree around `d` (sometimes far off).
fn target(rng: &mut Rng, d: usize) -> String {
    match rng.below(10) {
        0 => s(200),
        1 => s(d + 1),
        2 => s(0),
        _ => s(rng.below(d.max(1)).max(1)),
    }
}

fn tol(rng: &mut Rng) -> String {
    s(*rng.pick(&["1e-2", "1e-4", "1e-6", "1e-9", "1e-13", "0.5", "1e3"]))
}

/// `--tol T` (half the time) and `--continuity K` (a third of those).
fn maybe_tol(rng: &mut Rng, a: &mut Vec<String>) {
    if rng.one_in(2) {
        a.extend([s("--tol"), tol(rng)]);
        if rng.one_in(3) {
            a.extend([s("--continuity"), s(rng.below(4))]);
        }
    }
}

/// A command line for an input of `shape` (`v` the valid seed); may push input files.
fn command(rng: &mut Rng, shape: &str, v: &Value, files: &mut Vec<Vec<u8>>) -> Vec<String> {
    let d = degree_of(v);
    let mut a = Vec::new();
    match shape {
        "bezier" | "bezier-rational" => match rng.below(6) {
            0 => {
                a.push(s("implicitize"));
                if rng.one_in(3) {
                    a.push(s("--divide-base-points"));
                }
            }
            1 => {
                let other = make(rng, "bezier-rational");
                files.push(other.to_string().into_bytes());
                a.extend([s("intersect"), s("{F1}"), s("{F0}")]);
            }
            2 => {
                a.extend([s("convert"), s("--to"), s("nurbs")]);
                if rng.one_in(2) {
                    a.push(s("--standard-form"));
                }
            }
            _ => {
                a.extend([s("reduce"), s("--to"), target(rng, d)]);
                let m = *rng.pick(METHODS);
                if !rng.one_in(4) {
                    a.extend([s("--method"), s(m)]);
                }
                if matches!(m, "chebyshev" | "l2") && rng.one_in(2) {
                    a.extend([s("--r"), s(rng.below(3)), s("--p"), s(rng.below(3))]);
                }
                maybe_tol(rng, &mut a);
            }
        },
        "bspline" | "nurbs" => match rng.below(5) {
            0 => a.extend([s("convert"), s("--to"), s("bezier")]),
            1 if shape == "nurbs" => {
                a.extend([s("reduce"), s("--polynomial"), s("--tol"), tol(rng)]);
                if rng.one_in(2) {
                    a.extend([s("--to"), s(1 + rng.below(d + 1))]);
                }
            }
            _ => {
                a.extend([s("reduce"), s("--to"), target(rng, d)]);
                if rng.one_in(2) {
                    a.extend([s("--tol"), tol(rng)]);
                    let st = *rng.pick(&["fit", "segments", "piegl-tiller-1995"]);
                    if !rng.one_in(3) {
                        a.extend([s("--strategy"), s(st)]);
                    }
                    if st == "segments" && rng.one_in(2) {
                        a.extend([s("--method"), s(*rng.pick(&["l2", "chebyshev"]))]);
                    }
                    if rng.one_in(2) {
                        a.extend([s("--continuity"), s(rng.below(3))]);
                    }
                } else if rng.one_in(2) {
                    a.extend([s("--merge"), s(*rng.pick(&["exact", "lossy"]))]);
                }
            }
        },
        "tensor" | "triangle" => match rng.below(9) {
            0..=3 => {
                a.extend([s("reduce"), s("--to")]);
                if shape == "tensor" && rng.one_in(2) {
                    a.push(format!("{},{}", target(rng, d), target(rng, d)));
                } else {
                    a.push(target(rng, d));
                }
                if rng.one_in(2) {
                    a.extend([s("--method"), s(*rng.pick(METHODS))]);
                }
                if rng.one_in(2) {
                    a.extend([s("--tol"), tol(rng)]);
                }
            }
            4 => {
                let to = *rng.pick(&["rectangle", "rectangles3", "triangles", "triangle"]);
                a.extend([s("convert"), s("--to"), s(to)]);
                if to == "rectangles3" && rng.one_in(2) {
                    a.extend([s("--inner"), s("0.2,0.3"), s("--edges"), s("0.5,0.25,0.75")]);
                }
            }
            5 => a.extend([s("convert"), s("--split-line"), s("0.5,0.25")]),
            6 => a.extend([s("convert"), s("--split-curve"), s("0.25,0.75,0.5")]),
            _ => {
                files.push(make(rng, "trim").to_string().into_bytes());
                a.extend([s("convert"), s("--trim"), s("{F1}")]);
            }
        },
        "bspline-surface" => match rng.below(5) {
            0 => a.extend([s("convert"), s("--to"), s("bezier")]),
            1 => a.extend([s("reduce"), s("--polynomial"), s("--tol"), tol(rng)]),
            _ => {
                a.extend([
                    s("reduce"),
                    s("--to"),
                    format!("{},{}", target(rng, d), target(rng, d)),
                ]);
                if rng.one_in(2) {
                    a.extend([s("--tol"), tol(rng)]);
                    if rng.one_in(2) {
                        a.extend([s("--strategy"), s(*rng.pick(&["fit", "segments"]))]);
                    }
                }
                if rng.one_in(2) {
                    a.extend([s("--method"), s(*rng.pick(&["l2", "chebyshev"]))]);
                    a.extend([s("--continuity"), s(rng.below(3))]);
                }
            }
        },
        "beziers" => {
            if rng.one_in(3) {
                a.extend([s("convert"), s("--to"), s("nurbs")]);
                if rng.one_in(2) {
                    a.push(s("--standard-form"));
                }
            } else {
                a.push(s("merge"));
                if rng.one_in(2) {
                    a.extend([s("--continuity"), s(rng.below(3))]);
                }
            }
            if rng.one_in(3) {
                a.extend([s("--tol"), tol(rng)]);
            }
        }
        "bezier-patches" => a.extend([s("convert"), s("--to"), s("nurbs")]),
        "wsgb" => {
            a.extend([s("reduce"), s("--to"), target(rng, d)]);
            let m = *rng.pick(&[
                "perturbation",
                "uniform",
                "bezier-perturbation",
                "l2",
                "eck",
            ]);
            a.extend([s("--method"), s(m)]);
            maybe_tol(rng, &mut a);
        }
        "interval-triangle" => {
            a.extend([s("reduce"), s("--to"), target(rng, d)]);
            if rng.one_in(2) {
                a.extend([s("--containment-degree"), s(d + rng.below(3))]);
            }
        }
        // The mutated text is the trim file; a valid patch on stdin.
        "trim" => a.extend([s("convert"), s("--trim"), s("{F0}")]),
        _ => a.extend([s("check"), s("{F0}")]),
    }
    a
}

/// Damages the command line: an option's value replaced, an argument dropped or repeated,
/// `--help` or an unknown option added.
fn mutate_args(rng: &mut Rng, a: &mut Vec<String>) {
    if a.len() < 2 {
        return;
    }
    let i = 1 + rng.below(a.len() - 1);
    match rng.below(5) {
        0 => a[i] = option_value(rng),
        1 => {
            a.remove(i);
        }
        2 => {
            let x = a[i].clone();
            a.insert(i, x);
        }
        3 => a.push(s(
            *rng.pick(&["--help", "-h", "--frob", "--to", "-i", "--tol"])
        )),
        _ => {
            if let Some(j) = a.iter().position(|x| x.starts_with("--") && x != "--help") {
                if j + 1 < a.len() {
                    a[j + 1] = option_value(rng);
                }
            }
        }
    }
}

/// The next case.
pub(crate) fn next_case(rng: &mut Rng) -> Case {
    let shape = *rng.pick(SHAPES);
    let seed = make(rng, shape);
    let mut files = Vec::new();
    let mutated = mutate(rng, &seed);
    let mut stdin = Vec::new();
    let mut args;
    match shape {
        "vectors" => {
            files.push(mutated);
            args = command(rng, shape, &seed, &mut files);
        }
        "trim" => {
            files.push(mutated);
            stdin = make(rng, "triangle").to_string().into_bytes();
            args = command(rng, shape, &seed, &mut files);
        }
        _ => {
            // An input file first ({F0}), so that commands can add {F1}.
            files.push(mutated);
            args = command(rng, shape, &seed, &mut files);
            if args.iter().any(|x| x == "{F0}") || rng.one_in(5) {
                if !args.iter().any(|x| x == "{F0}") {
                    args.extend([s("-i"), s("{F0}")]);
                }
            } else {
                stdin = files.remove(0);
                for x in &mut args {
                    if x == "{F1}" {
                        *x = s("{F0}");
                    }
                }
            }
        }
    }
    if rng.one_in(6) {
        mutate_args(rng, &mut args);
    }
    if rng.one_in(12) && args.first().is_some_and(|c| c != "check") {
        args.extend([s("-o"), s("{OUT}")]);
    }
    if rng.one_in(12) && args.first().is_some_and(|c| c != "check" && c != "merge") {
        args.extend([s("--svg"), s("{SVG}")]);
    }
    Case {
        shape,
        args,
        stdin,
        files,
    }
}
