//! Reading the command's input text from a file or stdin, within
//! [`crate::limits::MAX_INPUT_BYTES`].

use std::io::Read;
use std::path::Path;

use crate::limits::{MAX_INPUT_BYTES, check_input_size};

/// The whole text of `path`, or of stdin when `None`; the error names the file (or says the
/// input is above the size limit, or not UTF-8).
pub(crate) fn read_input(path: Option<&Path>) -> Result<String, String> {
    match path {
        Some(p) => read_file(p),
        None => crate::console::read_stdin(MAX_INPUT_BYTES),
    }
}

/// The whole text of the file `p`, refused above the size limit; errors name the file.
pub(crate) fn read_file(p: &Path) -> Result<String, String> {
    if p.as_os_str().is_empty() {
        // An empty argument would give the message an empty field name (`cagd: : ...`).
        return Err("input file: the path is empty".to_string());
    }
    let name = p.display();
    let file = std::fs::File::open(p).map_err(|e| format!("{name}: {e}"))?;
    let mut bytes = Vec::new();
    file.take(MAX_INPUT_BYTES.saturating_add(1))
        .read_to_end(&mut bytes)
        .map_err(|e| format!("{name}: {e}"))?;
    check_input_size(bytes.len() as u64, &name.to_string())?;
    String::from_utf8(bytes).map_err(|e| format!("{name}: not UTF-8 text ({e})"))
}
