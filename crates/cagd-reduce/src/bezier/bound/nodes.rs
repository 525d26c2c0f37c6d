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

/// The symmetric split's [`max_value_norm`] (see `operator/error_map.rs`): `max_j
/// max(||e_j + o_j||, ||e_j - o_j||)` with `e_j = sum_k ve_jk ce_k` (`ve` row-major with
/// `ce.len() / dim` columns) and `o_j` alike; either part may be empty (zero).
pub(crate) fn max_pair_norm(
    (ve, ce): (&[f64], &[f64]),
    (vo, co): (&[f64], &[f64]),
    dim: usize,
) -> f64 {
    match dim {
        1 => pair_fused::<1>((ve, ce), (vo, co)),
        2 => pair_fused::<2>((ve, ce), (vo, co)),
        3 => pair_fused::<3>((ve, ce), (vo, co)),
        4 => pair_fused::<4>((ve, ce), (vo, co)),
        _ => {
            let (re, ro) = (ce.len() / dim, co.len() / dim);
            let rows = ve.len().checked_div(re).unwrap_or(vo.len() / ro.max(1));
            let (mut e, mut o) = (vec![0.0; dim], vec![0.0; dim]);
            let (mut best, mut bad) = (0.0f64, false);
            for j in 0..rows {
                part_value(ve, re, j, ce, &mut e);
                part_value(vo, ro, j, co, &mut o);
                let (mut sp, mut sm) = (0.0, 0.0);
                for (x, y) in e.iter().zip(&o) {
                    sp += (x + y) * (x + y);
                    sm += (x - y) * (x - y);
                }
                bad |= sp.is_nan() || sm.is_nan();
                best = best.max(sp).max(sm);
            }
            if bad { f64::NAN } else { best.sqrt() }
        }
    }
}

/// `out = sum_k v_jk c_k` over the `r` columns of row `j` of `v` (zero for `r = 0`).
fn part_value(v: &[f64], r: usize, j: usize, c: &[f64], out: &mut [f64]) {
    out.fill(0.0);
    if r == 0 {
        return;
    }
    let dim = out.len();
    for (x, ck) in v[j * r..(j + 1) * r].iter().zip(c.chunks_exact(dim)) {
        out.iter_mut().zip(ck).for_each(|(a, y)| *a += x * y);
    }
}

fn pair_fused<const D: usize>((ve, ce): (&[f64], &[f64]), (vo, co): (&[f64], &[f64])) -> f64 {
    let (re, ro) = (ce.len() / D, co.len() / D);
    let rows = ve.len().checked_div(re).unwrap_or(vo.len() / ro.max(1));
    let (mut best, mut bad) = (0.0f64, false);
    for j in 0..rows {
        let (mut e, mut o) = ([0.0f64; D], [0.0f64; D]);
        if re > 0 {
            for (x, ck) in ve[j * re..(j + 1) * re].iter().zip(ce.chunks_exact(D)) {
                for k in 0..D {
                    e[k] += x * ck[k];
                }
            }
        }
        if ro > 0 {
            for (x, ck) in vo[j * ro..(j + 1) * ro].iter().zip(co.chunks_exact(D)) {
                for k in 0..D {
                    o[k] += x * ck[k];
                }
            }
        }
        let (mut sp, mut sm) = (0.0, 0.0);
        for k in 0..D {
            sp += (e[k] + o[k]) * (e[k] + o[k]);
            sm += (e[k] - o[k]) * (e[k] - o[k]);
        }
        bad |= sp.is_nan() || sm.is_nan();
        best = best.max(sp).max(sm);
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

    /// The pair norm is the norm over the rows of `[ve vo]` and `[ve -vo]` applied to
    /// `[ce; co]`, for every split of the columns (empty parts included), and keeps NaN.
    #[test]
    fn pair_norm_equals_the_mirrored_definition() {
        for dim in 1..=6 {
            let (rows, r) = (5, 4);
            let v: Vec<f64> = (0..rows * r).map(|i| ((i * 7) % 11) as f64 - 5.0).collect();
            let c: Vec<f64> = (0..r * dim).map(|i| (i % 7) as f64 * 0.25 - 0.7).collect();
            for re in 0..=r {
                let cols = |range: std::ops::Range<usize>| -> Vec<f64> {
                    (0..rows)
                        .flat_map(|j| v[j * r..(j + 1) * r][range.clone()].to_vec())
                        .collect()
                };
                let (ve, vo) = (cols(0..re), cols(re..r));
                let mirrored: Vec<f64> = (0..2 * rows)
                    .flat_map(|j| {
                        let row = &v[(j % rows) * r..(j % rows + 1) * r];
                        row.iter()
                            .enumerate()
                            .map(move |(k, x)| if j >= rows && k >= re { -x } else { *x })
                            .collect::<Vec<_>>()
                    })
                    .collect();
                let (ce, co) = c.split_at(re * dim);
                let got = max_pair_norm((&ve, ce), (&vo, co), dim);
                let want = max_value_norm(&mirrored, r, &c, dim);
                assert!(
                    (got - want).abs() <= 1e-14 * want,
                    "dim {dim} re {re}: {got} {want}"
                );
                let mut bad = c.clone();
                bad[r * dim - 1] = f64::NAN;
                let (be, bo) = bad.split_at(re * dim);
                assert!(max_pair_norm((&ve, be), (&vo, bo), dim).is_nan());
            }
        }
    }
}
