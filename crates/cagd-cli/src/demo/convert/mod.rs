//! The conversion parts of `cagd demo`: a NURBS curve to Bézier pieces and back
//! ([`curve`]), and the patch conversions ([`patch`]).

pub(super) mod curve;
pub(super) mod patch;
