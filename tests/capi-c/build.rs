//! Compiles the C tests (`c/*.c`, C11, warnings as errors) and one C++17 translation unit
//! (`cpp/*.cpp`) against the committed `include/cagd.h` (STYLE §9.10). The header is not
//! generated here: a build script cannot rely on another crate's build output, and the
//! header's freshness is checked by cagd-capi's `header_is_fresh` test.

use std::path::{Path, PathBuf};

fn sources(dir: &Path, ext: &str) -> Vec<PathBuf> {
    let mut files: Vec<PathBuf> = std::fs::read_dir(dir)
        .unwrap_or_else(|e| panic!("cannot read {}: {e}", dir.display()))
        .map(|entry| entry.expect("directory entry").path())
        .filter(|p| p.extension().is_some_and(|e| e == ext))
        .collect();
    files.sort();
    files
}

fn main() {
    let here = PathBuf::from(std::env::var("CARGO_MANIFEST_DIR").expect("set by cargo"));
    let include = here.join("../../include");
    println!("cargo:rerun-if-changed=c");
    println!("cargo:rerun-if-changed=cpp");
    println!(
        "cargo:rerun-if-changed={}",
        include.join("cagd.h").display()
    );

    let c_files = sources(&here.join("c"), "c");
    for f in sources(&here.join("c"), "h").iter().chain(&c_files) {
        println!("cargo:rerun-if-changed={}", f.display());
    }
    cc::Build::new()
        .files(&c_files)
        .include(&include)
        .std("c11")
        .flag("-Wall")
        .flag("-Wextra")
        .flag("-Wpedantic")
        .flag("-Werror")
        .compile("cagd_ctests");

    // The C ABI fuzz harness (fuzz/capi, issue 18): its infrastructure and operations, run
    // in-process by src/fuzz.rs (a short seeded run under the debug build, whose overflow
    // checks turn arithmetic overflows into caught panics the oracle reports).
    let fuzz = here.join("../../fuzz/capi");
    println!("cargo:rerun-if-changed={}", fuzz.display());
    let fuzz_files = [fuzz.join("harness.c"), fuzz.join("ops.c")];
    for f in sources(&fuzz, "h").iter().chain(&fuzz_files) {
        println!("cargo:rerun-if-changed={}", f.display());
    }
    cc::Build::new()
        .files(&fuzz_files)
        .include(&include)
        .std("c11")
        .flag("-Wall")
        .flag("-Wextra")
        .flag("-Wpedantic")
        .flag("-Werror")
        .compile("cagd_capi_fuzz");

    let cpp_files = sources(&here.join("cpp"), "cpp");
    cc::Build::new()
        .cpp(true)
        .files(&cpp_files)
        .include(&include)
        .std("c++17")
        .flag("-Wall")
        .flag("-Wextra")
        .flag("-Wpedantic")
        .flag("-Werror")
        .compile("cagd_cpptests");
}
