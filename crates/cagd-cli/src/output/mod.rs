//! What the `cagd` command writes: JSON and text to files or stdout ([`json`]), SVG pages
//! ([`svg`]) and the pictures drawn on them ([`picture`], [`interval`], [`implicit`]).

pub(crate) mod implicit;
pub(crate) mod interval;
pub(crate) mod json;
pub(crate) mod picture;
pub(crate) mod svg;
