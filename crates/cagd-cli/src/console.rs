//! The command's standard streams, redirectable per thread so that the whole command can
//! run in-process (the fuzzer in `crate::fuzz` calls [`crate::run`] with stdin / stdout /
//! stderr buffers; it goes beyond the seeds).
//!
//! `main.rs` declares this module first with `#[macro_use]`, so the macros below shadow the
//! standard `print!`, `println!` and `eprintln!` in every later module (textual
//! macro scope comes before the prelude) and every module writes through [`out`] / [`err`]: to the process's
//! streams normally, to the thread's [`Captured`] buffers while [`capture`] runs. Reading
//! stdin goes through [`read_stdin`].

use std::cell::RefCell;
use std::fmt;
use std::io::{Read, Write};

/// The streams of one in-process run: stdin given, stdout and stderr collected.
#[derive(Debug, Default, Clone, PartialEq)]
pub(crate) struct Captured {
    /// What the command reads as stdin.
    pub(crate) stdin: Vec<u8>,
    /// What it wrote to stdout.
    pub(crate) stdout: Vec<u8>,
    /// What it wrote to stderr.
    pub(crate) stderr: Vec<u8>,
}

thread_local! {
    static CAPTURE: RefCell<Option<Captured>> = const { RefCell::new(None) };
}

/// Runs `f` with this thread's streams redirected to buffers (`stdin` as input); returns its
/// result and the buffers. Not re-entrant (an inner capture replaces the outer one's
/// buffers until it ends).
#[cfg(test)]
pub(crate) fn capture<T>(stdin: &[u8], f: impl FnOnce() -> T) -> (T, Captured) {
    let saved = CAPTURE.with(|c| {
        c.replace(Some(Captured {
            stdin: stdin.to_vec(),
            ..Captured::default()
        }))
    });
    // A panic inside `f` must not leave the thread redirected.
    struct Restore(Option<Option<Captured>>);
    impl Drop for Restore {
        fn drop(&mut self) {
            let saved = self.0.take().unwrap_or(None);
            CAPTURE.with(|c| c.replace(saved));
        }
    }
    let mut restore = Restore(Some(saved));
    let result = f();
    let got = CAPTURE.with(|c| c.replace(restore.0.take().unwrap_or(None)));
    (result, got.unwrap_or_default())
}

/// Writes to stdout (or the captured buffer).
pub(crate) fn out(args: fmt::Arguments<'_>) -> std::io::Result<()> {
    let captured = CAPTURE.with(|c| match c.borrow_mut().as_mut() {
        Some(cap) => {
            cap.stdout.extend_from_slice(args.to_string().as_bytes());
            true
        }
        None => false,
    });
    if captured {
        return Ok(());
    }
    let mut o = std::io::stdout().lock();
    o.write_fmt(args).and_then(|()| o.flush())
}

/// Writes to stderr (or the captured buffer); a failing stderr is ignored, as by
/// `eprintln!`'s callers there is nowhere left to report it.
pub(crate) fn err(args: fmt::Arguments<'_>) {
    let captured = CAPTURE.with(|c| match c.borrow_mut().as_mut() {
        Some(cap) => {
            cap.stderr.extend_from_slice(args.to_string().as_bytes());
            true
        }
        None => false,
    });
    if !captured {
        let _ignored = std::io::stderr().lock().write_fmt(args);
    }
}

/// The whole of stdin (or the captured input) as text.
pub(crate) fn read_stdin(limit: u64) -> Result<String, String> {
    let given = CAPTURE.with(|c| c.borrow().as_ref().map(|cap| cap.stdin.clone()));
    let bytes = match given {
        Some(b) => b,
        None => {
            let mut b = Vec::new();
            std::io::stdin()
                .lock()
                .take(limit.saturating_add(1))
                .read_to_end(&mut b)
                .map_err(|e| format!("stdin: {e}"))?;
            b
        }
    };
    crate::limits::check_input_size(bytes.len() as u64, "stdin")?;
    String::from_utf8(bytes).map_err(|e| format!("stdin: not UTF-8 text ({e})"))
}

/// `print!` through [`out`] (a failing stdout is ignored, as a `print!` that did not panic).
macro_rules! print {
    ($($t:tt)*) => {{
        let _ignored = $crate::console::out(format_args!($($t)*));
    }};
}

/// `println!` through [`out`].
macro_rules! println {
    () => { print!("\n") };
    ($($t:tt)*) => {{
        let _ignored = $crate::console::out(format_args!("{}\n", format_args!($($t)*)));
    }};
}

/// `eprintln!` through [`err`].
macro_rules! eprintln {
    () => { $crate::console::err(format_args!("\n")) };
    ($($t:tt)*) => { $crate::console::err(format_args!("{}\n", format_args!($($t)*))) };
}
