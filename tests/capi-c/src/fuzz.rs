//! The C ABI fuzz harness of `fuzz/capi` (issue 18), run in-process: a short seeded run
//! under the debug build (whose overflow checks turn arithmetic overflows into caught
//! panics, which the oracle reports), and the check that every `cagd_*` function of
//! `include/cagd.h` has an operation in the harness, so that a new entry point cannot be
//! left out of the fuzzing.

#[cfg(test)]
#[allow(unsafe_code, reason = "calls the C fuzz harness")]
mod tests {
    use std::collections::BTreeSet;
    use std::path::PathBuf;

    unsafe extern "C" {
        fn cagd_fuzz_run_seed(seed: u64, calls: u64, session_calls: u64, verbose: i32) -> u64;
        fn cagd_fuzz_n_functions() -> usize;
    }

    fn repo_file(rel: &str) -> String {
        let p = PathBuf::from(env!("CARGO_MANIFEST_DIR"))
            .join("../..")
            .join(rel);
        std::fs::read_to_string(&p).unwrap_or_else(|e| panic!("cannot read {}: {e}", p.display()))
    }

    /// The identifiers `cagd_<x>` directly followed by `(` in `text` (outside comments for
    /// the header: cbindgen puts a declaration's name at the start of a line or after its
    /// return type; doc comments mention functions as `` `cagd_x` `` without a paren).
    fn declared(header: &str) -> BTreeSet<String> {
        let mut names = BTreeSet::new();
        for line in header.lines() {
            let t = line.trim_start();
            if t.starts_with('*') || t.starts_with("/*") || t.starts_with("//") {
                continue;
            }
            let mut rest = t;
            while let Some(i) = rest.find("cagd_") {
                let tail = &rest[i..];
                let end = tail
                    .find(|c: char| !(c.is_ascii_alphanumeric() || c == '_'))
                    .unwrap_or(tail.len());
                if tail[end..].starts_with('(') {
                    names.insert(tail[..end].to_owned());
                }
                rest = &tail[end..];
            }
        }
        names
    }

    /// The `X(cagd_<x>)` entries of the harness's operation table.
    fn fuzzed(ops: &str) -> BTreeSet<String> {
        ops.split("X(cagd_")
            .skip(1)
            .filter_map(|s| s.split_once(')').map(|(n, _)| format!("cagd_{n}")))
            .filter(|n| n.chars().all(|c| c.is_ascii_alphanumeric() || c == '_'))
            .collect()
    }

    #[test]
    fn every_header_function_is_fuzzed() {
        let header = declared(&repo_file("include/cagd.h"));
        let fuzzed = fuzzed(&repo_file("fuzz/capi/ops.c"));
        assert!(
            header.len() >= 100,
            "found only {} functions; parser broken?",
            header.len()
        );
        let missing: Vec<_> = header.difference(&fuzzed).collect();
        let stale: Vec<_> = fuzzed.difference(&header).collect();
        assert!(
            missing.is_empty() && stale.is_empty(),
            "cagd_* functions of include/cagd.h without a fuzz operation in fuzz/capi/ops.c \
             (add an op_<name> and an X(<name>) entry): {missing:?}; operations for \
             functions no longer in the header: {stale:?}"
        );
        // SAFETY: a pure function of the harness.
        let n = unsafe { cagd_fuzz_n_functions() };
        assert_eq!(
            n,
            fuzzed.len(),
            "the X() list and the compiled table differ"
        );
    }

    /// A short run (fixed seed): every call returns a documented status, never
    /// `CAGD_ERR_PANIC`, outputs are finite, sizes consistent, bounds above errors. The C
    /// harness abort()s with the function, session seed and call on a violation.
    #[test]
    fn short_seeded_run_passes_the_oracle() {
        // SAFETY: the harness uses only its own memory and the cagd C ABI, and frees every
        // handle it creates before returning.
        let made = unsafe { cagd_fuzz_run_seed(20_261_126, 3_000, 300, 0) };
        assert_eq!(made, 3_000);
    }
}
