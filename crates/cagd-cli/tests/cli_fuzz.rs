//! The subprocess fuzz pass: the cases of the in-process fuzzer (`src/fuzz/`, included here
//! by path) run against the built `cagd` binary, each with a timeout, so that a signal, an
//! abort or a hang of the real process is seen too. `CAGD_FUZZ_CASES=N` (default 100) and
//! `CAGD_FUZZ_SEED=S` as for the in-process driver.

#[allow(
    dead_code,
    reason = "the in-process driver uses the rest of the fuzz module"
)]
#[path = "../src/fuzz/mod.rs"]
mod fuzz;
#[path = "../src/method_names.rs"]
mod method_names;

use std::io::Write;
use std::process::{Command, Stdio};
use std::time::Instant;

use fuzz::cases::Case;
use fuzz::oracle::Ran;
use fuzz::{CASE_TIMEOUT, campaign, case_count, materialize, out_file, scratch, seed};

/// Runs one case as a child process, killed after [`CASE_TIMEOUT`].
fn run_child(case: &Case, dir: &std::path::Path) -> Ran {
    let args = materialize(case, dir).unwrap_or_else(|e| panic!("scratch: {e}"));
    let stdin_file = dir.join("stdin");
    std::fs::write(&stdin_file, &case.stdin).unwrap_or_else(|e| panic!("scratch: {e}"));
    let mut child = Command::new(env!("CARGO_BIN_EXE_cagd"))
        .args(&args)
        .stdin(std::fs::File::open(&stdin_file).unwrap_or_else(|e| panic!("scratch: {e}")))
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap_or_else(|e| panic!("spawn cagd: {e}"));
    // Read the pipes on threads so that a large output cannot block the child.
    let mut out = child.stdout.take().map(|mut o| {
        std::thread::spawn(move || {
            let mut b = Vec::new();
            let _ = std::io::Read::read_to_end(&mut o, &mut b);
            b
        })
    });
    let mut err = child.stderr.take().map(|mut o| {
        std::thread::spawn(move || {
            let mut b = Vec::new();
            let _ = std::io::Read::read_to_end(&mut o, &mut b);
            b
        })
    });
    let start = Instant::now();
    let status = loop {
        match child.try_wait() {
            Ok(Some(s)) => break Some(s),
            Ok(None) if start.elapsed() > CASE_TIMEOUT => {
                let _ = child.kill();
                let _ = child.wait();
                break None;
            }
            Ok(None) => std::thread::sleep(std::time::Duration::from_millis(2)),
            Err(e) => panic!("wait: {e}"),
        }
    };
    let join = |h: Option<std::thread::JoinHandle<Vec<u8>>>| {
        h.and_then(|h| h.join().ok()).unwrap_or_default()
    };
    let (stdout, stderr) = (join(out.take()), join(err.take()));
    let abort = match &status {
        None => Some(format!("killed after {CASE_TIMEOUT:?} (a hang)")),
        Some(s) if s.code().is_none() => Some(format!("ended by a signal: {s}")),
        Some(_) => None,
    };
    let _ = std::io::stderr().flush();
    Ran {
        code: status.and_then(|s| s.code()),
        stdout,
        stderr,
        out_file: out_file(case, dir),
        abort,
    }
}

#[test]
fn fuzz_the_binary() {
    let (count, seed) = (case_count(100), seed());
    // Another seed than the in-process run: more ground covered by the two together.
    let seed = seed ^ 0x5eed;
    let dir = scratch("subprocess");
    let summary = campaign(
        seed,
        count,
        &mut |case| run_child(case, &dir),
        &mut |_, _| {},
    );
    let _gone = std::fs::remove_dir_all(&dir);
    println!("seed {seed}: {}", summary.report());
    assert!(summary.failures.is_empty(), "{}", summary.report());
    assert_eq!(summary.runs, count.saturating_sub(fuzz::first_case()));
}
