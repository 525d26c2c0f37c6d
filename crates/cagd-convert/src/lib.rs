//! # cagd-convert
//!
//! Representation conversions of seed 002 (chapter 15.1–15.7) as corrected by
//! SPEC-convert: NURBS spans ↔ rational Bézier segments (closed forms §15.1–15.3 and the
//! general route of any degree), triangular ↔ rectangular patches (§15.4–15.5), and exact
//! subdivision of a patch along a line or a polynomial curve (§15.6–15.7).
//!
//! Every rational formula is applied as a linear map on homogeneous points `(w r, w)`
//! (SPEC-convert §0), divided at the end.
