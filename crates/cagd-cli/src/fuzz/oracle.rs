//! The fuzz oracle: what a run of the command may do.
//!
//! Exit 0 with valid JSON whose numbers are all finite (a `null` only where the format has
//! one: `weights` of a polynomial piece, a bound that is not computed) and whose every
//! reported `error_bound` is `>=` its `max_error`; or exit 2 with exactly one line on
//! stderr, `cagd: FIELD: message`, naming the field, option or file, and nothing on stdout;
//! `cagd check` may also exit 1 (a vector failed). Never a panic, a signal, another code or
//! a hang (the drivers time each run).

use serde_json::Value;

use super::cases::Case;

/// What one run did.
#[derive(Debug, Clone)]
pub(crate) struct Ran {
    /// The exit code; `None` for a panic caught in-process or a signal.
    pub(crate) code: Option<i32>,
    /// What it wrote to stdout.
    pub(crate) stdout: Vec<u8>,
    /// What it wrote to stderr.
    pub(crate) stderr: Vec<u8>,
    /// The contents of `{OUT}` after the run, when the case names it.
    pub(crate) out_file: Option<Vec<u8>>,
    /// Why the run did not finish (a panic message, a signal, a timeout).
    pub(crate) abort: Option<String>,
}

/// Keys whose value may be `null` in the output.
const NULL_OK: &[&str] = &[
    "weights",
    "error_bound",
    "max_error",
    "bound",
    "svg",
    "method_params",
];

/// Checks the numbers, `null`s and bounds of an output value; `at` is its JSON path.
fn check_value(v: &Value, at: &str, key: &str) -> Result<(), String> {
    match v {
        Value::Null if !NULL_OK.contains(&key) => Err(format!("null at {at} (NaN written?)")),
        Value::Number(n) if !n.as_f64().is_some_and(f64::is_finite) => {
            Err(format!("non-finite number at {at}"))
        }
        Value::Array(a) => a
            .iter()
            .enumerate()
            .try_for_each(|(i, x)| check_value(x, &format!("{at}[{i}]"), key)),
        Value::Object(o) => {
            if let (Some(b), Some(e)) = (
                o.get("error_bound").and_then(Value::as_f64),
                o.get("max_error").and_then(Value::as_f64),
            ) {
                // The bound must hold; a relative 1e-9 covers the rounding of the
                // measurement itself.
                if e > b * (1.0 + 1e-9) + f64::MIN_POSITIVE {
                    return Err(format!(
                        "{at}: error_bound {b:e} is below the measured max_error {e:e}"
                    ));
                }
            }
            o.iter()
                .try_for_each(|(k, x)| check_value(x, &format!("{at}.{k}"), k))
        }
        _ => Ok(()),
    }
}

/// Judges one run of `case`: `Err` says what is wrong.
pub(crate) fn judge(case: &Case, ran: &Ran) -> Result<(), String> {
    if let Some(why) = &ran.abort {
        return Err(format!("aborted: {why}"));
    }
    let err = String::from_utf8_lossy(&ran.stderr);
    let out = String::from_utf8_lossy(&ran.stdout);
    if err.contains("panicked") || out.contains("panicked") {
        return Err(format!("a panic was reported: {err}{out}"));
    }
    let help = case.args.iter().any(|a| a == "--help" || a == "-h");
    match ran.code {
        Some(0) if help => {
            if out.starts_with("usage:") {
                Ok(())
            } else {
                Err("--help did not print the usage".into())
            }
        }
        Some(0 | 1) if case.command() == "check" => {
            if out.contains("the library panicked") {
                return Err(format!("check caught a library panic: {out}"));
            }
            if out.lines().last().is_some_and(|l| l.ends_with(" failed")) {
                Ok(())
            } else {
                Err(format!("check printed no summary line: {out}"))
            }
        }
        Some(0) => {
            let text = match &ran.out_file {
                Some(f) => String::from_utf8_lossy(f).into_owned(),
                None => out.into_owned(),
            };
            let v: Value = serde_json::from_str(&text)
                .map_err(|e| format!("exit 0 but the output is not JSON ({e}): {text:.300}"))?;
            check_value(&v, "output", "")
        }
        Some(2) => {
            if !ran.stdout.is_empty() {
                return Err(format!("exit 2 with output on stdout: {out:.300}"));
            }
            let lines: Vec<&str> = err.lines().collect();
            match lines[..] {
                [line] if err.ends_with('\n') => {
                    // `cagd: FIELD: message`: the field, option or file before the message.
                    let named = line
                        .strip_prefix("cagd: ")
                        .and_then(|rest| rest.split_once(": "))
                        .is_some_and(|(field, msg)| !field.trim().is_empty() && !msg.is_empty());
                    if named {
                        Ok(())
                    } else {
                        Err(format!("exit 2 but the line names no field: {line:?}"))
                    }
                }
                _ => Err(format!(
                    "exit 2 with {} lines on stderr: {err:?}",
                    lines.len()
                )),
            }
        }
        Some(c) => Err(format!("exit code {c}; stderr: {err:.300}")),
        None => Err("no exit code (signal)".into()),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use serde_json::json;

    fn case(args: &[&str]) -> Case {
        Case {
            shape: "bezier",
            args: args.iter().map(|s| (*s).to_string()).collect(),
            stdin: Vec::new(),
            files: Vec::new(),
        }
    }

    fn ran(code: i32, stdout: &str, stderr: &str) -> Ran {
        Ran {
            code: Some(code),
            stdout: stdout.into(),
            stderr: stderr.into(),
            out_file: None,
            abort: None,
        }
    }

    #[test]
    fn the_oracle_refuses_what_it_must() {
        let c = case(&["reduce", "--to", "2"]);
        let good = json!({"points": [[0.0]], "report": {"error_bound": 1.0, "max_error": 0.5}});
        assert!(judge(&c, &ran(0, &good.to_string(), "")).is_ok());
        let low = json!({"report": {"error_bound": 0.4, "max_error": 0.5}});
        assert!(judge(&c, &ran(0, &low.to_string(), "")).is_err());
        let nan = json!({"points": [[null]]});
        assert!(judge(&c, &ran(0, &nan.to_string(), "")).is_err());
        assert!(judge(&c, &ran(0, "{\"a\":", "")).is_err());
        assert!(judge(&c, &ran(2, "", "cagd: input.points[0]: bad\n")).is_ok());
        assert!(judge(&c, &ran(2, "", "cagd: bad\n")).is_err());
        assert!(judge(&c, &ran(2, "", "cagd: input: a\nusage\n")).is_err());
        assert!(judge(&c, &ran(2, "{}", "cagd: input: a\n")).is_err());
        assert!(judge(&c, &ran(101, "", "thread 'main' panicked at x")).is_err());
        assert!(judge(&c, &ran(1, "", "cagd: x: y\n")).is_err());
        let check = case(&["check", "f"]);
        assert!(judge(&check, &ran(1, "v1 FAIL\n0 passed, 1 failed\n", "")).is_ok());
        assert!(
            judge(
                &check,
                &ran(1, "v1 the library panicked\n0 passed, 1 failed\n", "")
            )
            .is_err()
        );
    }
}
