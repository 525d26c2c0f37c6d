//! Command-line parsing of the `cagd` command (no dependency: the grammar is small and the
//! messages are ours).

use std::path::PathBuf;

/// Usage text printed by `cagd --help` and after a usage error.
pub(crate) const USAGE: &str = "\
usage:
  cagd reduce --to M[,N] [--method NAME] [--r R] [--p P] [--tol T] [--continuity K]
              [--merge exact|lossy] [--strategy fit|segments|piegl-tiller-1995]
              [-i FILE] [-o FILE] [--svg FILE]
  cagd merge [--continuity K] [--tol T] [-i FILE] [-o FILE]
  cagd demo [--out DIR]
  cagd check FILE...
  cagd --help

reduce reads one JSON object or an array of objects (stdin by default) and writes JSON
(stdout by default). Methods: forrest, farin, piegl, perturbation, perturbation-g1, pinv,
pinv-ends, chebyshev (with --r/--p), eck, watkins-worsey, bogacki, l2 (with --r/--p).
--tol T turns on reduction to a tolerance (pieces within T, joined with C^K, K from
--continuity). --to M,N gives a tensor patch's or B-spline surface's target degrees
(--to M means M in both). A B-spline with uniform knots and no --tol goes through seed
001's matrix pipeline, its segments merged exactly (--merge exact, multiple knots) or by
averaging (--merge lossy); with --tol any B-spline / NURBS is reduced within the
tolerance, keeping its continuity: --strategy fit (default; global least-squares fit, up
to C^(M-1)), segments (per-segment reduction by --method l2 or chebyshev, up to
C^((M-1)/2); the default when --method is given) or piegl-tiller-1995 (the classical
algorithm: no subdivision, may fail). A B-spline / NURBS surface (\"bspline-surface\") is
reduced patch by patch (l2 or chebyshev, C^K across knot lines with --continuity K); with
--tol T by the global fit direction by direction (--strategy fit, default; knots added and
removed as for curves) or, with --strategy segments (the default when --method is given),
patch by patch with every knot span split until the certified bound is within T.
A WSGB curve ({\"type\":\"wsgb\",\"L\":L,\"points\":[...]}, seed 003) is reduced by --method
perturbation or uniform (seed 003's methods) or any Bézier method through the exact
conversion (bezier-perturbation: seed 000's perturbation), and written in WSGB form; with
--tol T as \"wsgb-pieces\".

merge reads one object {\"type\":\"beziers\",\"segments\":[[[x,y,...],...],...]} (optional
\"weights\": one list or null per segment; optional \"breaks\": count + 1 increasing values,
default 0, 1, ..., count) and merges the segments exactly into one \"bspline\" (seed 001
§4.1): segment i on [breaks[i], breaks[i+1]], interior knots of multiplicity m - K for
degree-m segments (--continuity K, default 0, K < m). The joints are checked: C0 within
T, C^K by a certified knot removal within T. --tol T defaults to
1e-9 * max(1, largest |coordinate|) (the homogeneous coordinates (w x, w) of rational
segments included); the report gives the T used.

check runs every vector of spec-vector files (the format of ../shared/spec/vectors-*.json:
a list of {id, algorithm, params, input, expected, tol}) through the library by its
algorithm, compares with expected (|got - expected| <= tol * max(1, |expected|); expected
error = the input must be refused), prints one line per vector and \"N passed, N failed\",
and exits 1 when a vector fails or names an algorithm it does not know (2: a file that
cannot be read).
";

/// Options of `cagd reduce`.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct ReduceArgs {
    pub(crate) to: (usize, Option<usize>),
    pub(crate) method: Option<String>,
    pub(crate) r: Option<i64>,
    pub(crate) p: Option<i64>,
    pub(crate) tol: Option<f64>,
    pub(crate) continuity: Option<usize>,
    pub(crate) input: Option<PathBuf>,
    pub(crate) output: Option<PathBuf>,
    pub(crate) svg: Option<PathBuf>,
    pub(crate) lossy_merge: bool,
    pub(crate) strategy: Option<String>,
}

impl ReduceArgs {
    /// The `--strategy` of a B-spline reduction to a tolerance: as given, else `segments`
    /// when `--method` is given, else `fit`.
    pub(crate) fn strategy_name(&self) -> &str {
        self.strategy
            .as_deref()
            .unwrap_or(if self.method.is_some() {
                "segments"
            } else {
                "fit"
            })
    }
}

/// Options of `cagd merge`.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct MergeArgs {
    /// The continuity `k` of the joints (default 0).
    pub(crate) continuity: usize,
    /// The tolerance of the joint check; `None` for the default relative one.
    pub(crate) tol: Option<f64>,
    pub(crate) input: Option<PathBuf>,
    pub(crate) output: Option<PathBuf>,
}

/// A parsed command line.
#[derive(Debug, Clone, PartialEq)]
pub(crate) enum Command {
    Reduce(ReduceArgs),
    Merge(MergeArgs),
    Demo { out: PathBuf },
    Check { files: Vec<PathBuf> },
    Help,
}

fn value<'a>(it: &mut impl Iterator<Item = &'a String>, flag: &str) -> Result<&'a str, String> {
    it.next()
        .map(String::as_str)
        .ok_or_else(|| format!("{flag} needs a value"))
}

fn parse_num<T: std::str::FromStr>(s: &str, flag: &str) -> Result<T, String> {
    s.parse()
        .map_err(|_| format!("{flag}: cannot read {s:?} as a number"))
}

/// The value of `--tol`: a finite number `> 0`.
fn parse_tol(s: &str) -> Result<f64, String> {
    let t: f64 = parse_num(s, "--tol")?;
    if t.is_finite() && t > 0.0 {
        Ok(t)
    } else {
        Err(format!("--tol: {t} must be finite and > 0"))
    }
}

/// The options of `cagd merge` (the arguments after `merge`).
fn parse_merge<'a>(mut it: impl Iterator<Item = &'a String>) -> Result<MergeArgs, String> {
    let mut m = MergeArgs {
        continuity: 0,
        tol: None,
        input: None,
        output: None,
    };
    while let Some(a) = it.next() {
        match a.as_str() {
            "--continuity" => m.continuity = parse_num(value(&mut it, a)?, a)?,
            "--tol" => m.tol = Some(parse_tol(value(&mut it, a)?)?),
            "-i" | "--input" => m.input = Some(PathBuf::from(value(&mut it, a)?)),
            "-o" | "--output" => m.output = Some(PathBuf::from(value(&mut it, a)?)),
            other => return Err(format!("merge: unknown argument {other:?}")),
        }
    }
    Ok(m)
}

/// Parses the arguments after the program name.
pub(crate) fn parse(args: &[String]) -> Result<Command, String> {
    let mut it = args.iter();
    let Some(cmd) = it.next() else {
        return Ok(Command::Help);
    };
    match cmd.as_str() {
        "--help" | "-h" | "help" => Ok(Command::Help),
        "demo" => {
            let mut out = PathBuf::from("cagd-demo");
            while let Some(a) = it.next() {
                match a.as_str() {
                    "--out" => out = PathBuf::from(value(&mut it, a)?),
                    other => return Err(format!("demo: unknown argument {other:?}")),
                }
            }
            Ok(Command::Demo { out })
        }
        "merge" => parse_merge(it).map(Command::Merge),
        "check" => {
            let files: Vec<PathBuf> = it.map(PathBuf::from).collect();
            if files.is_empty() {
                return Err("check: name at least one vector file".to_string());
            }
            Ok(Command::Check { files })
        }
        "reduce" => {
            let mut r = ReduceArgs {
                to: (0, None),
                method: None,
                r: None,
                p: None,
                tol: None,
                continuity: None,
                input: None,
                output: None,
                svg: None,
                lossy_merge: false,
                strategy: None,
            };
            let mut have_to = false;
            while let Some(a) = it.next() {
                match a.as_str() {
                    "--to" => {
                        let v = value(&mut it, a)?;
                        r.to = match v.split_once(',') {
                            Some((m, n)) => (parse_num(m, a)?, Some(parse_num(n, a)?)),
                            None => (parse_num(v, a)?, None),
                        };
                        have_to = true;
                    }
                    "--method" => r.method = Some(value(&mut it, a)?.to_string()),
                    "--strategy" => r.strategy = Some(value(&mut it, a)?.to_string()),
                    "--r" => r.r = Some(parse_num(value(&mut it, a)?, a)?),
                    "--p" => r.p = Some(parse_num(value(&mut it, a)?, a)?),
                    "--tol" => r.tol = Some(parse_tol(value(&mut it, a)?)?),
                    "--continuity" => r.continuity = Some(parse_num(value(&mut it, a)?, a)?),
                    "-i" | "--input" => r.input = Some(PathBuf::from(value(&mut it, a)?)),
                    "-o" | "--output" => r.output = Some(PathBuf::from(value(&mut it, a)?)),
                    "--svg" => r.svg = Some(PathBuf::from(value(&mut it, a)?)),
                    "--merge" => {
                        r.lossy_merge = match value(&mut it, a)? {
                            "exact" => false,
                            "lossy" => true,
                            other => {
                                return Err(format!("--merge: {other:?} is not exact or lossy"));
                            }
                        }
                    }
                    other => return Err(format!("reduce: unknown argument {other:?}")),
                }
            }
            if !have_to {
                return Err("reduce: --to M is required".to_string());
            }
            Ok(Command::Reduce(r))
        }
        other => Err(format!("unknown command {other:?}")),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn args(s: &str) -> Vec<String> {
        s.split_whitespace().map(String::from).collect()
    }

    #[test]
    fn reduce_arguments() {
        let Command::Reduce(r) = parse(&args(
            "reduce --to 3,2 --method l2 --r 1 --p -1 --tol 1e-3 -i a.json",
        ))
        .unwrap() else {
            panic!("not reduce");
        };
        assert_eq!(r.to, (3, Some(2)));
        assert_eq!(r.method.as_deref(), Some("l2"));
        assert_eq!((r.r, r.p, r.tol), (Some(1), Some(-1), Some(1e-3)));
        assert_eq!(r.input, Some(PathBuf::from("a.json")));
    }

    #[test]
    fn merge_arguments() {
        let Command::Merge(m) =
            parse(&args("merge --continuity 1 --tol 1e-6 -i a.json -o b.json")).unwrap()
        else {
            panic!("not merge");
        };
        assert_eq!((m.continuity, m.tol), (1, Some(1e-6)));
        assert_eq!(m.input, Some(PathBuf::from("a.json")));
        assert_eq!(m.output, Some(PathBuf::from("b.json")));
        assert_eq!(
            parse(&args("merge")).unwrap(),
            Command::Merge(MergeArgs {
                continuity: 0,
                tol: None,
                input: None,
                output: None
            })
        );
        assert_eq!(
            parse(&args("merge --tol 0")).unwrap_err(),
            "--tol: 0 must be finite and > 0"
        );
        assert_eq!(
            parse(&args("merge --continuity -1")).unwrap_err(),
            "--continuity: cannot read \"-1\" as a number"
        );
        assert_eq!(
            parse(&args("merge --to 3")).unwrap_err(),
            "merge: unknown argument \"--to\""
        );
    }

    #[test]
    fn usage_errors() {
        assert_eq!(
            parse(&args("reduce")).unwrap_err(),
            "reduce: --to M is required"
        );
        assert_eq!(
            parse(&args("reduce --to x")).unwrap_err(),
            "--to: cannot read \"x\" as a number"
        );
        assert_eq!(
            parse(&args("reduce --to 3 --tol -1")).unwrap_err(),
            "--tol: -1 must be finite and > 0"
        );
        assert_eq!(
            parse(&args("frobnicate")).unwrap_err(),
            "unknown command \"frobnicate\""
        );
        assert_eq!(
            parse(&args("reduce --to")).unwrap_err(),
            "--to needs a value"
        );
        assert_eq!(parse(&[]).unwrap(), Command::Help);
    }
}
