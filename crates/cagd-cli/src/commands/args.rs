//! Command-line parsing of the `cagd` command (no dependency: the grammar is small and the
//! messages are ours).

use std::path::PathBuf;

use crate::commands::implicit::{ImplicitizeArgs, IntersectArgs};

/// Usage text printed by `cagd --help` and after a usage error.
pub(crate) const USAGE: &str = "\
usage:
  cagd reduce --to M[,N] [--method NAME] [--r R] [--p P] [--tol T] [--continuity K]
              [--merge exact|lossy] [--strategy fit|segments|piegl-tiller-1995]
              [--containment-degree N] [--threads N] [-i FILE] [-o FILE] [--svg FILE]
  cagd reduce --polynomial --tol T [--to M[,N]] [--threads N] [-i FILE] [-o FILE] [--svg FILE]
  cagd merge [--continuity K] [--tol T] [-i FILE] [-o FILE]
  cagd convert --to bezier|nurbs [--standard-form] [--tol T] [-i FILE] [-o FILE] [--svg FILE]
  cagd convert (--to rectangle|rectangles3|triangles|triangle [--inner U,V] [--edges G,K,H]
               | --split-line F1,F0 | --split-curve A0,A1,... | --trim FILE)
               [--tol T] [-i FILE] [-o FILE] [--svg FILE]
  cagd implicitize [--divide-base-points] [-i FILE] [-o FILE] [--svg FILE]
  cagd intersect A.json B.json [-o FILE] [--svg FILE]
  cagd demo [--out DIR]
  cagd check FILE...
  cagd --help

reduce reads one JSON object or an array of objects (stdin by default) and writes JSON
(stdout by default). Methods: forrest, farin, piegl, perturbation, perturbation-g1, pinv,
pinv-ends, chebyshev (with --r/--p), eck, watkins-worsey, bogacki, l2 (with --r/--p).
--threads N reduces the objects of an array on N threads (0 or 1: one; the output is the
same). --tol T turns on reduction to a tolerance (pieces within T, joined with C^K, K from
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
An interval triangle ({\"type\":\"interval-triangle\",\"degree\":n,\"lo\":[...],\"hi\":[...]},
i-major) is wrapped by the tightest degree-M interval triangle of seed 004's LP, certified
to contain it; --containment-degree N (>= n) asks the tighter model of SPEC-convert I.2.

reduce --polynomial --tol T turns a NURBS curve (\"bspline\" with \"weights\") or surface
(\"bspline-surface\") into a polynomial one of degree <= M (default: the input's degree; M
may equal it, be lower — reduce and drop the weights in one pass — or higher) within the
certified bound T, keeping the continuity the input has at each knot (C^min(k, M-1) where
it is C^k); output: a \"bspline\" / \"bspline-surface\" without weights. Equal weights are
recognised exactly (the same control points, no spans added).

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

convert converts between NURBS and (rational) Bézier form (SPEC-convert §15.1-15.3).
--to bezier: a \"bspline\" becomes its pieces as the \"beziers\" object merge reads
(segments, weights or null, breaks = the distinct knot values), a \"bspline-surface\" its
\"bezier-patches\" (degree, breaks_u, breaks_v, patches u outer / v inner, weights);
--to nurbs: a \"beziers\" object, one \"bezier\", or \"bezier-patches\" become one
\"bspline\" / \"bspline-surface\" with the highest continuity the pieces have at each
joint (joint tolerance --tol T in homogeneous coordinates, default 1e-12 times the largest
one); the two directions round-trip. A \"report\" gives pieces, continuity and the
largest difference measured. --standard-form writes rational Bézier output with end weights
1. --svg draws the curve with both control polygons.

convert on a \"triangle\" / \"tensor\" (optional \"weights\") converts it exactly: --to
rectangle (one degenerate tensor, 15.4), --to rectangles3 (three tensors through the inner
point U,V, default the centroid, and the edge points (G,0), (K,1-K), (0,H), default 0.5
each; 15.5), --to triangles (two triangles of degree m+n, 15.6.3), --to triangle (a
degenerate n x n tensor back to its triangle within --tol, default 1e-12), --split-line
F1,F0 (the pieces on either side of u = F1 v + F0, 15.6), --split-curve A0,...,Ak (both
sides of u = f(v), f with Bernstein coefficients A, 15.7), --trim FILE (the untrimmed
pieces of the kept region, 15.7.3; FILE {\"direction\":\"u_of_v\"|\"v_of_u\",
\"keep\":\"below\"|\"above\",\"segments\":[{\"interval\":[c0,c1],\"bezier\":[...]},...]}).
Each piece carries its \"domain\" in the input's (u, v) and a \"report\" with the largest
difference measured.

implicitize reads one planar {\"type\":\"bezier\",\"points\":[[x,y],...]} (optional
\"weights\") and prints {\"degree\": n, \"monomials\": [[i, j, c], ...], \"monomials_exact\":
[[i, j, \"p/q\"], ...], \"report\": {...}}: f(x, y) = sum c x^i y^j = det F (SPEC-convert
15.8, exact coefficients, c rounded once). A curve with base points (X, Y, W sharing a
factor) is refused unless --divide-base-points. --svg draws the curve over the sign of f and
its zero set. intersect reads two such files and prints {\"intersections\": [{\"s\", \"t\",
\"point\", \"tangential\"}, ...], \"report\": {...}} (s on A, t on B, sorted by s); curves
overlapping along an arc give \"coincident\": true in the report.

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
    /// `--containment-degree N` of an interval-triangle reduction.
    pub(crate) containment_degree: Option<usize>,
    /// `--polynomial`: rational to polynomial within `--tol`; `to == (0, None)` when `--to`
    /// is not given (the input's degree).
    pub(crate) polynomial: bool,
    /// `--threads N`: the input objects are reduced on `N` threads (0 or 1: one; at most
    /// [`MAX_THREADS`]). The output does not depend on it.
    pub(crate) threads: usize,
}

/// The largest `--threads` accepted.
pub(crate) const MAX_THREADS: usize = 256;

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

/// Options of `cagd convert`: `to`, `standard_form` and `tol` for NURBS ↔ Bézier
/// (SPEC-convert §15.1–15.3); `to`, `inner`, `edges`, `split_line`, `split_curve`, `trim`
/// and `tol` for the patch conversions (§15.4–15.7).
#[derive(Debug, Clone, PartialEq, Default)]
pub(crate) struct ConvertArgs {
    pub(crate) to: Option<String>,
    pub(crate) inner: Option<(f64, f64)>,
    pub(crate) edges: Option<Vec<f64>>,
    pub(crate) split_line: Option<(f64, f64)>,
    pub(crate) split_curve: Option<Vec<f64>>,
    pub(crate) trim: Option<PathBuf>,
    pub(crate) standard_form: bool,
    pub(crate) tol: Option<f64>,
    pub(crate) input: Option<PathBuf>,
    pub(crate) output: Option<PathBuf>,
    pub(crate) svg: Option<PathBuf>,
}

/// A comma-separated list of finite numbers.
fn parse_list(s: &str, flag: &str) -> Result<Vec<f64>, String> {
    s.split(',')
        .map(|x| {
            let v: f64 = parse_num(x.trim(), flag)?;
            if v.is_finite() {
                Ok(v)
            } else {
                Err(format!("{flag}: {v} is not finite"))
            }
        })
        .collect()
}

/// A pair `A,B`.
fn parse_pair(s: &str, flag: &str) -> Result<(f64, f64), String> {
    match parse_list(s, flag)?[..] {
        [a, b] => Ok((a, b)),
        _ => Err(format!("{flag}: expected two numbers A,B, got {s:?}")),
    }
}

/// The options of `cagd convert` (the arguments after `convert`).
fn parse_convert<'a>(mut it: impl Iterator<Item = &'a String>) -> Result<ConvertArgs, String> {
    let mut c = ConvertArgs::default();
    while let Some(a) = it.next() {
        match a.as_str() {
            "--to" => c.to = Some(value(&mut it, a)?.to_string()),
            "--inner" => c.inner = Some(parse_pair(value(&mut it, a)?, a)?),
            "--edges" => c.edges = Some(parse_list(value(&mut it, a)?, a)?),
            "--split-line" => c.split_line = Some(parse_pair(value(&mut it, a)?, a)?),
            "--split-curve" => c.split_curve = Some(parse_list(value(&mut it, a)?, a)?),
            "--trim" => c.trim = Some(PathBuf::from(value(&mut it, a)?)),
            "--standard-form" => c.standard_form = true,
            "--tol" => c.tol = Some(parse_tol(value(&mut it, a)?)?),
            "-i" | "--input" => c.input = Some(PathBuf::from(value(&mut it, a)?)),
            "-o" | "--output" => c.output = Some(PathBuf::from(value(&mut it, a)?)),
            "--svg" => c.svg = Some(PathBuf::from(value(&mut it, a)?)),
            other => return Err(format!("convert: unknown argument {other:?}")),
        }
    }
    Ok(c)
}

/// A parsed command line.
#[derive(Debug, Clone, PartialEq)]
pub(crate) enum Command {
    Reduce(ReduceArgs),
    Merge(MergeArgs),
    Convert(ConvertArgs),
    Implicitize(ImplicitizeArgs),
    Intersect(IntersectArgs),
    Demo { out: PathBuf },
    Check { files: Vec<PathBuf> },
    Help,
}

fn value<'a>(it: &mut impl Iterator<Item = &'a String>, flag: &str) -> Result<&'a str, String> {
    it.next()
        .map(String::as_str)
        .ok_or_else(|| format!("{flag}: needs a value"))
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

/// The options of `cagd implicitize`.
fn parse_implicitize<'a>(
    mut it: impl Iterator<Item = &'a String>,
) -> Result<ImplicitizeArgs, String> {
    let mut a = ImplicitizeArgs {
        input: None,
        output: None,
        svg: None,
        divide_base_points: false,
    };
    while let Some(arg) = it.next() {
        match arg.as_str() {
            "-i" | "--input" => a.input = Some(PathBuf::from(value(&mut it, arg)?)),
            "-o" | "--output" => a.output = Some(PathBuf::from(value(&mut it, arg)?)),
            "--svg" => a.svg = Some(PathBuf::from(value(&mut it, arg)?)),
            "--divide-base-points" => a.divide_base_points = true,
            other => return Err(format!("implicitize: unknown argument {other:?}")),
        }
    }
    Ok(a)
}

/// The options of `cagd intersect` (two files, then options).
fn parse_intersect<'a>(mut it: impl Iterator<Item = &'a String>) -> Result<IntersectArgs, String> {
    let mut files = Vec::new();
    let (mut output, mut svg) = (None, None);
    while let Some(arg) = it.next() {
        match arg.as_str() {
            "-o" | "--output" => output = Some(PathBuf::from(value(&mut it, arg)?)),
            "--svg" => svg = Some(PathBuf::from(value(&mut it, arg)?)),
            other if other.starts_with('-') => {
                return Err(format!("intersect: unknown argument {other:?}"));
            }
            file => files.push(PathBuf::from(file)),
        }
    }
    match <[PathBuf; 2]>::try_from(files) {
        Ok([a, b]) => Ok(IntersectArgs { a, b, output, svg }),
        Err(f) => Err(format!(
            "intersect: name exactly two curve files, got {}",
            f.len()
        )),
    }
}

/// Parses the arguments after the program name.
pub(crate) fn parse(args: &[String]) -> Result<Command, String> {
    let mut it = args.iter();
    let Some(cmd) = it.next() else {
        return Ok(Command::Help);
    };
    // `--help` / `-h` anywhere after a subcommand (`cagd reduce --help`) is a help request.
    if it.clone().any(|a| a == "--help" || a == "-h") {
        return Ok(Command::Help);
    }
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
        "convert" => parse_convert(it).map(Command::Convert),
        "implicitize" => parse_implicitize(it).map(Command::Implicitize),
        "intersect" => parse_intersect(it).map(Command::Intersect),
        "check" => {
            let mut files = Vec::new();
            for a in it {
                if a.starts_with('-') {
                    return Err(format!("check: unknown argument {a:?}"));
                }
                files.push(PathBuf::from(a));
            }
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
                containment_degree: None,
                polynomial: false,
                threads: 0,
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
                    "--containment-degree" => {
                        r.containment_degree = Some(parse_num(value(&mut it, a)?, a)?);
                    }
                    "--merge" => {
                        r.lossy_merge = match value(&mut it, a)? {
                            "exact" => false,
                            "lossy" => true,
                            other => {
                                return Err(format!("--merge: {other:?} is not exact or lossy"));
                            }
                        }
                    }
                    "--polynomial" => r.polynomial = true,
                    "--threads" => {
                        r.threads = parse_num(value(&mut it, a)?, a)?;
                        if r.threads > MAX_THREADS {
                            return Err(format!(
                                "--threads: {} is above the maximum {MAX_THREADS}",
                                r.threads
                            ));
                        }
                    }
                    other => return Err(format!("reduce: unknown argument {other:?}")),
                }
            }
            if r.polynomial {
                return check_polynomial(r, have_to).map(Command::Reduce);
            }
            if !have_to {
                return Err("reduce: --to M is required".to_string());
            }
            Ok(Command::Reduce(r))
        }
        other => Err(format!("{other:?}: unknown command")),
    }
}

/// The arguments of `reduce --polynomial`: `--tol` required, `--to` optional (not 0), no
/// method, strategy, continuity or merge options.
fn check_polynomial(r: ReduceArgs, have_to: bool) -> Result<ReduceArgs, String> {
    if r.tol.is_none() {
        return Err("reduce --polynomial: --tol T is required".to_string());
    }
    if have_to && (r.to.0 == 0 || r.to.1 == Some(0)) {
        return Err("reduce --polynomial: --to degrees must be at least 1".to_string());
    }
    let extra = [
        (r.method.is_some(), "--method"),
        (r.strategy.is_some(), "--strategy"),
        (r.r.is_some() || r.p.is_some(), "--r/--p"),
        (r.continuity.is_some(), "--continuity"),
        (r.lossy_merge, "--merge"),
    ];
    if let Some((_, name)) = extra.iter().find(|(given, _)| *given) {
        return Err(format!(
            "reduce --polynomial: {name} does not apply (the continuity kept is the input's)"
        ));
    }
    Ok(r)
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
    fn polynomial_arguments() {
        let Command::Reduce(r) = parse(&args("reduce --polynomial --tol 1e-3")).unwrap() else {
            panic!("not reduce");
        };
        assert!(r.polynomial && r.to == (0, None) && r.tol == Some(1e-3));
        let Command::Reduce(r) = parse(&args("reduce --polynomial --to 3 --tol 1e-3")).unwrap()
        else {
            panic!("not reduce");
        };
        assert_eq!(r.to, (3, None));
        for bad in [
            "reduce --polynomial",
            "reduce --polynomial --tol 1e-3 --to 0",
            "reduce --polynomial --tol 1e-3 --strategy fit",
        ] {
            assert!(parse(&args(bad)).is_err(), "{bad}");
        }
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
    fn convert_arguments() {
        let Command::Convert(c) = parse(&args(
            "convert --to nurbs --inner 0.25,0.5 --edges 1,2,3 --split-line 0.5,-1 \
             --split-curve 0,1,2 --trim t.json --standard-form --tol 1e-9 -i a -o b --svg c",
        ))
        .unwrap() else {
            panic!("not convert");
        };
        assert_eq!(c.to.as_deref(), Some("nurbs"));
        assert_eq!(c.inner, Some((0.25, 0.5)));
        assert_eq!(c.edges, Some(vec![1.0, 2.0, 3.0]));
        assert_eq!(c.split_line, Some((0.5, -1.0)));
        assert_eq!(c.split_curve, Some(vec![0.0, 1.0, 2.0]));
        assert_eq!(c.trim, Some(PathBuf::from("t.json")));
        assert!(c.standard_form);
        assert_eq!(c.tol, Some(1e-9));
        assert_eq!(c.input, Some(PathBuf::from("a")));
        assert_eq!(c.output, Some(PathBuf::from("b")));
        assert_eq!(c.svg, Some(PathBuf::from("c")));
        assert_eq!(
            parse(&args("convert --inner 1")).unwrap_err(),
            "--inner: expected two numbers A,B, got \"1\""
        );
        assert_eq!(
            parse(&args("convert --edges 1,x")).unwrap_err(),
            "--edges: cannot read \"x\" as a number"
        );
        assert_eq!(
            parse(&args("convert --frob")).unwrap_err(),
            "convert: unknown argument \"--frob\""
        );
    }

    #[test]
    fn implicit_arguments() {
        let Command::Implicitize(a) = parse(&args(
            "implicitize --divide-base-points -i c.json --svg c.svg",
        ))
        .unwrap() else {
            panic!("not implicitize");
        };
        assert!(a.divide_base_points);
        assert_eq!(a.input, Some(PathBuf::from("c.json")));
        assert_eq!(a.svg, Some(PathBuf::from("c.svg")));
        let Command::Intersect(i) = parse(&args("intersect a.json b.json -o out.json")).unwrap()
        else {
            panic!("not intersect");
        };
        assert_eq!(
            (i.a, i.b),
            (PathBuf::from("a.json"), PathBuf::from("b.json"))
        );
        assert_eq!(i.output, Some(PathBuf::from("out.json")));
        assert_eq!(
            parse(&args("intersect a.json")).unwrap_err(),
            "intersect: name exactly two curve files, got 1"
        );
        assert_eq!(
            parse(&args("implicitize --to 3")).unwrap_err(),
            "implicitize: unknown argument \"--to\""
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
            "\"frobnicate\": unknown command"
        );
        assert_eq!(
            parse(&args("reduce --to")).unwrap_err(),
            "--to: needs a value"
        );
        assert_eq!(parse(&[]).unwrap(), Command::Help);
        // Found by the fuzzer: `check` took options for files, ran the vectors of the files
        // before them and then failed (exit 2 after output on stdout).
        assert_eq!(
            parse(&args("check a.json --tol")).unwrap_err(),
            "check: unknown argument \"--tol\""
        );
    }

    #[test]
    fn help_after_any_subcommand() {
        for line in [
            "--help",
            "-h",
            "help",
            "reduce --help",
            "reduce -h",
            "reduce --to 3 --frob --help",
            "merge --help",
            "convert -h",
            "implicitize --help",
            "intersect --help",
            "check --help",
            "demo -h",
        ] {
            assert_eq!(parse(&args(line)).unwrap(), Command::Help, "{line}");
        }
    }
}
