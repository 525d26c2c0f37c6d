//! The README's Rust example is the one the facade's crate docs compile as a doc test
//! (`src/lib.rs`): the same code block, character for character.

use std::path::Path;

/// The fenced ```` ```rust ```` blocks of `text`, without the fences.
fn rust_blocks(text: &str) -> Vec<String> {
    let mut blocks = Vec::new();
    let mut current: Option<Vec<&str>> = None;
    for line in text.lines() {
        match current.as_mut() {
            None if line.trim_end() == "```rust" => current = Some(Vec::new()),
            None => {}
            Some(lines) if line.trim_end() == "```" => {
                blocks.push(lines.join("\n"));
                current = None;
            }
            Some(lines) => lines.push(line),
        }
    }
    blocks
}

#[test]
fn readme_rust_example_is_the_doc_tested_one() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let readme = std::fs::read_to_string(root.join("README.md")).expect("README.md");
    let lib = std::fs::read_to_string(root.join("src/lib.rs")).expect("src/lib.rs");
    let docs: String = lib
        .lines()
        .filter_map(|l| l.strip_prefix("//!"))
        .map(|l| l.strip_prefix(' ').unwrap_or(l))
        .collect::<Vec<_>>()
        .join("\n");
    let tested = rust_blocks(&docs);
    assert_eq!(
        tested.len(),
        1,
        "the facade's crate docs hold one Rust example"
    );
    let in_readme = rust_blocks(&readme);
    assert!(
        in_readme.contains(&tested[0]),
        "README.md must contain the facade's doc-tested example verbatim:\n{}",
        tested[0]
    );
    assert!(
        tested[0].contains("use cagd::"),
        "the example goes through the facade"
    );
}
