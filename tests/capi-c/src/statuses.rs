//! The per-function status table of the C ABI fuzz harness (issue 18): `fuzz/capi/statuses.h`
//! is generated from the doc comments of `include/cagd.h`, so that the harness's oracle
//! checks that every status a function returns is one its doc comment lists (DESIGN.md:
//! "every C function's doc comment lists every status it can return"), from the header
//! itself and not from a hand-kept list.
//!
//! The rule read from the header: a function returning `CagdStatus` has a `Returns:`
//! section, a list whose items start with one or more status names before the item's
//! first `:` outside parentheses and backticks
//! (`` - `CAGD_ERR_BAD_KNOTS`, `CAGD_ERR_NON_FINITE` (fit): ... ``). A status named only
//! inside an item's text (after its `:`), or a list item that does not start with a
//! status, is refused: such a doc comment does not say clearly what the function returns.
//!
//! `status_table_is_fresh` fails when the committed table differs from the one the
//! header gives; `CAGD_BLESS=1 cargo test -p cagd-capi-ctests --lib statuses` rewrites it.

#[cfg(test)]
mod tests {
    use std::collections::BTreeMap;
    use std::fmt::Write as _;
    use std::path::PathBuf;

    fn repo_path(rel: &str) -> PathBuf {
        PathBuf::from(env!("CARGO_MANIFEST_DIR"))
            .join("../..")
            .join(rel)
    }

    fn read(rel: &str) -> String {
        let p = repo_path(rel);
        std::fs::read_to_string(&p).unwrap_or_else(|e| panic!("cannot read {}: {e}", p.display()))
    }

    /// The `CagdStatus` enumerators of the header, name to value.
    fn status_names(header: &str) -> BTreeMap<String, i32> {
        let start = header
            .find("enum CagdStatus")
            .expect("include/cagd.h declares enum CagdStatus");
        let body = &header[start..];
        let end = body.find("};").expect("enum CagdStatus ends");
        let mut names = BTreeMap::new();
        for line in body[..end].lines() {
            let t = line.trim();
            if let Some((name, value)) = t.split_once(" = ") {
                if name.starts_with("CAGD_") {
                    let v = value.trim_end_matches(',').trim();
                    let v: i32 = v
                        .parse()
                        .unwrap_or_else(|_| panic!("CagdStatus {name} = {v}: not a number"));
                    names.insert(name.to_owned(), v);
                }
            }
        }
        names
    }

    /// A function declared in the header: its name, return type and doc comment (the
    /// comment text lines with the leading ` * ` removed).
    struct Decl {
        name: String,
        returns: String,
        doc: Vec<String>,
    }

    /// The function declarations of the header (cbindgen writes each one's name on the
    /// line that starts it, after its return type, directly after its doc comment).
    fn declarations(header: &str) -> Vec<Decl> {
        let mut out = Vec::new();
        let mut doc: Vec<String> = Vec::new();
        let mut in_doc = false;
        let mut doc_just_closed = false;
        for line in header.lines() {
            let t = line.trim();
            if in_doc {
                if t == "*/" {
                    in_doc = false;
                    doc_just_closed = true;
                } else {
                    let text = t.strip_prefix('*').unwrap_or(t);
                    doc.push(text.strip_prefix(' ').unwrap_or(text).to_owned());
                }
                continue;
            }
            if t == "/**" {
                in_doc = true;
                doc.clear();
                continue;
            }
            if !doc_just_closed {
                continue;
            }
            doc_just_closed = false;
            let Some(open) = t.find('(') else { continue };
            let head = &t[..open];
            let Some(at) = head.rfind("cagd_") else {
                continue;
            };
            let name = &head[at..];
            if !name.chars().all(|c| c.is_ascii_alphanumeric() || c == '_') {
                continue;
            }
            out.push(Decl {
                name: name.to_owned(),
                returns: head[..at].trim().to_owned(),
                doc: std::mem::take(&mut doc),
            });
        }
        out
    }

    /// The `` `CAGD_X` `` names in `text`.
    fn backticked_statuses(text: &str) -> Vec<String> {
        text.split('`')
            .skip(1)
            .step_by(2)
            .filter(|s| s.starts_with("CAGD_"))
            .map(str::to_owned)
            .collect()
    }

    /// The item's head: its text up to the first `:` outside parentheses and backticks.
    fn item_head(item: &str) -> &str {
        let (mut depth, mut tick) = (0i32, false);
        for (i, c) in item.char_indices() {
            match c {
                '`' => tick = !tick,
                '(' if !tick => depth += 1,
                ')' if !tick => depth -= 1,
                ':' if !tick && depth == 0 => return &item[..i],
                _ => {}
            }
        }
        item
    }

    /// The statuses the doc comment of `d` lists, in the order listed, or why they cannot
    /// be read.
    fn listed(d: &Decl, known: &BTreeMap<String, i32>) -> Result<Vec<String>, String> {
        let at = d
            .doc
            .iter()
            .position(|l| l.trim() == "Returns:")
            .ok_or("no `Returns:` section")?;
        // The items: `- ` starts one, deeper-indented lines continue it, a blank line or
        // a heading ends the section.
        let mut items: Vec<String> = Vec::new();
        for l in &d.doc[at + 1..] {
            if l.trim().is_empty() || l.starts_with('#') {
                break;
            }
            if let Some(rest) = l.strip_prefix("- ") {
                items.push(rest.to_owned());
            } else if l.starts_with("  ") && !items.is_empty() {
                let last = items.last_mut().expect("not empty");
                last.push(' ');
                last.push_str(l.trim());
            } else {
                return Err(format!("unexpected line in `Returns:`: {l:?}"));
            }
        }
        if items.is_empty() {
            return Err("empty `Returns:` section".to_owned());
        }
        let mut out: Vec<String> = Vec::new();
        for item in &items {
            if !item.starts_with("`CAGD_") {
                return Err(format!(
                    "an item that does not start with a status: {item:?}"
                ));
            }
            for s in backticked_statuses(item_head(item)) {
                if !known.contains_key(&s) {
                    return Err(format!("{s} is not a CagdStatus (item {item:?})"));
                }
                if !out.contains(&s) {
                    out.push(s);
                }
            }
        }
        for item in &items {
            let body = &item[item_head(item).len()..];
            for s in backticked_statuses(body) {
                if known.contains_key(&s) && !out.contains(&s) {
                    return Err(format!(
                        "{s} is named inside an item, not at the start of one (give it its \
                         own item): {item:?}"
                    ));
                }
            }
        }
        Ok(out)
    }

    /// The generated C table: one row per function returning `CagdStatus`.
    fn generate(header: &str) -> Result<String, Vec<String>> {
        let known = status_names(header);
        assert!(known.len() >= 20, "found only {} statuses", known.len());
        let mut errors = Vec::new();
        let mut rows = Vec::new();
        for d in declarations(header) {
            if d.returns != "CagdStatus" {
                continue;
            }
            match listed(&d, &known) {
                Ok(list) => rows.push((d.name, list)),
                Err(e) => errors.push(format!("{}: {e}", d.name)),
            }
        }
        if !errors.is_empty() {
            return Err(errors);
        }
        rows.sort();
        let width = rows.iter().map(|(_, l)| l.len()).max().unwrap_or(0);
        let mut s = String::new();
        s.push_str(
            "/* The statuses each cagd_* function's doc comment in include/cagd.h lists (its\n \
             * `Returns:` items), for the per-function status oracle of the C ABI fuzz harness\n \
             * (fuzz/capi/README.md). Generated by tests/capi-c/src/statuses.rs; do not edit.\n \
             * Regenerate with CAGD_BLESS=1 cargo test -p cagd-capi-ctests --lib statuses */\n",
        );
        s.push_str("#ifndef CAGD_FUZZ_STATUSES_H\n#define CAGD_FUZZ_STATUSES_H\n\n");
        s.push_str("#include \"cagd.h\"\n\n#include <stddef.h>\n\n");
        let _ = writeln!(s, "#define FZ_DOC_MAX_STATUSES {width}\n");
        s.push_str(
            "typedef struct FzDocStatuses {\n    const char *fn;\n    size_t n;\n    \
             CagdStatus statuses[FZ_DOC_MAX_STATUSES];\n} FzDocStatuses;\n\n",
        );
        s.push_str("static const FzDocStatuses FZ_DOC_STATUSES[] = {\n");
        for (name, list) in &rows {
            let _ = writeln!(s, "    {{\"{name}\", {},", list.len());
            let _ = writeln!(s, "     {{{}}}}},", list.join(", "));
        }
        s.push_str("};\n\n#endif\n");
        Ok(s)
    }

    #[test]
    fn status_table_is_fresh() {
        let header = read("include/cagd.h");
        let table = generate(&header).unwrap_or_else(|errors| {
            panic!(
                "doc comments of include/cagd.h whose `Returns:` list cannot be read \
                 (fix them in crates/cagd-capi/src, then CAGD_BLESS=1 cargo test -p \
                 cagd-capi --test header):\n{}",
                errors.join("\n")
            )
        });
        let rel = "fuzz/capi/statuses.h";
        if std::env::var_os("CAGD_BLESS").is_some_and(|v| v == "1") {
            std::fs::write(repo_path(rel), &table).expect("write fuzz/capi/statuses.h");
            return;
        }
        let committed = std::fs::read_to_string(repo_path(rel)).unwrap_or_default();
        assert!(
            committed == table,
            "{rel} is stale against the doc comments of include/cagd.h; regenerate it with \
             `CAGD_BLESS=1 cargo test -p cagd-capi-ctests --lib statuses` and commit it"
        );
    }

    #[test]
    fn the_table_reader_finds_what_the_doc_says() {
        let header = read("include/cagd.h");
        let decls = declarations(&header);
        let fallible = decls.iter().filter(|d| d.returns == "CagdStatus").count();
        assert!(
            fallible >= 100,
            "found only {fallible} fallible functions; parser broken?"
        );
        let known = status_names(&header);
        assert_eq!(known.get("CAGD_OK"), Some(&0));
        assert_eq!(known.get("CAGD_ERR_PANIC"), Some(&99));
        let new = decls
            .iter()
            .find(|d| d.name == "cagd_curve_new")
            .expect("cagd_curve_new is declared");
        let list = listed(new, &known).expect("cagd_curve_new's list reads");
        for s in [
            "CAGD_OK",
            "CAGD_ERR_NULL_POINTER",
            "CAGD_ERR_INVALID_ARGUMENT",
            "CAGD_ERR_NOT_ENOUGH_POINTS",
            "CAGD_ERR_DEGREE_OUT_OF_RANGE",
            "CAGD_ERR_NON_FINITE",
            "CAGD_ERR_PANIC",
        ] {
            assert!(list.iter().any(|l| l == s), "{s} missing from {list:?}");
        }
        assert_eq!(list.len(), 7, "{list:?}");
        // Several statuses in one item head, a parenthesis with a colon inside the head,
        // and a status named in an item's text (refused).
        let known_small: BTreeMap<String, i32> = ["CAGD_OK", "CAGD_ERR_A", "CAGD_ERR_B"]
            .iter()
            .enumerate()
            .map(|(i, s)| ((*s).to_owned(), i32::try_from(i).expect("small")))
            .collect();
        let doc = |lines: &[&str]| Decl {
            name: "cagd_x".to_owned(),
            returns: "CagdStatus".to_owned(),
            doc: lines.iter().map(|s| (*s).to_owned()).collect(),
        };
        let d = doc(&[
            "Returns:",
            "- `CAGD_OK`.",
            "- `CAGD_ERR_A` (fit: `x`),",
            "  `CAGD_ERR_B`: as `cagd_y`.",
            "",
            "# Safety",
        ]);
        assert_eq!(
            listed(&d, &known_small).expect("reads"),
            ["CAGD_OK", "CAGD_ERR_A", "CAGD_ERR_B"]
        );
        let d = doc(&["Returns:", "- `CAGD_OK`: fine. `CAGD_ERR_B`: bad."]);
        assert!(listed(&d, &known_small).is_err());
        let d = doc(&["Returns:", "- fine."]);
        assert!(listed(&d, &known_small).is_err());
        let d = doc(&["Returns:", "- `CAGD_ERR_C`: unknown."]);
        assert!(listed(&d, &known_small).is_err());
    }
}
