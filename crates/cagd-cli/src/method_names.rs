//! The method names of `cagd reduce --method` (a module of its own so that the subprocess
//! fuzz driver, a separate test crate that includes `src/fuzz/` by path, fuzzes the same
//! names: a new method is fuzzed as soon as it is added).

/// Every method name the command accepts, in the order `cagd demo` prints them.
pub(crate) const NAMES: &[&str] = &[
    "forrest",
    "farin",
    "piegl",
    "perturbation",
    "perturbation-g1",
    "pinv",
    "pinv-ends",
    "chebyshev",
    "eck",
    "watkins-worsey",
    "bogacki",
    "l2",
];
