//! A structure-aware mutation fuzzer of the `cagd` command and its JSON readers (issue 18;
//! beyond the seeds): valid inputs of every shape ([`seeds`]) are mutated ([`mutate`]) and
//! run through every subcommand and its main options ([`cases`]); each run is judged by
//! [`oracle`]. Stable Rust, fixed seed, no dependency.
//!
//! Two drivers run the same cases: in-process (`crate::fuzz_in_process`, the command's
//! [`crate::run`] with buffers for its streams; fast) and as a subprocess of the built
//! binary (`tests/cli_fuzz.rs`, which includes this folder by path). Both read
//! `CAGD_FUZZ_CASES` (how many cases; short defaults for `cargo test`) and `CAGD_FUZZ_SEED`;
//! the README's Fuzzing section has the long runs.

pub(crate) mod cases;
pub(crate) mod mutate;
pub(crate) mod oracle;
pub(crate) mod rng;
pub(crate) mod seeds;

use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

use cases::{Case, next_case};
use oracle::{Ran, judge};
use rng::Rng;

/// The default seed (issue 18).
pub(crate) const DEFAULT_SEED: u64 = 0x0001_8c11_f022;

/// The longest a single run may take before it counts as a hang (debug builds included).
pub(crate) const CASE_TIMEOUT: Duration = Duration::from_secs(60);

/// `CAGD_FUZZ_CASES` or `default`.
pub(crate) fn case_count(default: usize) -> usize {
    std::env::var("CAGD_FUZZ_CASES")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(default)
}

/// `CAGD_FUZZ_SEED` or [`DEFAULT_SEED`].
pub(crate) fn seed() -> u64 {
    std::env::var("CAGD_FUZZ_SEED")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(DEFAULT_SEED)
}

/// The outcome of a campaign.
#[derive(Debug, Default)]
pub(crate) struct Summary {
    /// Cases run.
    pub(crate) runs: usize,
    /// Runs per exit code 0, 1, 2.
    pub(crate) exits: [usize; 3],
    /// Runs per subcommand.
    pub(crate) per_command: std::collections::BTreeMap<String, usize>,
    /// The failures: case number, reproducer, what the oracle said.
    pub(crate) failures: Vec<(usize, String, String)>,
    /// Cases not run because they hit a known, still open defect ([`pending`]).
    pub(crate) pending: usize,
    /// The slowest run.
    pub(crate) slowest: Duration,
    /// The slowest case.
    pub(crate) slowest_case: String,
    /// Total time.
    pub(crate) elapsed: Duration,
}

impl Summary {
    /// One paragraph for the test log.
    pub(crate) fn report(&self) -> String {
        let mut s = format!(
            "{} runs in {:.1} s (exit 0: {}, 1: {}, 2: {}; slowest {:.2} s; {} pending cases \
             skipped); per command: {:?}; {} failures",
            self.runs,
            self.elapsed.as_secs_f64(),
            self.exits[0],
            self.exits[1],
            self.exits[2],
            self.slowest.as_secs_f64(),
            self.pending,
            self.per_command,
            self.failures.len()
        );
        s.push_str(&format!("\nslowest: {:.300}", self.slowest_case));
        for (i, case, why) in self.failures.iter().take(20) {
            s.push_str(&format!("\n--- case {i}: {why}\n{case}"));
        }
        s
    }
}

/// The files of a case in `dir`, and `args` with the placeholders replaced.
pub(crate) fn materialize(case: &Case, dir: &Path) -> std::io::Result<Vec<String>> {
    for (i, f) in case.files.iter().enumerate() {
        std::fs::write(dir.join(format!("f{i}.json")), f)?;
    }
    let out = dir.join("out.json");
    let _absent = std::fs::remove_file(&out);
    let path = |name: &str| -> String { dir.join(name).to_string_lossy().into_owned() };
    Ok(case
        .args
        .iter()
        .map(|a| match a.as_str() {
            "{F0}" => path("f0.json"),
            "{F1}" => path("f1.json"),
            "{OUT}" => path("out.json"),
            "{SVG}" => path("out.svg"),
            _ => a.clone(),
        })
        .collect())
}

/// The `{OUT}` file after a run, when the case names it.
pub(crate) fn out_file(case: &Case, dir: &Path) -> Option<Vec<u8>> {
    case.args
        .iter()
        .any(|a| a == "{OUT}")
        .then(|| std::fs::read(dir.join("out.json")).unwrap_or_default())
}

/// A fresh scratch folder for one driver.
pub(crate) fn scratch(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("cagd-fuzz-{name}-{}", std::process::id()));
    let _fresh = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap_or_else(|e| panic!("{}: {e}", dir.display()));
    dir
}

/// A case that hits a known defect still open elsewhere, skipped unless
/// `CAGD_FUZZ_PENDING` is set: a patch or B-spline surface reduced to a tolerance has no
/// practical bound on its work yet (issue 18, "bounded work on every strategy", in
/// cagd-reduce). The fuzzer found small inputs that run for half a minute to many minutes
/// in a release build: a 4 x 5 NURBS surface with a weight of 1.8e19 (`--strategy
/// segments`, even at `--tol 1e3`), a bicubic 4 x 5 NURBS surface to degree (1, 1) within
/// 1e-4 (`--strategy fit`), a 3 x 4 NURBS surface with coordinates up to 2e6 made
/// polynomial within 0.5 (883 000 patches out), a bicubic tensor patch to (1, 1) within
/// 1e-2 by `pinv` (16 384 pieces, 35 s), a quadratic B-spline to degree 1 within 1e-13 by
/// `--strategy segments` (subdivision to depth 40). Their inputs are in `tests/data/fuzz/`.
/// Skipped: tolerances below 1 on tensor / triangle / B-spline surfaces, the `segments`
/// strategy below 1e-6 on any B-spline and on rational surfaces at all.
pub(crate) fn pending(case: &Case) -> bool {
    if std::env::var_os("CAGD_FUZZ_PENDING").is_some() || case.command() != "reduce" {
        return false;
    }
    let has = |a: &str| case.args.iter().any(|x| x == a);
    let tol = case
        .args
        .iter()
        .position(|x| x == "--tol")
        .and_then(|i| case.args.get(i + 1))
        .and_then(|t| t.parse::<f64>().ok());
    let patch = matches!(case.shape, "tensor" | "triangle" | "bspline-surface");
    let segments = has("segments") || (has("--method") && !has("fit"));
    let rational = case
        .files
        .iter()
        .chain([&case.stdin])
        .any(|f| String::from_utf8_lossy(f).contains("\"weights\""));
    let spline = matches!(case.shape, "bspline" | "nurbs" | "bspline-surface");
    tol.is_some_and(|t| {
        (patch && t < 1.0)
            || (spline && segments && t < 1e-6)
            || (case.shape == "bspline-surface" && segments && rational)
    })
}

/// Runs `count` cases from `seed` through `run`; `progress` is told each case before it
/// runs (for a watchdog).
pub(crate) fn campaign(
    seed: u64,
    count: usize,
    run: &mut dyn FnMut(&Case) -> Ran,
    progress: &mut dyn FnMut(usize, &Case),
) -> Summary {
    let mut rng = Rng::new(seed);
    let mut summary = Summary::default();
    let start = Instant::now();
    for i in 0..count {
        let case = next_case(&mut rng);
        if pending(&case) {
            summary.pending += 1;
            continue;
        }
        progress(i, &case);
        let t = Instant::now();
        let ran = run(&case);
        if t.elapsed() > summary.slowest {
            summary.slowest = t.elapsed();
            summary.slowest_case = case.describe();
        }
        summary.runs += 1;
        if let Some(c @ 0..=2) = ran.code {
            summary.exits[usize::try_from(c).unwrap_or(0)] += 1;
        }
        *summary
            .per_command
            .entry(case.command().to_string())
            .or_default() += 1;
        if let Err(why) = judge(&case, &ran) {
            summary.failures.push((i, case.describe(), why));
        }
    }
    summary.elapsed = start.elapsed();
    summary
}
