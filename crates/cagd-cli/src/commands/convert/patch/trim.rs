//! The trimming file of `cagd convert --trim FILE` (SPEC-convert §15.7.3):
//!
//! ```json
//! {"direction": "u_of_v", "keep": "below",
//!  "segments": [{"interval": [0, 0.4], "bezier": [0.3, 0.6, 0.5]},
//!               {"interval": [0.4, 1], "bezier": [0.5, 0.2, 0.9, 0.7]}]}
//! ```
//!
//! `direction`: `"u_of_v"` (curves `u = f(v)`, intervals in `v`) or `"v_of_u"`; `keep`:
//! `"below"` (`u <= f(v)`, resp. `v <= g(u)`) or `"above"`; `segments`: consecutive
//! intervals of the free parameter, each with the Bernstein coefficients (degree <= 3) of
//! the curve over the local `t in [0, 1]` of its interval. The chain must be continuous
//! and run from edge to edge of the square: across the whole `[0, 1]`, or starting / ending
//! where the curve meets a side edge (`f = 0` or `f = 1`). Other layouts are refused with a
//! named error (see `cagd_convert::trim_to_patches`).

use std::path::Path;

use cagd_convert::{TrimChain, TrimDirection, TrimKeep, TrimSegment};
use serde_json::Value;

use crate::input::{field, numbers};

/// Reads and parses a trimming file.
pub(crate) fn read(path: &Path) -> Result<TrimChain, String> {
    let text = crate::input::read_file(path)?;
    let v: Value = serde_json::from_str(&text)
        .map_err(|e| format!("{}: not valid JSON: {e}", path.display()))?;
    parse(&v).map_err(|e| format!("{}: {e}", path.display()))
}

/// Parses a trimming chain object.
pub(crate) fn parse(v: &Value) -> Result<TrimChain, String> {
    let p = "trim";
    let direction = match field(v, p, "direction")
        .map_err(|e| e.to_string())?
        .as_str()
    {
        Some("u_of_v") => TrimDirection::UOfV,
        Some("v_of_u") => TrimDirection::VOfU,
        _ => return Err("trim.direction: expected \"u_of_v\" or \"v_of_u\"".into()),
    };
    let keep = match field(v, p, "keep").map_err(|e| e.to_string())?.as_str() {
        Some("below") => TrimKeep::Below,
        Some("above") => TrimKeep::Above,
        _ => return Err("trim.keep: expected \"below\" or \"above\"".into()),
    };
    let segs = field(v, p, "segments")
        .map_err(|e| e.to_string())?
        .as_array()
        .ok_or("trim.segments: expected an array")?;
    let mut segments = Vec::with_capacity(segs.len());
    for (i, s) in segs.iter().enumerate() {
        let sp = format!("trim.segments[{i}]");
        let interval = numbers(
            field(s, &sp, "interval").map_err(|e| e.to_string())?,
            &format!("{sp}.interval"),
        )
        .map_err(|e| e.to_string())?;
        let [start, end] = interval[..] else {
            return Err(format!("{sp}.interval: expected [start, end]"));
        };
        let bezier = numbers(
            field(s, &sp, "bezier").map_err(|e| e.to_string())?,
            &format!("{sp}.bezier"),
        )
        .map_err(|e| e.to_string())?;
        segments.push(TrimSegment { start, end, bezier });
    }
    Ok(TrimChain {
        direction,
        keep,
        segments,
    })
}
