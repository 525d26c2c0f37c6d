//! The committed header `include/cagd.h` is what cbindgen generates from this crate
//! (`header_is_fresh`; `CAGD_BLESS=1` rewrites it), every declaration in it is documented,
//! and its version macros equal the package version.

use std::path::PathBuf;

fn crate_dir() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

fn header_path() -> PathBuf {
    crate_dir().join("../../include/cagd.h")
}

fn generate() -> String {
    let config = cbindgen::Config::from_file(crate_dir().join("cbindgen.toml"))
        .expect("cbindgen.toml parses");
    let bindings = cbindgen::Builder::new()
        .with_crate(crate_dir())
        .with_config(config)
        .generate()
        .expect("cbindgen generates the header");
    let mut out = Vec::new();
    bindings.write(&mut out);
    String::from_utf8(out).expect("header is UTF-8")
}

#[test]
fn header_is_fresh() {
    let fresh = generate();
    let path = header_path();
    if std::env::var_os("CAGD_BLESS").is_some_and(|v| v == "1") {
        std::fs::write(&path, &fresh).expect("write include/cagd.h");
        return;
    }
    let committed = std::fs::read_to_string(&path).unwrap_or_default();
    assert!(
        committed == fresh,
        "include/cagd.h is stale; regenerate it with \
         `CAGD_BLESS=1 cargo test -p cagd-capi --test header` and commit it"
    );
}

/// A declaration line of the header: a function prototype, a typedef, an enum, a struct or
/// a `#define CAGD_` macro, starting in column 0 (continuation lines are indented).
fn is_declaration(l: &str) -> bool {
    (l.starts_with("typedef ")
        || l.starts_with("enum ")
        || l.starts_with("struct ")
        || l.starts_with("#define CAGD_")
        || (l.contains(" cagd_") && l.contains('(')))
        && !l.starts_with(' ')
}

#[test]
fn every_declaration_is_documented() {
    let text = std::fs::read_to_string(header_path()).expect("include/cagd.h exists");
    let lines: Vec<&str> = text.lines().collect();
    let mut checked = 0;
    let mut documented_enums: Vec<String> = Vec::new();
    for (i, line) in lines.iter().enumerate() {
        let l = line.trim();
        if !is_declaration(line) || l.starts_with("#define CAGD_H") {
            continue;
        }
        // cbindgen follows a documented `enum X` with `typedef enum X X;` or
        // `typedef int32_t X;` inside preprocessor conditionals: those repeat the enum.
        if l.starts_with("typedef ")
            && documented_enums
                .iter()
                .any(|e| l.ends_with(&format!(" {e};")))
        {
            continue;
        }
        let documented = i > 0 && lines[i - 1].trim().ends_with("*/");
        assert!(documented, "line {}: `{l}` has no doc comment", i + 1);
        if let Some(name) = l.strip_prefix("enum ") {
            documented_enums.push(name.trim().to_owned());
        }
        checked += 1;
    }
    assert!(
        checked >= 20,
        "only {checked} declarations found; parser broken?"
    );
}

#[test]
fn every_function_documents_its_statuses() {
    let text = std::fs::read_to_string(header_path()).expect("include/cagd.h exists");
    // Split into comment + declaration chunks at each "/**".
    let mut checked = 0;
    for chunk in text.split("/**").skip(1) {
        let Some((doc, decl)) = chunk.split_once("*/") else {
            continue;
        };
        let decl = decl.trim_start().lines().next().unwrap_or("");
        if decl.starts_with("CagdStatus cagd_") {
            assert!(doc.contains("Returns:"), "{decl}: no Returns: section");
            assert!(doc.contains("CAGD_OK"), "{decl}: CAGD_OK not documented");
            assert!(
                doc.contains("CAGD_ERR_PANIC"),
                "{decl}: CAGD_ERR_PANIC not documented"
            );
            assert!(
                doc.contains("Parameters:"),
                "{decl}: no Parameters: section"
            );
            assert!(doc.contains("# Safety"), "{decl}: no Safety section");
            checked += 1;
        }
    }
    assert!(
        checked >= 15,
        "only {checked} functions found; parser broken?"
    );
}

#[test]
fn version_macros_match_cargo_toml() {
    let text = std::fs::read_to_string(header_path()).expect("include/cagd.h exists");
    for (name, want) in [
        ("CAGD_VERSION_MAJOR", env!("CARGO_PKG_VERSION_MAJOR")),
        ("CAGD_VERSION_MINOR", env!("CARGO_PKG_VERSION_MINOR")),
        ("CAGD_VERSION_PATCH", env!("CARGO_PKG_VERSION_PATCH")),
    ] {
        let line = text
            .lines()
            .find(|l| l.starts_with(&format!("#define {name} ")))
            .unwrap_or_else(|| panic!("{name} missing from the header"));
        let value = line.split_whitespace().nth(2).unwrap();
        assert_eq!(value, want, "{name}");
    }
}
