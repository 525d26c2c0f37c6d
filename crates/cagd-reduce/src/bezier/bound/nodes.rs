//! The largest norm of the error curve's node values `V c` (goes beyond the seed; see
//! `operator/error_map.rs`): fused for one curve (no buffer), or over a computed block of
//! values (the batch: `lanes.rs`). A NaN value makes the result NaN (never silently skipped), which the bound
//! turns into `+inf`.

/// `max_j ||sum_k v_jk c_k||` for `v` row-major with `r` columns and `c` = `r` points of
/// `dim` coordinates; `0` when `r = 0`.
pub(crate) fn max_value_norm(v: &[f64], r: usize, c: &[f64], dim: usize) -> f64 {
    if r == 0 {
        return 0.0;
    }
    match dim {
        1 => fused::<1>(v, r, c),
        2 => fused::<2>(v, r, c),
        3 => fused::<3>(v, r, c),
        4 => fused::<4>(v, r, c),
        _ => {
            let mut acc = vec![0.0; dim];
            let (mut best, mut bad) = (0.0f64, false);
            for row in v.chunks_exact(r) {
                acc.fill(0.0);
                for (x, ck) in row.iter().zip(c.chunks_exact(dim)) {
                    acc.iter_mut().zip(ck).for_each(|(a, y)| *a += x * y);
                }
                let s: f64 = acc.iter().map(|a| a * a).sum();
                bad |= s.is_nan();
                best = best.max(s);
            }
            if bad { f64::NAN } else { best.sqrt() }
        }
    }
}

fn fused<const D: usize>(v: &[f64], r: usize, c: &[f64]) -> f64 {
    let (mut best, mut bad) = (0.0f64, false);
    for row in v.chunks_exact(r) {
        let mut acc = [0.0f64; D];
        for (x, ck) in row.iter().zip(c.chunks_exact(D)) {
            for k in 0..D {
                acc[k] += x * ck[k];
            }
        }
        let s: f64 = acc.iter().map(|a| a * a).sum();
        bad |= s.is_nan();
        best = best.max(s);
    }
    if bad { f64::NAN } else { best.sqrt() }
}

/// `max_j ||s_j||` over the points of `s` (`dim` coordinates each); NaN if any is NaN (the
/// test oracle of [`max_value_norm`]; the batch takes the maxima in the lanes kernel).
#[cfg(test)]
fn max_row_norm(s: &[f64], dim: usize) -> f64 {
    let (mut best, mut bad) = (0.0f64, false);
    for p in s.chunks_exact(dim) {
        let q: f64 = p.iter().map(|a| a * a).sum();
        bad |= q.is_nan();
        best = best.max(q);
    }
    if bad { f64::NAN } else { best.sqrt() }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fused_equals_the_definition_and_keeps_nan() {
        for dim in 1..=6 {
            let (rows, r) = (7, 3);
            let v: Vec<f64> = (0..rows * r).map(|i| (i % 5) as f64 - 2.0).collect();
            let c: Vec<f64> = (0..r * dim).map(|i| (i % 7) as f64 * 0.25 - 0.5).collect();
            let mut s = vec![0.0; rows * dim];
            for j in 0..rows {
                for k in 0..r {
                    for d in 0..dim {
                        s[j * dim + d] += v[j * r + k] * c[k * dim + d];
                    }
                }
            }
            assert_eq!(max_value_norm(&v, r, &c, dim), max_row_norm(&s, dim));
            let mut bad = c.clone();
            bad[dim] = f64::NAN;
            assert!(max_value_norm(&v, r, &bad, dim).is_nan(), "dim {dim}");
            s[dim] = f64::NAN;
            assert!(max_row_norm(&s, dim).is_nan());
        }
        assert_eq!(max_value_norm(&[], 0, &[], 3), 0.0);
    }
}
