//! Measured (sampled) error between two curves with the same parametrisation.

use cagd_core::{BezierCurve, Error, Result};

/// Number of uniform samples (SPEC-reduce §0: "sampled = maximum over a dense grid, 4001
/// points").
pub const SAMPLES: usize = 4001;

/// `max_t ||p(t) - q(t)||` (Euclidean) estimated from below: the maximum over
/// [`SAMPLES`] uniform parameters, refined by golden-section search around the largest
/// samples. Rational curves are compared in Euclidean space.
///
/// Being a maximum over evaluated points it never exceeds the true maximum by more than
/// the evaluation rounding (a few ulp of the curve size), so a certified bound must be at
/// least this value.
///
/// # Errors
/// [`Error::LengthMismatch`] when the dimensions differ.
pub fn max_deviation(p: &BezierCurve, q: &BezierCurve) -> Result<f64> {
    if p.dim() != q.dim() {
        return Err(Error::LengthMismatch {
            what: "curve dimensions",
            got: q.dim(),
            expected: p.dim(),
        });
    }
    let dist = |t: f64| {
        let (a, b) = (p.eval(t), q.eval(t));
        a.iter()
            .zip(&b)
            .map(|(x, y)| (x - y) * (x - y))
            .sum::<f64>()
            .sqrt()
    };
    let h = 1.0 / (SAMPLES - 1) as f64;
    let vals: Vec<f64> = (0..SAMPLES).map(|i| dist(i as f64 * h)).collect();
    let mut best = vals.iter().copied().fold(0.0, f64::max);
    // Refine the five largest local maxima.
    let mut peaks: Vec<usize> = (0..SAMPLES)
        .filter(|&i| {
            (i == 0 || vals[i] >= vals[i - 1]) && (i + 1 == SAMPLES || vals[i] >= vals[i + 1])
        })
        .collect();
    peaks.sort_by(|&a, &b| vals[b].total_cmp(&vals[a]));
    for &i in peaks.iter().take(5) {
        let (mut a, mut b) = ((i as f64 - 1.0) * h, (i as f64 + 1.0) * h);
        a = a.max(0.0);
        b = b.min(1.0);
        let g = (5f64.sqrt() - 1.0) / 2.0;
        for _ in 0..40 {
            let c = b - g * (b - a);
            let d = a + g * (b - a);
            if dist(c) > dist(d) {
                b = d;
            } else {
                a = c;
            }
        }
        best = best.max(dist(0.5 * (a + b)));
    }
    Ok(best)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn distance_of_a_line_to_a_parabola() {
        // p(t) = 2t(1-t) (degree 2, points 0, 1, 0), q = 0: max 1/2 at t = 1/2.
        let p = BezierCurve::new(vec![0.0, 1.0, 0.0], 1).unwrap();
        let q = BezierCurve::new(vec![0.0, 0.0], 1).unwrap();
        assert!((max_deviation(&p, &q).unwrap() - 0.5).abs() < 1e-15);
        let q2 = BezierCurve::new(vec![0.0, 0.0, 0.0, 0.0], 2).unwrap();
        assert!(max_deviation(&p, &q2).is_err());
    }
}
