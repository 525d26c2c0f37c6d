//! Point buffers written back in the input form, shared by every shape.

use serde_json::{Value, json};

/// A flat row-major buffer as a JSON list of points.
pub(crate) fn rows(flat: &[f64], dim: usize) -> Value {
    Value::Array(flat.chunks(dim).map(|p| json!(p)).collect())
}
