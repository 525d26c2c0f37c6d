//! Reading the command's input text from a file or stdin.

use std::io::Read;
use std::path::Path;

/// The whole text of `path`, or of stdin when `None`; the error names the file.
pub(crate) fn read_input(path: Option<&Path>) -> Result<String, String> {
    let mut text = String::new();
    match path {
        Some(p) => {
            text = std::fs::read_to_string(p).map_err(|e| format!("{}: {e}", p.display()))?;
        }
        None => {
            std::io::stdin()
                .read_to_string(&mut text)
                .map_err(|e| format!("stdin: {e}"))?;
        }
    }
    Ok(text)
}
