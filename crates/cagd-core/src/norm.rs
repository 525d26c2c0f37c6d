//! The Euclidean norm of a point without overflow or underflow of its squares (goes beyond
//! the seeds: coordinates up to the largest double are valid input, and `sum x^2` overflows
//! from `|x| ~ 1.3e154` on, which once turned a finite rounding bound into `+inf`).

/// `sqrt(sum x_k^2)`, computed as `s sqrt(sum (x_k / s)^2)` with `s = max |x_k|` when the
/// plain sum could overflow or lose its value to underflow (`s` outside `[1e-150, 1e150]`),
/// so the result is finite for every finite point (within `(dim + 2) eps` relative). NaN
/// for a point with a NaN coordinate, `+inf` for one with an infinite coordinate.
pub fn point_norm(x: &[f64]) -> f64 {
    let s = x.iter().fold(0.0f64, |m, v| m.max(v.abs()));
    if x.iter().any(|v| v.is_nan()) {
        return f64::NAN;
    }
    if s == 0.0 || s.is_infinite() {
        return s;
    }
    if (1e-150..=1e150).contains(&s) {
        return x.iter().map(|v| v * v).sum::<f64>().sqrt();
    }
    s * x.iter().map(|v| (v / s) * (v / s)).sum::<f64>().sqrt()
}

/// The largest [`point_norm`] over the points of `points` (`dim` coordinates each); `0`
/// for no points.
pub fn max_point_norm(points: &[f64], dim: usize) -> f64 {
    points
        .chunks_exact(dim.max(1))
        .map(point_norm)
        .fold(0.0, f64::max)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn finite_for_every_finite_point() {
        assert_eq!(point_norm(&[3.0, 4.0]), 5.0);
        assert_eq!(point_norm(&[]), 0.0);
        let big = point_norm(&[3e300, 4e300]);
        assert!((big - 5e300).abs() <= 4.0 * f64::EPSILON * 5e300, "{big:e}");
        let tiny = point_norm(&[3e-310, 4e-310]);
        assert!((tiny - 5e-310).abs() <= 1e-5 * 5e-310, "{tiny:e}");
        let top = point_norm(&[f64::MAX, f64::MAX]);
        assert!(
            top.is_infinite(),
            "the true norm is above f64::MAX: {top:e}"
        );
        assert!(point_norm(&[1.0, f64::NAN]).is_nan());
        assert_eq!(point_norm(&[1.0, f64::NEG_INFINITY]), f64::INFINITY);
        assert_eq!(max_point_norm(&[3.0, 4.0, 1e300, 0.0], 2), 1e300);
    }
}
