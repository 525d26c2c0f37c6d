//! The in-process fuzz driver: every case of [`crate::fuzz`] through [`crate::run`] with
//! buffers for stdin / stdout / stderr (panics caught), watched for hangs by a second
//! thread. `cargo test -p cagd-cli --bin cagd fuzz` runs the short campaign (fixed seed);
//! `CAGD_FUZZ_CASES=N` (and `CAGD_FUZZ_SEED=S`) a long one, best with `--release`.

use std::panic::{AssertUnwindSafe, catch_unwind};
use std::process::ExitCode;
use std::sync::mpsc;
use std::sync::{Arc, Mutex};
use std::time::Instant;

use crate::fuzz::oracle::Ran;
use crate::fuzz::{CASE_TIMEOUT, campaign, case_count, materialize, out_file, scratch, seed};

/// The exit code as a number (`ExitCode` has no accessor; it compares).
fn code_of(c: ExitCode) -> Option<i32> {
    (0..=255u8).find(|&n| ExitCode::from(n) == c).map(i32::from)
}

/// The short in-process campaign: no failure allowed.
#[test]
fn fuzz_in_process() {
    let (count, seed) = (case_count(400), seed());
    // The case being run and when it started, for the watchdog.
    let current: Arc<Mutex<(usize, Instant, String)>> =
        Arc::new(Mutex::new((0, Instant::now(), String::new())));
    let (done_tx, done_rx) = mpsc::channel();
    let watched = Arc::clone(&current);
    // The panics are expected (caught and reported as failures); keep the log short.
    let hook = std::panic::take_hook();
    std::panic::set_hook(Box::new(|_| {}));
    std::thread::spawn(move || {
        let dir = scratch("inproc");
        let mut run = |case: &crate::fuzz::cases::Case| {
            let args = materialize(case, &dir).unwrap_or_else(|e| panic!("scratch: {e}"));
            let (result, streams) = crate::console::capture(&case.stdin, || {
                catch_unwind(AssertUnwindSafe(|| crate::run(&args)))
            });
            let (code, abort) = match result {
                Ok(c) => (code_of(c), None),
                Err(p) => {
                    let msg = p
                        .downcast_ref::<String>()
                        .cloned()
                        .or_else(|| p.downcast_ref::<&str>().map(|s| (*s).to_string()))
                        .unwrap_or_default();
                    (None, Some(format!("panic: {msg}")))
                }
            };
            Ran {
                code,
                stdout: streams.stdout,
                stderr: streams.stderr,
                out_file: out_file(case, &dir),
                abort,
            }
        };
        let mut progress = |i: usize, case: &crate::fuzz::cases::Case| {
            if let Ok(mut c) = watched.lock() {
                *c = (i, Instant::now(), case.describe());
            }
        };
        let summary = campaign(seed, count, &mut run, &mut progress);
        let _gone = std::fs::remove_dir_all(&dir);
        let _ = done_tx.send(summary);
    });
    let outcome = loop {
        match done_rx.recv_timeout(std::time::Duration::from_millis(200)) {
            Ok(s) => break Ok(s),
            Err(mpsc::RecvTimeoutError::Timeout) => {
                let c = current.lock().map(|c| c.clone()).ok();
                if let Some((i, since, case)) = c.filter(|c| c.1.elapsed() > CASE_TIMEOUT) {
                    let _ = since;
                    break Err(format!(
                        "case {i} runs for more than {CASE_TIMEOUT:?} (a hang):\n{case}"
                    ));
                }
            }
            Err(mpsc::RecvTimeoutError::Disconnected) => {
                break Err("the fuzz thread died".to_string());
            }
        }
    };
    std::panic::set_hook(hook);
    let summary = outcome.unwrap_or_else(|e| panic!("{e}"));
    std::println!("seed {seed}: {}", summary.report());
    assert!(summary.failures.is_empty(), "{}", summary.report());
    assert_eq!(
        summary.runs,
        count.saturating_sub(crate::fuzz::first_case())
    );
}
