//! Writing the command's output: text to a file or stdout, JSON pretty-printed.

use std::path::Path;
use std::process::ExitCode;

use serde_json::Value;

/// Writes `text` to `path` or stdout; the error names the file.
pub(crate) fn write_output(path: Option<&Path>, text: &str) -> Result<(), String> {
    match path {
        Some(p) if p.as_os_str().is_empty() => Err("output file: the path is empty".to_string()),
        Some(p) => std::fs::write(p, text).map_err(|e| format!("{}: {e}", p.display())),
        None => crate::console::out(format_args!("{text}")).map_err(|e| format!("stdout: {e}")),
    }
}

/// Writes `json` (pretty, one trailing newline) to `path` or stdout; exit code 1 on an I/O
/// failure.
pub(crate) fn write_json(path: Option<&Path>, json: &Value) -> ExitCode {
    let mut text = serde_json::to_string_pretty(json).unwrap_or_default();
    text.push('\n');
    match write_output(path, &text) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("cagd: {e}");
            ExitCode::from(1)
        }
    }
}
