//! What `cagd reduce` gives back for each input object: its output or a failure naming
//! the JSON path; the default method.

use serde_json::Value;

use crate::input::shape::Shape;

/// The default method when `--method` is not given: the L2-optimal reduction with the end
/// points interpolated, the choice that keeps neighbouring curves connected.
pub(crate) const DEFAULT_METHOD: &str = "l2";

/// A failure of one object: its JSON path and the message.
#[derive(Debug)]
pub(crate) struct Failure {
    pub(crate) path: String,
    pub(crate) message: String,
}

/// The result of one input object: its output JSON and, for pictures, the input and result.
pub(crate) struct Output {
    pub(crate) json: Value,
    pub(crate) pair: Option<(Shape, Shape)>,
}
