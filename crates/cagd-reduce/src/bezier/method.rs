//! The reduction methods and their preconditions.

use cagd_core::{Error, MAX_DEGREE, Result};

/// A degree-reduction method for Bézier curves. Every variant is linear in the control
/// points (an `(m+1) x (n+1)` [`crate::Operator`]); the G1 method with *optimal* `l1, l2`
/// is not, and is the plain function [`crate::reduce_g1_optimal`].
///
/// "One-degree" methods reduce `k -> k-1`; asked for `m < n - 1` they are applied stepwise
/// `n -> n-1 -> ... -> m` (the operator is the exact product of the steps).
///
/// `r` and `p` are the highest derivative orders interpolated at `t = 0` and `t = 1`;
/// `-1` means no constraint at that end.
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub enum Method {
    /// Forrest's one-degree reduction (seed 000 chapter introduction; SPEC-reduce §3):
    /// forward recursion `P^I` for the first half, backward `P^II` for the second, their mean
    /// in the middle. Interpolates derivatives up to order `floor((m-1)/2)` at both ends.
    Forrest,
    /// Piegl–Tiller one-degree reduction: the special case `m = n-1`,
    /// `r = p = floor((m-1)/2)` of seed 000 §14.5 (SPEC-reduce §7). Identical to
    /// [`Method::Forrest`] (computed by its own formula; a test checks equality).
    PieglTiller,
    /// Farin's one-degree reduction `Pbar_i = ((n-i) P^I_i + i P^II_i) / n` (SPEC-reduce §3).
    /// Interpolates the end points. Needs `m >= 1`.
    Farin,
    /// Control-point perturbation with fixed ends, one degree (seed 000 §14.2.1,
    /// eqs. 14.2.3 / 14.2.5): minimises `sum ||eps_i||^2` (not the curve error). Certified
    /// bound `W_n ||F|| / (C(2n,n) - 2)` (SPEC-reduce §2.1 erratum). Needs `m >= 1`.
    Perturb,
    /// Perturbation with G1 end constraints and *given* `l1, l2` (seed 000 §14.2.3,
    /// eq. 14.2.12; SPEC-reduce §2.3), one degree: `eps_1 = l1 (P_1 - P_0)`,
    /// `eps_{n-1} = l2 (P_{n-1} - P_n)`. `l1 = l2 = 0` gives C1 ends. Needs `m >= 3`, finite
    /// `l1, l2` with `1 + l1 > 0`, `1 + l2 > 0`.
    PerturbG1 {
        /// Tangent scale at `t = 0`.
        l1: f64,
        /// Tangent scale at `t = 1`.
        l2: f64,
    },
    /// Eck's one-degree reduction = Chebyshev economisation with the closed-form
    /// `lambda_i = 2^(-2n-1) sum_{j<=i} C(2n+2, 2j)` (SPEC-reduce §3). Best uniform
    /// approximation for one degree; ends not interpolated.
    Eck,
    /// Watkins–Worsey: convert to the Chebyshev basis, drop the terms above degree `m`,
    /// convert back (multi-degree directly). Equals [`Method::Eck`] for one degree and
    /// [`Method::BogackiWeinsteinXu`] in general.
    WatkinsWorsey,
    /// Bogacki–Weinstein–Xu multi-degree reduction = seed 000 §14.5 with `r = p = -1`
    /// (SPEC-reduce §3): near-best uniform approximation, ends not interpolated.
    BogackiWeinsteinXu,
    /// Generalized-inverse reduction without constraints (seed 000 §14.4.1, eqs.
    /// 14.4.5 / 14.4.6): least squares on the control points of the elevated curve, which
    /// equals the continuous L2-best approximation (SPEC-reduce §6).
    GeneralizedInverse,
    /// Generalized-inverse reduction with the end points interpolated (seed 000 §14.4.2,
    /// eqs. 14.4.8–14.4.15). Needs `m >= 1`. Not the end-constrained L2-best.
    GeneralizedInverseEnds,
    /// Multi-degree reduction with `(r, p)`-order end interpolation by constrained
    /// Chebyshev approximation (seed 000 §14.5, Theorem 14.5.2 with SPEC-reduce §7
    /// corrections). Needs `r, p >= -1` and `r + p + 1 <= m`; `m = r + p + 1` is the
    /// two-point Hermite interpolation of Corollary 14.5.2, `r = p = -1` is Chebyshev
    /// truncation.
    ConstrainedChebyshev {
        /// Highest derivative order kept at `t = 0` (`-1`: none).
        r: i32,
        /// Highest derivative order kept at `t = 1` (`-1`: none).
        p: i32,
    },
    /// L2-optimal multi-degree reduction with `C^(r,p)` end constraints (beyond the seed):
    /// minimises `∫_0^1 ||P(t) - Q(t)||^2 dt` subject to derivatives `0..=r` at `t = 0` and
    /// `0..=p` at `t = 1` being equal. Ends by eq. 14.5.10, interior by the exact Gram
    /// system `G_ij = C(m,i) C(m,j) / ((2m+1) C(2m,i+j))`. Needs `r + p + 1 <= m`.
    L2 {
        /// Highest derivative order kept at `t = 0` (`-1`: none).
        r: i32,
        /// Highest derivative order kept at `t = 1` (`-1`: none).
        p: i32,
    },
}

impl Method {
    /// A short stable name (used in reports and by the C ABI / CLI).
    pub fn name(&self) -> &'static str {
        match self {
            Method::Forrest => "forrest",
            Method::PieglTiller => "piegl-tiller",
            Method::Farin => "farin",
            Method::Perturb => "perturb",
            Method::PerturbG1 { .. } => "perturb-g1",
            Method::Eck => "eck",
            Method::WatkinsWorsey => "watkins-worsey",
            Method::BogackiWeinsteinXu => "bogacki-weinstein-xu",
            Method::GeneralizedInverse => "generalized-inverse",
            Method::GeneralizedInverseEnds => "generalized-inverse-ends",
            Method::ConstrainedChebyshev { .. } => "constrained-chebyshev",
            Method::L2 { .. } => "l2",
        }
    }

    /// Whether the method reduces one degree per step (and is applied stepwise).
    pub fn is_one_degree(&self) -> bool {
        matches!(
            self,
            Method::Forrest
                | Method::PieglTiller
                | Method::Farin
                | Method::Perturb
                | Method::PerturbG1 { .. }
                | Method::Eck
        )
    }

    /// The derivative orders `(r, p)` the method interpolates at `t = 0` and `t = 1` when
    /// reducing to degree `m` (`-1`: none). For [`Method::PerturbG1`] with non-zero `l1` or
    /// `l2` only the tangent direction (G1) is kept beyond order 0.
    pub fn end_orders(&self, m: usize) -> (i32, i32) {
        match *self {
            Method::Forrest | Method::PieglTiller => {
                let o = (i32::try_from(m).unwrap_or(i32::MAX) - 1).div_euclid(2);
                (o, o)
            }
            Method::Farin | Method::Perturb | Method::GeneralizedInverseEnds => (0, 0),
            Method::PerturbG1 { l1, l2 } => {
                (if l1 == 0.0 { 1 } else { 0 }, if l2 == 0.0 { 1 } else { 0 })
            }
            Method::Eck
            | Method::WatkinsWorsey
            | Method::BogackiWeinsteinXu
            | Method::GeneralizedInverse => (-1, -1),
            Method::ConstrainedChebyshev { r, p } | Method::L2 { r, p } => (r, p),
        }
    }

    /// Checks that the method can reduce degree `n` to degree `m`.
    ///
    /// # Errors
    /// [`Error::DegreeOutOfRange`] (`n > 64`), [`Error::BadDegreePair`] (`m >= n`, or `m`
    /// below the method's minimum), [`Error::TooManyConstraints`] (`r + p + 1 > m`, or
    /// `r, p < -1`), [`Error::BadParameter`] (non-finite or non-G1 `l1, l2`).
    pub fn check(&self, n: usize, m: usize) -> Result<()> {
        cagd_core::check_degree(n)?;
        if m >= n {
            return Err(Error::BadDegreePair {
                from: n,
                to: m,
                why: "the target degree must be below the source degree",
            });
        }
        let min_m = match self {
            Method::Farin | Method::Perturb | Method::GeneralizedInverseEnds => 1,
            Method::PerturbG1 { .. } => 3,
            _ => 0,
        };
        if m < min_m {
            return Err(Error::BadDegreePair {
                from: n,
                to: m,
                why: match min_m {
                    1 => "this method fixes both end points and needs a target degree >= 1",
                    _ => "the G1 perturbation needs a target degree >= 3 (source >= 4)",
                },
            });
        }
        if let Method::PerturbG1 { l1, l2 } = *self {
            for (name, l) in [("l1", l1), ("l2", l2)] {
                if !l.is_finite() || 1.0 + l <= 0.0 {
                    return Err(Error::BadParameter {
                        name,
                        value: l,
                        why: "must be finite with 1 + l > 0 (G1 keeps the tangent direction)",
                    });
                }
            }
        }
        if let Method::ConstrainedChebyshev { r, p } | Method::L2 { r, p } = *self {
            let too_many = |why| Error::TooManyConstraints {
                r: i64::from(r),
                p: i64::from(p),
                m,
                why,
            };
            if r < -1 || p < -1 {
                return Err(too_many("r and p must be >= -1"));
            }
            if i64::from(r) + i64::from(p) + 1 > i64::try_from(m).unwrap_or(i64::MAX) {
                return Err(too_many("needs r + p + 1 <= m"));
            }
        }
        debug_assert!(n <= MAX_DEGREE);
        Ok(())
    }

    /// A hashable key for the operator cache (the `f64` parameters by their bits).
    pub(crate) fn key(&self) -> (u8, u64, u64) {
        let rp = |r: i32, p: i32| (r as u32 as u64, p as u32 as u64);
        match *self {
            Method::Forrest => (0, 0, 0),
            Method::PieglTiller => (1, 0, 0),
            Method::Farin => (2, 0, 0),
            Method::Perturb => (3, 0, 0),
            Method::PerturbG1 { l1, l2 } => (4, l1.to_bits(), l2.to_bits()),
            Method::Eck => (5, 0, 0),
            Method::WatkinsWorsey => (6, 0, 0),
            Method::BogackiWeinsteinXu => (7, 0, 0),
            Method::GeneralizedInverse => (8, 0, 0),
            Method::GeneralizedInverseEnds => (9, 0, 0),
            Method::ConstrainedChebyshev { r, p } => {
                let (a, b) = rp(r, p);
                (10, a, b)
            }
            Method::L2 { r, p } => {
                let (a, b) = rp(r, p);
                (11, a, b)
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn preconditions() {
        assert!(Method::Eck.check(5, 4).is_ok());
        assert!(matches!(
            Method::Eck.check(5, 5),
            Err(Error::BadDegreePair { .. })
        ));
        assert!(matches!(
            Method::Eck.check(65, 4),
            Err(Error::DegreeOutOfRange { .. })
        ));
        assert!(matches!(
            Method::ConstrainedChebyshev { r: 2, p: 2 }.check(10, 4),
            Err(Error::TooManyConstraints { .. })
        ));
        assert!(
            Method::ConstrainedChebyshev { r: 2, p: 2 }
                .check(10, 6)
                .is_ok()
        );
        // m = r + p + 1: the Hermite case of Corollary 14.5.2.
        assert!(
            Method::ConstrainedChebyshev { r: 2, p: 2 }
                .check(10, 5)
                .is_ok()
        );
        assert!(Method::L2 { r: -2, p: 0 }.check(10, 6).is_err());
        assert!(Method::Perturb.check(2, 0).is_err());
        assert!(
            Method::PerturbG1 {
                l1: f64::NAN,
                l2: 0.0
            }
            .check(6, 5)
            .is_err()
        );
        assert!(Method::PerturbG1 { l1: -1.0, l2: 0.0 }.check(6, 5).is_err());
        assert_eq!(Method::Forrest.end_orders(0), (-1, -1));
        assert_eq!(Method::Forrest.end_orders(5), (2, 2));
    }
}
