//! The non-zero B-spline basis functions on one knot span, by the triangular Cox–de Boor
//! recursion (Piegl & Tiller, "The NURBS Book", §2.5, algorithm A2.2; written anew).

/// Writes `N_{s-p,p}(t), ..., N_{s,p}(t)` — the `p + 1` basis functions of degree `p`
/// that do not vanish on the span `[u_s, u_{s+1})` — to `out[..=p]`.
///
/// Requires `p <= s`, `s + p + 1 <= u.len()` and `u_s < u_{s+1}` (a non-empty span, e.g.
/// from [`crate::find_span`]); `t` should lie in the span (outside it the polynomial pieces
/// are extrapolated). Every step divides by a knot difference `>= u_{s+1} - u_s > 0` and,
/// for `t` in the span, combines non-negative terms, so the values are non-negative and sum
/// to 1 up to a few ulp. `scratch` needs `2 (p + 1)` doubles.
///
/// ```
/// let u = [0.0, 0.0, 0.0, 1.0, 2.0, 2.0, 2.0];
/// let (mut n, mut scratch) = ([0.0; 3], [0.0; 6]);
/// cagd_core::basis_functions(&u, 3, 2, 1.5, &mut n, &mut scratch);
/// assert_eq!(n, [0.125, 0.625, 0.25]);
/// ```
pub fn basis_functions(
    u: &[f64],
    s: usize,
    p: usize,
    t: f64,
    out: &mut [f64],
    scratch: &mut [f64],
) {
    let (left, right) = scratch.split_at_mut(p + 1);
    out[0] = 1.0;
    for j in 1..=p {
        left[j] = t - u[s + 1 - j];
        right[j] = u[s + j] - t;
        let mut saved = 0.0;
        for r in 0..j {
            let temp = out[r] / (right[r + 1] + left[j - r]);
            out[r] = saved + right[r + 1] * temp;
            saved = left[j - r] * temp;
        }
        out[j] = saved;
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{BSplineCurve, find_span};

    /// The basis functions reproduce the spline: `sum_i N_i(t) P_i` equals de Boor.
    #[test]
    fn reproduces_de_boor() {
        let u = vec![0.0, 0.0, 0.0, 0.0, 0.3, 0.3, 0.7, 1.0, 1.0, 1.0, 1.0];
        let pts: Vec<f64> = (0..7).map(|i| f64::from(i * i % 5) - 1.5).collect();
        let c = BSplineCurve::new(3, u.clone(), pts.clone(), 1).unwrap();
        let (mut n, mut scratch) = ([0.0; 4], [0.0; 8]);
        for k in 0..=50 {
            let t = f64::from(k) / 50.0;
            let s = find_span(&u, 3, 7, t);
            basis_functions(&u, s, 3, t, &mut n, &mut scratch);
            let sum: f64 = n.iter().sum();
            assert!(
                (sum - 1.0).abs() < 1e-15,
                "partition of unity at {t}: {sum}"
            );
            assert!(n.iter().all(|x| *x >= 0.0));
            let v: f64 = n.iter().zip(&pts[s - 3..=s]).map(|(a, b)| a * b).sum();
            let w = c.eval(t).unwrap()[0];
            assert!((v - w).abs() < 1e-14, "{t}: {v} vs {w}");
        }
    }
}
