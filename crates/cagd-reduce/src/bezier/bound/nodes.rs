//! The largest norm of the error curve's node values `V c` (goes beyond the seed; see
//! `operator/error_map.rs`) for one curve: node by node with the point in registers for
//! small maps, node-major in a per-thread scratch from [`BY_NODES_MIN`] entries (the
//! symmetric split's two parts, or the full map as an even part alone), both with the
//! same sums in the same order; the batch computes its own in `lanes.rs`. A NaN value makes the result NaN (never silently skipped), which the bound
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

/// Fewest entries of the node maps (`rows r`, multiply-adds per coordinate) for which
/// [`max_pair_norm_t`] is used; below, [`max_pair_norm`] (measured with callgrind:
/// at (4,3) and (5,4), 9-11 entries, the node-major loops cost 160-300 instructions more
/// per curve; from (10,5) fast, 65 entries, they cost less).
pub(crate) const BY_NODES_MIN: usize = 48;

/// The symmetric split's largest node value norm for one curve (the per-curve bound; the
/// batch takes its maxima in the lanes kernel): `max_j max(||e_j + o_j||, ||e_j - o_j||)`
/// with `e_j = sum_k ve_jk ce_k` and `o_j` alike (see `operator/error_map.rs`), the node
/// maps given transposed (`vet` = `V_e^T`, row-major `r_e x rows`: one even basis curve's
/// values at every node, contiguous; `vot` alike; either part may be empty). Every node
/// value is summed over `k` in increasing order (multiply, then add) and every squared
/// norm over `d` in increasing order, as in the point-major oracle `max_pair_norm`, so
/// the result is the same bits (tested); only the loop nest is turned so that the
/// innermost loops run over the nodes (vectorised, AVX2 when the CPU has it): at (30,15)
/// tight the per-curve call went from 33.7 k to 22.8 k instructions (benches README).
pub(crate) fn max_pair_norm_t(
    (vet, ce): (&[f64], &[f64]),
    (vot, co): (&[f64], &[f64]),
    rows: usize,
    dim: usize,
) -> f64 {
    SCRATCH.with_borrow_mut(|scratch| {
        // Grown once; every element used is written before it is read (no zeroing).
        let need = 2 * rows * (dim + 1);
        if scratch.len() < need {
            scratch.resize(need, 0.0);
        }
        let scratch = &mut scratch[..need];
        #[cfg(target_arch = "x86_64")]
        if super::super::lanes::isa() != super::super::lanes::Isa::Portable {
            #[allow(unsafe_code, reason = "the call of a `target_feature` function")]
            // SAFETY: the CPU has AVX2 (detected by `isa`), the function's only
            // requirement; the function is itself safe code.
            return unsafe { pair_by_nodes_avx2((vet, ce), (vot, co), rows, dim, scratch) };
        }
        pair_by_nodes((vet, ce), (vot, co), rows, dim, scratch)
    })
}

thread_local! {
    /// The node values and squared norms of [`max_pair_norm_t`] (no allocation per call
    /// once grown).
    static SCRATCH: std::cell::RefCell<Vec<f64>> = const { std::cell::RefCell::new(Vec::new()) };
}

/// [`pair_by_nodes`] compiled with AVX2 (4 nodes per vector; no FMA: the same
/// multiply-then-add as the portable code).
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
fn pair_by_nodes_avx2(
    e: (&[f64], &[f64]),
    o: (&[f64], &[f64]),
    rows: usize,
    dim: usize,
    scratch: &mut [f64],
) -> f64 {
    pair_by_nodes(e, o, rows, dim, scratch)
}

/// The body of [`max_pair_norm_t`]; `scratch` holds `2 rows (dim + 1)` doubles (any
/// values: each is written before it is read).
#[inline(always)]
fn pair_by_nodes(
    (vet, ce): (&[f64], &[f64]),
    (vot, co): (&[f64], &[f64]),
    rows: usize,
    dim: usize,
    scratch: &mut [f64],
) -> f64 {
    if rows == 0 {
        return 0.0;
    }
    let (e, rest) = scratch.split_at_mut(rows * dim);
    let (o, rest) = rest.split_at_mut(rows * dim);
    let (qp, qm) = rest.split_at_mut(rows);
    part_values_t(vet, rows, ce, dim, e);
    part_values_t(vot, rows, co, dim, o);
    // qp_j = sum_d (e_jd + o_jd)^2 and qm_j = sum_d (e_jd - o_jd)^2, d increasing; the
    // first term assigned (`0 + x = x` for the square `x >= +0` or NaN: the same bits).
    for (d, (ed, od)) in e.chunks_exact(rows).zip(o.chunks_exact(rows)).enumerate() {
        let terms = qp.iter_mut().zip(qm.iter_mut()).zip(ed).zip(od);
        if d == 0 {
            for (((p, m), x), y) in terms {
                let (s, t) = (x + y, x - y);
                *p = s * s;
                *m = t * t;
            }
        } else {
            for (((p, m), x), y) in terms {
                let (s, t) = (x + y, x - y);
                *p += s * s;
                *m += t * t;
            }
        }
    }
    // Selects only (whole-vector max and NaN flag); a NaN makes the result NaN.
    let (mut best, mut bad) = (0.0f64, 0.0f64);
    for (p, m) in qp.iter().zip(qm.iter()) {
        let q = if p > m { *p } else { *m };
        best = if q > best { q } else { best };
        bad = if (p + m).is_nan() { 1.0 } else { bad };
    }
    if bad != 0.0 { f64::NAN } else { best.sqrt() }
}

/// `out[d rows + j] = sum_k vt[k rows + j] c[k dim + d]`, `k` increasing (zero for no
/// columns): the values of one part at every node, one coordinate per row of `out`. The
/// first term is assigned where the oracle adds it to `+0`: the two differ at most in
/// the sign of a zero value, which the squared norms of [`pair_by_nodes`] do not see
/// (`(±0 + y)^2` and `(±0 - y)^2` are the same bits for every `y`).
#[inline(always)]
fn part_values_t(vt: &[f64], rows: usize, c: &[f64], dim: usize, out: &mut [f64]) {
    if vt.is_empty() {
        out.fill(0.0);
        return;
    }
    for (k, (col, ck)) in vt.chunks_exact(rows).zip(c.chunks_exact(dim)).enumerate() {
        for (x, od) in ck.iter().zip(out.chunks_exact_mut(rows)) {
            if k == 0 {
                for (a, v) in od.iter_mut().zip(col) {
                    *a = v * x;
                }
            } else {
                for (a, v) in od.iter_mut().zip(col) {
                    *a += v * x;
                }
            }
        }
    }
}

/// The symmetric split's [`max_value_norm`] (see `operator/error_map.rs`): `max_j
/// max(||e_j + o_j||, ||e_j - o_j||)` with `e_j = sum_k ve_jk ce_k` (`ve` row-major with
/// `ce.len() / dim` columns) and `o_j` alike; either part may be empty (zero). Node by
/// node with the point in registers: the route for small maps (below
/// [`BY_NODES_MIN`] multiply-adds per coordinate, where [`max_pair_norm_t`]'s set-up
/// costs more than it saves), and the test oracle of [`max_pair_norm_t`].
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

    /// The node-major loops give the bits of the point-major oracle, for every split of
    /// the columns (empty parts included), dimensions 1-6, and keep NaN and infinity.
    #[test]
    fn pair_norm_by_nodes_is_the_oracle_bit_for_bit() {
        let transpose = |v: &[f64], rows: usize, cols: usize| -> Vec<f64> {
            let mut t = vec![0.0; rows * cols];
            for j in 0..rows {
                for k in 0..cols {
                    t[k * rows + j] = v[j * cols + k];
                }
            }
            t
        };
        for dim in 1..=6 {
            for (rows, r) in [(1, 1), (5, 4), (13, 7), (64, 15), (137, 32)] {
                let v: Vec<f64> = (0..rows * r).map(|i| (i as f64 * 0.731).sin()).collect();
                let c: Vec<f64> = (0..r * dim)
                    .map(|i| (i as f64 * 1.37).cos() * 1e3)
                    .collect();
                for re in 0..=r {
                    let cols = |range: std::ops::Range<usize>| -> Vec<f64> {
                        (0..rows)
                            .flat_map(|j| v[j * r..(j + 1) * r][range.clone()].to_vec())
                            .collect()
                    };
                    let (ve, vo) = (cols(0..re), cols(re..r));
                    let (vet, vot) = (transpose(&ve, rows, re), transpose(&vo, rows, r - re));
                    for bad in [None, Some(f64::NAN), Some(f64::INFINITY)] {
                        let mut c = c.clone();
                        if let Some(x) = bad {
                            c[(r - 1) * dim] = x;
                        }
                        let (ce, co) = c.split_at(re * dim);
                        let want = if rows == 0 {
                            0.0
                        } else {
                            max_pair_norm((&ve, ce), (&vo, co), dim)
                        };
                        let got = max_pair_norm_t((&vet, ce), (&vot, co), rows, dim);
                        assert_eq!(
                            got.to_bits(),
                            want.to_bits(),
                            "dim {dim} rows {rows} r {r} re {re} {bad:?}: {got} {want}"
                        );
                    }
                }
            }
        }
    }

    /// With an empty odd part the node-major loops give [`max_value_norm`]'s bits (the
    /// route of the per-curve bound for maps without the symmetric split).
    #[test]
    fn full_map_by_nodes_is_max_value_norm_bit_for_bit() {
        for dim in 1..=6 {
            for (rows, r) in [(1, 1), (7, 3), (23, 5), (127, 15), (271, 32)] {
                let v: Vec<f64> = (0..rows * r).map(|i| (i as f64 * 0.917).sin()).collect();
                let mut vt = vec![0.0; rows * r];
                for j in 0..rows {
                    for k in 0..r {
                        vt[k * rows + j] = v[j * r + k];
                    }
                }
                for bad in [None, Some(f64::NAN), Some(f64::NEG_INFINITY)] {
                    let mut c: Vec<f64> = (0..r * dim)
                        .map(|i| (i as f64 * 2.11).cos() * 1e-3)
                        .collect();
                    if let Some(x) = bad {
                        c[r * dim - 1] = x;
                    }
                    let want = max_value_norm(&v, r, &c, dim);
                    let got = max_pair_norm_t((&vt, &c), (&[], &[]), rows, dim);
                    assert_eq!(
                        got.to_bits(),
                        want.to_bits(),
                        "dim {dim} rows {rows} r {r} {bad:?}: {got} {want}"
                    );
                }
            }
        }
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
