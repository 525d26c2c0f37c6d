//! The continuity decision at one joint of the reverse general route: the smallest
//! multiplicity of the joint's knot for which two consecutive Bézier pieces are one spline
//! within the tolerance (Tiller's knot removal, Piegl & Tiller A5.8, on the two-piece
//! spline; seed 001 §4.1's merge gives the multiplicity-`p` start).
//!
//! The two-piece spline has knots `b0^(p+1), b1^p, b2^(p+1)` and points `L_0..L_{p-1}`,
//! the joint `J = (L_p + R_0) / 2`, `R_1..R_p`. Removing one copy of `b1` (multiplicity
//! `s`, last index `r = p + s`) solves the knot-insertion equations
//! `P_i = a Q_i + (1-a) Q_{i-1}`, `i = s..=p`, with `a = (b1 - b0)/(b2 - b0)` (the same for
//! every equation on this knot vector), `Q_{s-1} = P_{s-1}`, `Q_p = P_{p+1}`. With
//! `a >= 1/2` the equations are solved from the left (dividing by `a`) and the last one is
//! left over, else from the right (dividing by `1 - a`) and the first is left over, as
//! Tiller's removal does where `a_i` crosses 1/2; the Euclidean residual of the leftover
//! equation certifies the removal (partition of unity: it bounds the change of the curve).
//! Copies are removed while the summed residuals stay within the joint's budget.
//!
//! Only the points left of the joint change: after removals down to multiplicity `s`, the
//! logical point `P_j` is `cur[j]` for `j < p` and `R_{j-s}` for `j > s`, `j >= p` (`J`
//! while `s = p`), so the right piece is read in place and nothing but the left piece's
//! first `p` points is copied.

use super::width::{Width, dist2, residual2, unblend, unblend_in};

/// Scratch of [`joint_multiplicity`], sized once for a degree and point width.
pub(crate) struct JointScratch {
    cur: Vec<f64>,
    joint: Vec<f64>,
    carry: Vec<f64>,
    next: Vec<f64>,
}

impl JointScratch {
    /// Scratch for degree `p` and `pdim` working coordinates per point.
    pub(crate) fn new(p: usize, pdim: usize) -> Self {
        Self {
            cur: vec![0.0; p.max(1) * pdim],
            joint: vec![0.0; pdim],
            carry: vec![0.0; pdim],
            next: vec![0.0; pdim],
        }
    }
}

/// The multiplicity kept at the joint between the pieces `l` and `r` (`p + 1` working
/// points each): `p + 1` when their end points are farther apart than `tol` (or `p = 0`),
/// else the smallest `s >= 1` reached by removing copies while the summed residual stays
/// within `tol - gap / 2` (`gap`: the distance of the end points, half of which the
/// averaged joint point already moved each piece). `a = (b1 - b0) / (b2 - b0)`.
pub(crate) fn joint_multiplicity<W: Width>(
    l: &[f64],
    r: &[f64],
    p: usize,
    a: f64,
    tol: f64,
    w: W,
    sc: &mut JointScratch,
) -> usize {
    let d = w.get();
    let (lp, r0) = (&l[p * d..(p + 1) * d], &r[..d]);
    let gap = dist2(w, lp, r0).sqrt();
    if p == 0 || gap.is_nan() || gap > tol {
        return p + 1;
    }
    for ((j, x), y) in sc.joint[..d].iter_mut().zip(lp).zip(r0) {
        *j = 0.5 * (x + y);
    }
    sc.cur[..p * d].copy_from_slice(&l[..p * d]);
    let mut budget = tol - 0.5 * gap;
    let b = 1.0 - a;
    let from_left = a >= 0.5;
    let inv = if from_left { 1.0 / a } else { 1.0 / b };
    let cur = &mut sc.cur[..p * d];
    let mut s = p;
    while s > 1 {
        // P_p and P_{p+1} = Q_p of this removal.
        let pp: &[f64] = if s == p {
            &sc.joint[..d]
        } else {
            &r[(p - s) * d..(p - s + 1) * d]
        };
        let pp1 = &r[(p + 1 - s) * d..(p + 2 - s) * d];
        let eps2;
        if from_left {
            // Q_i = (P_i - b Q_{i-1}) / a, i = s..p, in place (cur[s - 1] = Q_{s-1}); the
            // leftover equation is i = p: P_p - a Q_p - b Q_{p-1}.
            for i in s..p {
                let (lo, hi) = cur[(i - 1) * d..(i + 1) * d].split_at_mut(d);
                unblend_in(w, hi, lo, b, inv);
            }
            eps2 = residual2(w, pp, pp1, &cur[(p - 1) * d..], a, b);
        } else {
            // Q_{i-1} = (P_i - a Q_i) / (1 - a), i = p..=s+1 (Q_p = P_{p+1}); the
            // leftover equation is i = s: P_s - a Q_s - b Q_{s-1}. Q_i goes to cur[i]
            // once P_i has been read.
            sc.carry[..d].copy_from_slice(pp1);
            for i in (s + 1..p + 1).rev() {
                let pi: &[f64] = if i == p { pp } else { &cur[i * d..(i + 1) * d] };
                unblend(w, &mut sc.next, pi, &sc.carry, a, inv);
                if i < p {
                    cur[i * d..(i + 1) * d].copy_from_slice(&sc.carry[..d]);
                }
                std::mem::swap(&mut sc.carry, &mut sc.next);
            }
            let ps: &[f64] = if s == p { pp } else { &cur[s * d..(s + 1) * d] };
            eps2 = residual2(w, ps, &sc.carry, &cur[(s - 1) * d..], a, b);
            if s < p {
                cur[s * d..(s + 1) * d].copy_from_slice(&sc.carry[..d]);
            }
        }
        let eps = f64::sqrt(eps2);
        if eps.is_nan() || eps > budget {
            break;
        }
        budget -= eps;
        s -= 1;
    }
    s
}
