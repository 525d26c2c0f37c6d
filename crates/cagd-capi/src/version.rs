//! The version of the C ABI, as `#define`s in the header. The values equal the package
//! version (tested in `tests/header.rs` and below), so a C program can check at compile time
//! which cagd it was built against.

/// Major version of cagd (the `x` of `x.y.z`); becomes `#define CAGD_VERSION_MAJOR`.
pub const CAGD_VERSION_MAJOR: u32 = 0;
/// Minor version of cagd (the `y` of `x.y.z`); becomes `#define CAGD_VERSION_MINOR`.
pub const CAGD_VERSION_MINOR: u32 = 1;
/// Patch version of cagd (the `z` of `x.y.z`); becomes `#define CAGD_VERSION_PATCH`.
pub const CAGD_VERSION_PATCH: u32 = 0;

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn version_matches_cargo_toml() {
        let v = |s: &str| s.parse::<u32>().unwrap();
        assert_eq!(CAGD_VERSION_MAJOR, v(env!("CARGO_PKG_VERSION_MAJOR")));
        assert_eq!(CAGD_VERSION_MINOR, v(env!("CARGO_PKG_VERSION_MINOR")));
        assert_eq!(CAGD_VERSION_PATCH, v(env!("CARGO_PKG_VERSION_PATCH")));
    }
}
