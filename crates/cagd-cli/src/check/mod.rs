//! `cagd check FILE…`: the conformance runner over spec-vector files
//! (`../shared/spec/vectors-*.json`, format of SPEC-convert §0 / SPEC-reduce §0).
//!
//! Every vector `{id, algorithm, params, input, expected, tol, exact?, note?}` is run through
//! the library by its `algorithm` field (one dispatch table per spec family, [`lookup`]) and
//! compared with `expected` by the rule of the spec the algorithm belongs to ([`Rule`]:
//! SPEC-convert §0 per number, SPEC-reduce §0 per array); every key of `expected` must be
//! produced;
//! a vector whose `expected` has `error` passes only when the library refuses the input.
//! An algorithm no table knows is a failure, never a skip.

mod compare;
mod fields;
mod implicit;
mod interval;
mod nurbs;
mod patch;
mod reduce;
mod wsgb;

use std::path::Path;

use serde_json::Value;

pub(crate) use compare::{Rule, compare};
pub(crate) use fields::Vector;

/// What a runner says about one vector.
#[derive(Debug)]
pub(crate) enum Outcome {
    /// The library's answer: a JSON object holding (at least) every key of `expected`,
    /// compared by the spec's tolerance rule.
    Values(Value),
    /// The runner compared the answer itself (an optimum that is not unique, a polynomial
    /// up to its scale): the largest relative difference found and whether it passes.
    Compared {
        /// The largest difference, relative as the runner's rule says.
        max_diff: f64,
        /// Whether the vector passes.
        pass: bool,
        /// What was compared, printed with a failure.
        detail: String,
    },
    /// The library refused the input with this message.
    Refused(String),
}

/// A runner: reads the vector's `params` / `input`, calls the library, returns its answer.
/// `Err` is a malformed vector (a missing or ill-typed field), reported as a failure.
pub(crate) type Runner = fn(&Vector<'_>) -> Result<Outcome, String>;

/// The dispatch tables, one per family of algorithms, with the tolerance rule of the spec
/// file the family's vectors belong to.
const TABLES: &[(&[(&str, Runner)], Rule)] = &[
    (reduce::TABLE, Rule::PerArray),
    (nurbs::TABLE, Rule::Elementwise),
    (patch::TABLE, Rule::Elementwise),
    (implicit::TABLE, Rule::Elementwise),
    (interval::TABLE, Rule::Elementwise),
    (wsgb::TABLE, Rule::PerArray),
];

/// The runner of `algorithm` and its comparison rule, if any table knows it.
pub(crate) fn lookup(algorithm: &str) -> Option<(Runner, Rule)> {
    TABLES.iter().find_map(|(table, rule)| {
        table
            .iter()
            .find(|(name, _)| *name == algorithm)
            .map(|(_, run)| (*run, *rule))
    })
}

/// The verdict on one vector.
#[derive(Debug)]
pub(crate) struct Verdict {
    /// The vector's id (or its index when it has none).
    pub(crate) id: String,
    /// Its algorithm.
    pub(crate) algorithm: String,
    /// Whether it passed.
    pub(crate) pass: bool,
    /// The largest difference measured (`NaN` when nothing was compared).
    pub(crate) max_diff: f64,
    /// Why it failed, or what the pass rests on (e.g. "refused as expected").
    pub(crate) detail: String,
}

/// Runs one vector (never panics: a panic in the library is caught and reported as a
/// failure of that vector).
pub(crate) fn run_vector(raw: &Value, index: usize) -> Verdict {
    let id = raw
        .get("id")
        .and_then(Value::as_str)
        .map_or_else(|| format!("#{index}"), str::to_string);
    let algorithm = raw
        .get("algorithm")
        .and_then(Value::as_str)
        .unwrap_or("")
        .to_string();
    let fail = |detail: String| Verdict {
        id: id.clone(),
        algorithm: algorithm.clone(),
        pass: false,
        max_diff: f64::NAN,
        detail,
    };
    let vector = match Vector::read(raw) {
        Ok(v) => v,
        Err(e) => return fail(format!("malformed vector: {e}")),
    };
    let Some((runner, rule)) = lookup(&algorithm) else {
        return fail(format!("unknown algorithm {algorithm:?}"));
    };
    let outcome = match std::panic::catch_unwind(|| runner(&vector)) {
        Ok(Ok(o)) => o,
        Ok(Err(e)) => return fail(format!("malformed vector: {e}")),
        Err(_) => return fail("the library panicked".to_string()),
    };
    let wants_error = vector.expected.get("error").is_some();
    let (pass, max_diff, detail) = match (wants_error, outcome) {
        (true, Outcome::Refused(msg)) => (true, f64::NAN, format!("refused as expected: {msg}")),
        (true, _) => (
            false,
            f64::NAN,
            "expected an error, got a result".to_string(),
        ),
        (false, Outcome::Refused(msg)) => (false, f64::NAN, format!("refused: {msg}")),
        (false, Outcome::Values(got)) => match compare(&got, vector.expected, vector.tol, rule) {
            Ok(d) => (true, d, String::new()),
            Err((d, why)) => (false, d, why),
        },
        (
            false,
            Outcome::Compared {
                max_diff,
                pass,
                detail,
            },
        ) => (pass, max_diff, detail),
    };
    Verdict {
        id,
        algorithm,
        pass,
        max_diff,
        detail,
    }
}

/// Runs every vector of every file; prints one line per vector and a closing count line
/// `N passed, N failed`. Returns whether all passed, or `Err` when a file cannot be read as
/// a list of vectors.
pub(crate) fn run_files(files: &[std::path::PathBuf]) -> Result<bool, String> {
    let mut passed = 0usize;
    let mut failed = 0usize;
    for file in files {
        for v in read_file(file)? {
            if v.pass {
                passed += 1;
            } else {
                failed += 1;
            }
            let status = if v.pass { "pass" } else { "FAIL" };
            let diff = if v.max_diff.is_nan() {
                "-".to_string()
            } else {
                format!("{:.2e}", v.max_diff)
            };
            let mut line = format!("{status} {} [{}] max diff {diff}", v.id, v.algorithm);
            if !v.detail.is_empty() && !v.pass {
                line.push_str(": ");
                line.push_str(&v.detail);
            }
            println!("{line}");
        }
    }
    println!("{passed} passed, {failed} failed");
    Ok(failed == 0)
}

/// Reads one file and runs its vectors.
fn read_file(file: &Path) -> Result<Vec<Verdict>, String> {
    let text = crate::input::read_file(file)?;
    let value: Value =
        serde_json::from_str(&text).map_err(|e| format!("{}: {e}", file.display()))?;
    let list = match &value {
        Value::Array(a) => a,
        _ => return Err(format!("{}: not a JSON array of vectors", file.display())),
    };
    Ok(list
        .iter()
        .enumerate()
        .map(|(i, raw)| run_vector(raw, i))
        .collect())
}
