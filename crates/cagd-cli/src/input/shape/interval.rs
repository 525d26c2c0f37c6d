//! The interval-triangle shape (seed 004, SPEC-convert part I):
//! `{"type":"interval-triangle","degree":n,"lo":[[x,y,...],...],"hi":[...]}` (i-major, as
//! for triangles), validated and written back.

use cagd_core::Error;
use cagd_reduce::IntervalTriPatch;
use serde_json::{Value, json};

use crate::input::shape::rows;
use crate::input::{InputError, PointList};

/// Validates the nets with cagd-reduce; errors name the offending field.
pub(crate) fn build(
    degree: usize,
    lo: PointList,
    hi: PointList,
    path: &str,
) -> Result<IntervalTriPatch, InputError> {
    IntervalTriPatch::new(lo.coords, hi.coords, degree, lo.dim).map_err(|e| {
        let at = match &e {
            Error::EmptyInterval { index, coord, .. } => format!("{path}.lo[{index}][{coord}]"),
            Error::DegreeOutOfRange { .. } => format!("{path}.degree"),
            _ => path.to_string(),
        };
        InputError::new(at, e.to_string())
    })
}

/// The shape in the input JSON form.
pub(crate) fn to_json(t: &IntervalTriPatch) -> Value {
    json!({
        "type": "interval-triangle",
        "degree": t.degree(),
        "lo": rows(t.lo(), t.dim()),
        "hi": rows(t.hi(), t.dim()),
    })
}
