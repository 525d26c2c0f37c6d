//! The subcommands of `cagd`: the command line ([`args`]), `reduce` (one part per shape),
//! `merge`, `convert` (NURBS and patch conversions), `implicitize` / `intersect`.
//! (`check` and `demo` have their own folders.)

pub(crate) mod args;
pub(crate) mod convert;
pub(crate) mod implicit;
pub(crate) mod merge;
pub(crate) mod reduce;
