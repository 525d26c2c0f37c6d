//! [`OuterKnots`]: the knots of a spline's knot vector beyond its first and last
//! breakpoint — what Bézier pieces do not carry, and what an unclamped spline needs to come
//! back from its pieces with the same knot vector. (Beyond the seed: SPEC-convert §15.3's
//! general route describes the clamped case; the curve on its domain never depends on
//! these knots, its control points do.)

use cagd_core::{Error, Result};

/// The outer knots of a spline of degree `p` whose domain is `[a, b]` (the first and the
/// last break): its full knot vector is `left ++ [a] ++ (interior knots) ++ [b] ++ right`,
/// where `left` is every knot before the last copy of `a` and `right` every knot after the
/// first copy of `b`. A clamped spline has `left = [a; p]`, `right = [b; p]`.
///
/// Invariants (checked by [`crate::BezierPieces::with_outer_knots`]): both have at least `p` knots, are finite
/// and non-decreasing, `left <= a`, `right >= b`; the knots of `left` from index `p` on
/// (and of `right` up to `right.len() - p`) equal `a` (`b`), so that the domain of the
/// spline is `[a, b]`; `a` and `b` keep multiplicity `<= p + 1`.
#[derive(Debug, Clone, PartialEq)]
pub struct OuterKnots {
    pub(crate) left: Vec<f64>,
    pub(crate) right: Vec<f64>,
}

impl OuterKnots {
    /// Outer knots for a spline of degree `degree` on `[a, b]`, validated (through
    /// [`crate::BezierPieces::with_outer_knots`]).
    ///
    /// # Errors
    /// [`Error::BadParameter`] naming `"outer_knots.left"` or `"outer_knots.right"` and the
    /// offending knot: fewer than `degree` knots, a non-finite or decreasing knot, a knot
    /// on the wrong side of `a` (`b`), a domain that would not start at `a` (end at `b`),
    /// or `a` (`b`) with multiplicity above `degree + 1`.
    pub(crate) fn new(
        left: Vec<f64>,
        right: Vec<f64>,
        degree: usize,
        a: f64,
        b: f64,
    ) -> Result<Self> {
        check_side(&left, degree, a, "outer_knots.left", false)?;
        let rev: Vec<f64> = right.iter().rev().map(|x| -x).collect();
        check_side(&rev, degree, -b, "outer_knots.right", true)?;
        Ok(Self { left, right })
    }

    /// The outer knots of a valid knot vector `knots` of degree `p` with `n` control
    /// points (`knots.len() == n + p + 1`), `None` when it is clamped at both ends.
    pub(crate) fn of_knots(knots: &[f64], p: usize, n: usize) -> Option<Self> {
        let mut s = p;
        while knots[s + 1] <= knots[s] {
            s += 1;
        }
        let mut e = n;
        while knots[e - 1] >= knots[e] {
            e -= 1;
        }
        let (a, b) = (knots[s], knots[e]);
        let clamped = s == p && e == n && knots[..p].iter().all(|x| *x == a) && {
            knots[n + 1..].iter().all(|x| *x == b)
        };
        (!clamped).then(|| Self {
            left: knots[..s].to_vec(),
            right: knots[e + 1..].to_vec(),
        })
    }

    /// The knots before the last copy of the first break.
    pub fn left(&self) -> &[f64] {
        &self.left
    }

    /// The knots after the first copy of the last break.
    pub fn right(&self) -> &[f64] {
        &self.right
    }
}

/// Checks one side, written as a left side (the right side is passed mirrored: reversed
/// and negated, so that the same rules apply).
fn check_side(k: &[f64], p: usize, a: f64, name: &'static str, mirrored: bool) -> Result<()> {
    let bad = |value: f64, why: &'static str| Error::BadParameter {
        name,
        value: if mirrored { -value } else { value },
        why,
    };
    if k.len() < p {
        return Err(Error::BadParameter {
            name,
            value: k.len() as f64,
            why: "needs at least `degree` knots (this value is the count given)",
        });
    }
    if let Some(x) = k.iter().find(|x| !x.is_finite()) {
        return Err(bad(*x, "a knot is not finite"));
    }
    if let Some(w) = k.windows(2).find(|w| w[1] < w[0]) {
        return Err(bad(
            if mirrored { w[0] } else { w[1] },
            "the knots must be non-decreasing",
        ));
    }
    if let Some(x) = k.iter().find(|x| **x > a) {
        return Err(bad(
            *x,
            "a knot lies inside the domain of the pieces (beyond the first / last break)",
        ));
    }
    if let Some(x) = k[p..].iter().find(|x| **x != a) {
        return Err(bad(
            *x,
            "the domain would not start (end) at the first (last) break: the knots past the \
             first `degree` must equal the break",
        ));
    }
    let copies = k.iter().rev().take_while(|x| **x == a).count();
    if copies > p {
        return Err(bad(a, "the break would have multiplicity above degree + 1"));
    }
    Ok(())
}
