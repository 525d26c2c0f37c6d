//! The helpers of the command's integration tests: run the binary, read its JSON.

use std::io::Write;
use std::process::{Command, Output, Stdio};

use cagd_testkit::serde_json::{self, Value};

/// Runs `cagd` with `args`, `stdin` written to its standard input.
pub(crate) fn cagd(args: &[&str], stdin: &str) -> Output {
    let mut child = Command::new(env!("CARGO_BIN_EXE_cagd"))
        .args(args)
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("cagd runs");
    // A usage error ends the command before it reads its input: a closed pipe is fine.
    let written = child
        .stdin
        .take()
        .expect("stdin")
        .write_all(stdin.as_bytes());
    if let Err(e) = written {
        assert_eq!(e.kind(), std::io::ErrorKind::BrokenPipe, "write stdin: {e}");
    }
    child.wait_with_output().expect("cagd finishes")
}

/// The JSON on stdout of a successful run (fails the test otherwise).
pub(crate) fn json_out(o: &Output) -> Value {
    assert!(
        o.status.success(),
        "cagd failed: {}",
        String::from_utf8_lossy(&o.stderr)
    );
    serde_json::from_slice(&o.stdout).expect("stdout is JSON")
}
