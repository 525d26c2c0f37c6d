//! Trimmed patch → untrimmed patches (SPEC-convert §15.7.3; the seed gives guidance only,
//! so the supported layout is designed here).
//!
//! **Supported layout.** One trimming chain that is the graph of a piecewise polynomial
//! function over one parameter direction: segments `u = f_i(v)` (or `v = g_i(u)`) over
//! consecutive intervals `[c_i, c_{i+1}]` of the other parameter, each of degree `<= 3`,
//! given by Bernstein coefficients over the local `t in [0, 1]` of its interval, with values
//! in `[0, 1]`, continuous at the joints. The chain either spans the whole interval
//! `[0, 1]` (it runs from one edge of the square to the opposite one) or starts / ends
//! where the curve meets a side edge (`f = 0` or `f = 1`), the rest of the boundary then
//! following that edge. The kept region is one side of the chain: `Below` (`u <= f(v)`,
//! resp. `v <= g(u)`) or `Above`.
//!
//! **Tiling.** Each segment gives one ruled piece between the curve and the kept side's
//! edge (the §15.7 corner cutting, `m x (k m + n)`); where the chain starts or ends on a
//! side edge, the strip beyond it belongs entirely to one side (to `Above` when the chain
//! touches `f = 0`, to `Below` when `f = 1`) and is kept as a plain sub-patch. Anything else
//! (gaps or overlaps between intervals, a jump at a joint, an end inside the square,
//! degree > 3, holes, several chains) is [`Error::UnsupportedTrim`]; a curve leaving
//! `[0, 1]` is [`Error::BadParameter`].

use cagd_core::{Error, Result};

use super::ruled::{check_side, ruled_subpatch};
use super::{PatchPiece, PieceDomain, TensorSurface};

/// Which parameter the trimming curves are functions of.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum TrimDirection {
    /// Curves `u = f(v)`, intervals in `v`.
    UOfV,
    /// Curves `v = g(u)`, intervals in `u`.
    VOfU,
}

/// Which side of the chain is kept.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum TrimKeep {
    /// `u <= f(v)` (resp. `v <= g(u)`).
    Below,
    /// `u >= f(v)` (resp. `v >= g(u)`).
    Above,
}

/// One polynomial segment of the chain.
#[derive(Debug, Clone, PartialEq)]
pub struct TrimSegment {
    /// Start of its interval of the free parameter.
    pub start: f64,
    /// End of its interval (`> start`).
    pub end: f64,
    /// Bernstein coefficients over the local `t in [0, 1]` of `[start, end]`, degree <= 3.
    pub bezier: Vec<f64>,
}

/// A trimming chain (see the module documentation for the supported layout).
#[derive(Debug, Clone, PartialEq)]
pub struct TrimChain {
    /// Curves `u = f(v)` or `v = g(u)`.
    pub direction: TrimDirection,
    /// The kept side.
    pub keep: TrimKeep,
    /// The segments, in increasing order of their intervals.
    pub segments: Vec<TrimSegment>,
}

/// Tolerance on joints and edge contacts (parameter units).
const JOINT: f64 = 1e-9;

/// Validates the chain's layout.
fn check_chain(chain: &TrimChain) -> Result<()> {
    let segs = &chain.segments;
    if segs.is_empty() {
        return Err(Error::UnsupportedTrim {
            index: 0,
            why: "the chain has no segment",
        });
    }
    for (index, s) in segs.iter().enumerate() {
        if s.bezier.is_empty() || s.bezier.len() > 4 {
            return Err(Error::UnsupportedTrim {
                index,
                why: "a segment needs degree 0..=3",
            });
        }
        check_side("trimming curve", &s.bezier)?;
        if !(s.start.is_finite()
            && s.end.is_finite()
            && 0.0 <= s.start
            && s.start < s.end
            && s.end <= 1.0)
        {
            return Err(Error::BadParameter {
                name: "trimming interval",
                value: if s.start.is_finite() && s.start >= 0.0 {
                    s.end
                } else {
                    s.start
                },
                why: "a segment's interval needs 0 <= start < end <= 1",
            });
        }
        if index > 0 {
            let prev = &segs[index - 1];
            if (prev.end - s.start).abs() > JOINT {
                return Err(Error::UnsupportedTrim {
                    index,
                    why: "intervals must follow each other without gap or overlap",
                });
            }
            let (a, b) = (prev.bezier[prev.bezier.len() - 1], s.bezier[0]);
            if (a - b).abs() > JOINT {
                return Err(Error::UnsupportedTrim {
                    index,
                    why: "the chain jumps at a joint",
                });
            }
        }
    }
    let on_edge = |x: f64| x.abs() <= JOINT || (x - 1.0).abs() <= JOINT;
    let (first, last) = (&segs[0], &segs[segs.len() - 1]);
    if first.start > JOINT && !on_edge(first.bezier[0]) {
        return Err(Error::UnsupportedTrim {
            index: 0,
            why: "the chain starts inside the square (it must start on an edge)",
        });
    }
    if last.end < 1.0 - JOINT && !on_edge(last.bezier[last.bezier.len() - 1]) {
        return Err(Error::UnsupportedTrim {
            index: segs.len() - 1,
            why: "the chain ends inside the square (it must end on an edge)",
        });
    }
    Ok(())
}

/// The untrimmed patches covering exactly the kept region of `p` trimmed by `chain`, each
/// with its domain (ruled pieces along the curves, bilinear strips beyond the chain's
/// ends). See the module documentation for the supported layouts.
/// (SPEC-convert §15.7.3 guidance, applied with §15.7's split along a curve; the tiling
/// itself is ours.)
///
/// # Errors
/// [`Error::UnsupportedTrim`] for a layout outside the supported one,
/// [`Error::BadParameter`] when a curve leaves `[0, 1]` or an interval is not in `[0, 1]`.
pub fn trim_to_patches(p: &TensorSurface, chain: &TrimChain) -> Result<Vec<PatchPiece>> {
    check_chain(chain)?;
    let transposed = chain.direction == TrimDirection::VOfU;
    let mut out = Vec::new();
    let strip = |v0: f64, v1: f64| -> Result<PatchPiece> {
        let mut piece = ruled_subpatch(p, &[0.0], &[1.0], v0, v1, transposed)?;
        let c = [[0.0, v0], [1.0, v0], [0.0, v1], [1.0, v1]];
        piece.domain = PieceDomain::Bilinear(if transposed {
            c.map(|[a, b]| [b, a])
        } else {
            c
        });
        Ok(piece)
    };
    // Which side a strip beyond an end belongs to: Above when the chain touches f = 0.
    let strip_kept = |f_end: f64| (f_end.abs() <= JOINT) == (chain.keep == TrimKeep::Above);
    let segs = &chain.segments;
    let first = &segs[0];
    if first.start > JOINT && strip_kept(first.bezier[0]) {
        out.push(strip(0.0, first.start)?);
    }
    for s in segs {
        let piece = match chain.keep {
            TrimKeep::Below => ruled_subpatch(p, &[0.0], &s.bezier, s.start, s.end, transposed)?,
            TrimKeep::Above => ruled_subpatch(p, &s.bezier, &[1.0], s.start, s.end, transposed)?,
        };
        out.push(piece);
    }
    let last = &segs[segs.len() - 1];
    if last.end < 1.0 - JOINT && strip_kept(last.bezier[last.bezier.len() - 1]) {
        out.push(strip(last.end, 1.0)?);
    }
    Ok(out)
}
