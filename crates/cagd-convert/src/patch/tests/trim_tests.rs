//! The trimmed-patch job (§15.7.3): supported layouts tile the kept region exactly;
//! unsupported ones are named errors.

use proptest::prelude::*;

use super::{any_rect, assert_exact};
use crate::patch::{
    PatchPiece, PatchSurface, TrimChain, TrimDirection, TrimKeep, TrimSegment, trim_to_patches,
};
use cagd_core::Error;

/// Value of a Bernstein polynomial.
fn bez(c: &[f64], t: f64) -> f64 {
    let mut out = [0.0];
    let mut work = vec![0.0; c.len()];
    cagd_core::kernel::de_casteljau(c, 1, t, &mut work, &mut out);
    out[0]
}

/// The chain's function `f` at the free parameter `x`, if the chain covers `x`.
fn chain_value(chain: &TrimChain, x: f64) -> Option<f64> {
    chain
        .segments
        .iter()
        .find(|s| s.start <= x && x <= s.end)
        .map(|s| bez(&s.bezier, (x - s.start) / (s.end - s.start)))
}

/// Whether `(u, v)` is kept (well inside or well outside; `None` near the boundary).
fn kept(chain: &TrimChain, u: f64, v: f64) -> Option<bool> {
    let (x, y) = match chain.direction {
        TrimDirection::UOfV => (v, u),
        TrimDirection::VOfU => (u, v),
    };
    let below = match chain_value(chain, x) {
        Some(f) if (y - f).abs() < 1e-6 => return None,
        Some(f) => y < f,
        // Beyond the chain: the side the strip belongs to.
        None => {
            let end = if x < chain.segments[0].start {
                chain.segments[0].bezier[0]
            } else {
                *chain.segments.last().unwrap().bezier.last().unwrap()
            };
            end > 0.5
        }
    };
    Some(below == (chain.keep == TrimKeep::Below))
}

/// Every sample point of the square is covered by a piece iff it is kept, and by at most
/// one piece.
fn assert_covers_kept(chain: &TrimChain, pieces: &[PatchPiece]) {
    for a in 1..40 {
        for b in 1..40 {
            let (u, v) = (a as f64 / 40.0 + 0.0031, b as f64 / 40.0 + 0.0017);
            let Some(k) = kept(chain, u, v) else { continue };
            let loose = pieces
                .iter()
                .filter(|p| p.domain.locate(u, v, 1e-7).is_some())
                .count();
            let strict = pieces
                .iter()
                .filter(|p| p.domain.locate(u, v, -1e-7).is_some())
                .count();
            assert!(strict <= 1, "({u}, {v}) in {strict} pieces");
            assert_eq!(loose >= 1, k, "({u}, {v}) kept = {k}, covered by {loose}");
        }
    }
}

fn seg(start: f64, end: f64, bezier: &[f64]) -> TrimSegment {
    TrimSegment {
        start,
        end,
        bezier: bezier.to_vec(),
    }
}

/// Chains of each supported kind.
fn layouts() -> Vec<TrimChain> {
    let full = vec![
        seg(0.0, 0.4, &[0.3, 0.6, 0.5]),
        seg(0.4, 1.0, &[0.5, 0.2, 0.9, 0.7]),
    ];
    let to_left_edge = vec![seg(0.0, 0.7, &[0.6, 0.5, 0.2, 0.0])];
    let from_right_edge = vec![seg(0.3, 1.0, &[1.0, 0.4, 0.5])];
    let mut out = Vec::new();
    for segments in [full, to_left_edge, from_right_edge] {
        for direction in [TrimDirection::UOfV, TrimDirection::VOfU] {
            for keep in [TrimKeep::Below, TrimKeep::Above] {
                out.push(TrimChain {
                    direction,
                    keep,
                    segments: segments.clone(),
                });
            }
        }
    }
    out
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(6))]

    #[test]
    fn supported_layouts_tile_the_kept_region(p in any_rect(0..=5, 0..=5)) {
        for chain in layouts() {
            let pieces = trim_to_patches(&p, &chain).unwrap();
            assert_exact(&PatchSurface::Tensor(p.clone()), &pieces, 1e-13);
            assert_covers_kept(&chain, &pieces);
        }
    }
}

#[test]
fn unsupported_layouts_are_named_errors() {
    let p = crate::TensorSurface::new(vec![0.0, 1.0, 2.0, 3.0], 1, 1, 1, None).unwrap();
    let chain = |segments: Vec<TrimSegment>| TrimChain {
        direction: TrimDirection::UOfV,
        keep: TrimKeep::Below,
        segments,
    };
    let unsupported = [
        chain(vec![]),
        chain(vec![seg(0.0, 0.5, &[0.5, 0.5]), seg(0.6, 1.0, &[0.5, 0.5])]), // gap
        chain(vec![seg(0.0, 0.5, &[0.5, 0.5]), seg(0.5, 1.0, &[0.6, 0.5])]), // jump
        chain(vec![seg(0.0, 0.5, &[0.5, 0.5])]),                             // ends inside
        chain(vec![seg(0.2, 1.0, &[0.5, 0.5])]),                             // starts inside
        chain(vec![seg(0.0, 1.0, &[0.5, 0.5, 0.5, 0.5, 0.5])]),              // degree 4
    ];
    for c in unsupported {
        let e = trim_to_patches(&p, &c).unwrap_err();
        assert!(matches!(e, Error::UnsupportedTrim { .. }), "{e}");
    }
    // A curve leaving [0, 1]: the end value 1.2 is outside.
    let e = trim_to_patches(&p, &chain(vec![seg(0.0, 1.0, &[0.5, 1.2])])).unwrap_err();
    assert!(matches!(e, Error::BadParameter { .. }), "{e}");
    // Coefficients outside [0, 1] but values inside: accepted (0 <= f <= 1 is the condition).
    // f = (0.1, 1.05, 0.1) has maximum 0.575.
    assert!(trim_to_patches(&p, &chain(vec![seg(0.0, 1.0, &[0.1, 1.05, 0.1])])).is_ok());
    // Values leaving [0, 1] between the ends: f = (0.5, 1.8, 0.5) peaks at 1.15.
    let e = trim_to_patches(&p, &chain(vec![seg(0.0, 1.0, &[0.5, 1.8, 0.5])])).unwrap_err();
    assert!(matches!(e, Error::BadParameter { .. }), "{e}");
}
