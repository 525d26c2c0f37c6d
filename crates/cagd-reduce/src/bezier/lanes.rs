//! The curves-in-lanes kernel: one small linear map `Q_c = A P_c` applied to many curves
//! stored curve-major, four curves at a time, each curve in one lane of a 4-wide vector.
//! Goes beyond the seed: the data path under [`crate::reduce_batch`] (see `gemm.rs`).
//!
//! A group of four curves is transposed (4 x 4 blocks, in L1) so that element `l` of the
//! four flat curves is one vector `t_l`; the output element `(i, k)` of the four curves is
//! then `sum_j a_ij t_(j dim + k)`, accumulated in registers over tiles of up to 4 rows x 3
//! coordinates (12 vectors) and transposed back. This does exactly the `(m+1)(n+1) dim`
//! multiply-adds per curve of the definition (the Kronecker-expanded GEMM does `dim` times
//! as many, most of them on zeros), needs no packing, and works for every `dim` alike.
//!
//! Two instances of the same code: with AVX2 and FMA (detected at run time; the sums are
//! fused multiply-adds) and the portable one (a multiply then an add, whatever the target
//! vectorises it to). Both sum every output over `j = 0..=n` in increasing order, the zeros
//! of the map included, so a NaN or infinity anywhere in coordinate `k` of a curve reaches
//! every output of coordinate `k` of that curve. The curves that do not fill a group of
//! four go through a one-curve loop with the same operations in the same order, so every
//! curve gets the same bits wherever it sits in the batch (the result does not depend on
//! how the caller cuts the batch into blocks or threads).

/// Curves per group (the vector width in doubles).
const W: usize = 4;

/// One vector: the same element of four curves.
type V = [f64; W];

/// Rows of the map per register tile.
const TILE_ROWS: usize = 4;

/// Coordinates per register tile (12 accumulators with [`TILE_ROWS`]).
const TILE_COORDS: usize = 3;

/// Applies the row-major `rows x cols` map `a` (also given transposed: `at` is `cols x
/// rows`, row-major) to every curve of `input` (`cols * dim` doubles each, curve-major)
/// into `output` (`rows * dim` doubles each). `scratch` is resized as needed (one
/// allocation per call at most).
pub(crate) fn apply(
    at: &[f64],
    rows: usize,
    dim: usize,
    input: &[f64],
    output: &mut [f64],
    scratch: &mut Vec<V>,
) {
    #[cfg(target_arch = "x86_64")]
    if fused_available() {
        #[allow(unsafe_code, reason = "the one call of a `target_feature` function")]
        // SAFETY: the CPU supports AVX2 and FMA (detected just above), which is the only
        // requirement of `apply_avx2_fma`; the function itself is safe code.
        unsafe {
            apply_avx2_fma(at, rows, dim, input, output, scratch);
        }
        return;
    }
    apply_generic::<false>(at, rows, dim, input, output, scratch, transpose);
}

/// Whether this CPU runs the fused (AVX2 + FMA) instance.
#[cfg(target_arch = "x86_64")]
pub(crate) fn fused_available() -> bool {
    std::arch::is_x86_feature_detected!("avx2") && std::arch::is_x86_feature_detected!("fma")
}

/// The kernel compiled with AVX2 and FMA (fused multiply-adds).
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2,fma")]
fn apply_avx2_fma(
    at: &[f64],
    rows: usize,
    dim: usize,
    input: &[f64],
    output: &mut [f64],
    scratch: &mut Vec<V>,
) {
    // The closure inherits the target features (so the AVX transpose is inlined).
    apply_generic::<true>(at, rows, dim, input, output, scratch, |a, b, c, d| {
        transpose_avx(a, b, c, d)
    });
}

/// The 4 x 4 transpose with AVX shuffles (two `unpack`s and a 128-bit permute per row).
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2,fma")]
#[inline]
fn transpose_avx(a: V, b: V, c: V, d: V) -> [V; W] {
    use std::arch::x86_64::{
        __m256d, _mm256_permute2f128_pd, _mm256_unpackhi_pd, _mm256_unpacklo_pd,
    };
    let [a, b, c, d] = [a, b, c, d].map(bytemuck::cast::<V, __m256d>);
    // [a0 b0 a2 b2], [a1 b1 a3 b3], [c0 d0 c2 d2], [c1 d1 c3 d3]
    let (t0, t1) = (_mm256_unpacklo_pd(a, b), _mm256_unpackhi_pd(a, b));
    let (t2, t3) = (_mm256_unpacklo_pd(c, d), _mm256_unpackhi_pd(c, d));
    [
        _mm256_permute2f128_pd::<0x20>(t0, t2),
        _mm256_permute2f128_pd::<0x20>(t1, t3),
        _mm256_permute2f128_pd::<0x31>(t0, t2),
        _mm256_permute2f128_pd::<0x31>(t1, t3),
    ]
    .map(bytemuck::cast::<__m256d, V>)
}

/// The 4 x 4 transpose, portable.
#[inline(always)]
fn transpose(a: V, b: V, c: V, d: V) -> [V; W] {
    [
        [a[0], b[0], c[0], d[0]],
        [a[1], b[1], c[1], d[1]],
        [a[2], b[2], c[2], d[2]],
        [a[3], b[3], c[3], d[3]],
    ]
}

/// `acc + c x`, fused (one rounding) when `F`.
#[inline(always)]
fn madd<const F: bool>(c: f64, x: f64, acc: f64) -> f64 {
    if F { c.mul_add(x, acc) } else { acc + c * x }
}

/// The kernel, for either kind of multiply-add (see [`apply`]).
#[inline(always)]
pub(crate) fn apply_generic<const F: bool>(
    at: &[f64],
    rows: usize,
    dim: usize,
    input: &[f64],
    output: &mut [f64],
    scratch: &mut Vec<V>,
    tr: impl Fn(V, V, V, V) -> [V; W],
) {
    if rows == 0 || dim == 0 {
        return;
    }
    let cols = at.len() / rows;
    let (lin, lout) = (cols * dim, rows * dim);
    if lin == 0 {
        output.fill(0.0);
        return;
    }
    let curves = input.len() / lin;
    debug_assert_eq!(output.len(), curves * lout);
    scratch.clear();
    scratch.resize(lin + lout, [0.0; W]);
    let (t, u) = scratch.split_at_mut(lin);
    let groups = curves / W;
    let (in_g, in_rest) = input.split_at(groups * W * lin);
    let (out_g, out_rest) = output.split_at_mut(groups * W * lout);
    for (inp, out) in in_g
        .chunks_exact(W * lin)
        .zip(out_g.chunks_exact_mut(W * lout))
    {
        transpose_in(inp, lin, t, &tr);
        tiles::<F>(at, rows, cols, dim, t, u);
        transpose_out(u, lout, out, &tr);
    }
    for (inp, out) in in_rest
        .chunks_exact(lin)
        .zip(out_rest.chunks_exact_mut(lout))
    {
        one_curve::<F>(at, rows, dim, inp, out);
    }
}

/// `t[l] = [c0[l], c1[l], c2[l], c3[l]]` for the four flat curves `c` of `inp` (`lin`
/// doubles each), in 4 x 4 blocks.
#[inline(always)]
fn transpose_in(inp: &[f64], lin: usize, t: &mut [V], tr: impl Fn(V, V, V, V) -> [V; W]) {
    let (c0, rest) = inp.split_at(lin);
    let (c1, rest) = rest.split_at(lin);
    let (c2, c3) = rest.split_at(lin);
    let whole = lin / W * W;
    for ((((tb, x0), x1), x2), x3) in t[..whole]
        .chunks_exact_mut(W)
        .zip(c0.chunks_exact(W))
        .zip(c1.chunks_exact(W))
        .zip(c2.chunks_exact(W))
        .zip(c3.chunks_exact(W))
    {
        let [x0, x1, x2, x3] = [x0, x1, x2, x3].map(vector);
        tb.copy_from_slice(&tr(x0, x1, x2, x3));
    }
    for l in whole..lin {
        t[l] = [c0[l], c1[l], c2[l], c3[l]];
    }
}

/// Four doubles as one value (a vector load).
#[inline(always)]
fn vector(x: &[f64]) -> V {
    x.try_into().unwrap_or([0.0; W])
}

/// The inverse of [`transpose_in`]: the four flat curves of `out` (`lout` doubles each)
/// from the vectors `u`.
#[inline(always)]
fn transpose_out(u: &[V], lout: usize, out: &mut [f64], tr: impl Fn(V, V, V, V) -> [V; W]) {
    let (c0, rest) = out.split_at_mut(lout);
    let (c1, rest) = rest.split_at_mut(lout);
    let (c2, c3) = rest.split_at_mut(lout);
    let whole = lout / W * W;
    for ((((ub, y0), y1), y2), y3) in u[..whole]
        .chunks_exact(W)
        .zip(c0.chunks_exact_mut(W))
        .zip(c1.chunks_exact_mut(W))
        .zip(c2.chunks_exact_mut(W))
        .zip(c3.chunks_exact_mut(W))
    {
        let [v0, v1, v2, v3] = tr(ub[0], ub[1], ub[2], ub[3]);
        y0.copy_from_slice(&v0);
        y1.copy_from_slice(&v1);
        y2.copy_from_slice(&v2);
        y3.copy_from_slice(&v3);
    }
    for l in whole..lout {
        c0[l] = u[l][0];
        c1[l] = u[l][1];
        c2[l] = u[l][2];
        c3[l] = u[l][3];
    }
}

/// Every output vector `u[i dim + k] = sum_j a_ij t[j dim + k]`, tile by tile.
#[inline(always)]
fn tiles<const F: bool>(at: &[f64], rows: usize, cols: usize, dim: usize, t: &[V], u: &mut [V]) {
    let mut i = 0;
    while i < rows {
        let r = (rows - i).min(TILE_ROWS);
        let mut k = 0;
        while k < dim {
            let kk = (dim - k).min(TILE_COORDS);
            let at_ = (at, rows, cols, dim, i, k);
            match (r, kk) {
                (4, 3) => tile::<F, 4, 3>(at_, t, u),
                (4, 2) => tile::<F, 4, 2>(at_, t, u),
                (4, 1) => tile::<F, 4, 1>(at_, t, u),
                (3, 3) => tile::<F, 3, 3>(at_, t, u),
                (3, 2) => tile::<F, 3, 2>(at_, t, u),
                (3, 1) => tile::<F, 3, 1>(at_, t, u),
                (2, 3) => tile::<F, 2, 3>(at_, t, u),
                (2, 2) => tile::<F, 2, 2>(at_, t, u),
                (2, 1) => tile::<F, 2, 1>(at_, t, u),
                (1, 3) => tile::<F, 1, 3>(at_, t, u),
                (1, 2) => tile::<F, 1, 2>(at_, t, u),
                _ => tile::<F, 1, 1>(at_, t, u),
            }
            k += kk;
        }
        i += r;
    }
}

/// The map (transposed), its sizes, `dim`, and the tile's first row and coordinate.
type TileAt<'a> = (&'a [f64], usize, usize, usize, usize, usize);

/// One register tile: rows `i..i + R`, coordinates `k..k + K`, summed over `j` in
/// increasing order.
#[inline(always)]
fn tile<const F: bool, const R: usize, const K: usize>(
    (at, rows, cols, dim, i, k): TileAt<'_>,
    t: &[V],
    u: &mut [V],
) {
    let mut acc = [[[0.0f64; W]; K]; R];
    for (acol, tj) in at.chunks_exact(rows).zip(t.chunks_exact(dim)).take(cols) {
        let c: &[f64; R] = acol[i..i + R].try_into().unwrap_or(&[0.0; R]);
        let x: &[V; K] = tj[k..k + K].try_into().unwrap_or(&[[0.0; W]; K]);
        for r in 0..R {
            for q in 0..K {
                for l in 0..W {
                    acc[r][q][l] = madd::<F>(c[r], x[q][l], acc[r][q][l]);
                }
            }
        }
    }
    for (r, ar) in acc.iter().enumerate() {
        let o = (i + r) * dim + k;
        u[o..o + K].copy_from_slice(ar);
    }
}

/// One curve with the operations of a lane of the groups, in the same order (the same
/// bits): `out[i dim + k] = sum_j a_ij in[j dim + k]`, `j` increasing.
#[inline(always)]
fn one_curve<const F: bool>(at: &[f64], rows: usize, dim: usize, inp: &[f64], out: &mut [f64]) {
    out.fill(0.0);
    for (acol, pj) in at.chunks_exact(rows).zip(inp.chunks_exact(dim)) {
        for (c, o) in acol.iter().zip(out.chunks_exact_mut(dim)) {
            for (ok, xk) in o.iter_mut().zip(pj) {
                *ok = madd::<F>(*c, *xk, *ok);
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The definition, curve by curve, in `f64` with the multiply-adds of instance `F`.
    fn reference<const F: bool>(
        a: &[f64],
        rows: usize,
        cols: usize,
        input: &[f64],
        dim: usize,
    ) -> Vec<f64> {
        let curves = input.len() / (cols * dim);
        let mut out = vec![0.0; curves * rows * dim];
        for c in 0..curves {
            for i in 0..rows {
                for k in 0..dim {
                    let mut s = 0.0;
                    for j in 0..cols {
                        s = madd::<F>(a[i * cols + j], input[(c * cols + j) * dim + k], s);
                    }
                    out[(c * rows + i) * dim + k] = s;
                }
            }
        }
        out
    }

    fn transpose(a: &[f64], rows: usize, cols: usize) -> Vec<f64> {
        let mut at = vec![0.0; rows * cols];
        for i in 0..rows {
            for j in 0..cols {
                at[j * rows + i] = a[i * cols + j];
            }
        }
        at
    }

    /// A kernel under test: `(at, rows, dim, input, output, scratch)`.
    type Kernel<'a> = &'a dyn Fn(&[f64], usize, usize, &[f64], &mut [f64], &mut Vec<V>);

    fn check<const F: bool>(run: Kernel<'_>) {
        let mut scratch = Vec::new();
        for (rows, cols) in [
            (1, 1),
            (1, 2),
            (4, 5),
            (5, 6),
            (6, 11),
            (11, 16),
            (16, 31),
            (2, 3),
        ] {
            let a: Vec<f64> = (0..rows * cols)
                .map(|i| ((i * 37 % 23) as f64 - 11.0) / 7.0)
                .collect();
            let at = transpose(&a, rows, cols);
            for dim in 1..=7 {
                for curves in [0, 1, 3, 4, 5, 8, 11, 101] {
                    let input: Vec<f64> = (0..curves * cols * dim)
                        .map(|i| ((i * 7919 % 1001) as f64 - 500.0) / 97.0)
                        .collect();
                    let mut out = vec![f64::NAN; curves * rows * dim];
                    run(&at, rows, dim, &input, &mut out, &mut scratch);
                    let want = reference::<F>(&a, rows, cols, &input, dim);
                    // The same operations in the same order: the same bits.
                    assert_eq!(
                        out.iter().map(|x| x.to_bits()).collect::<Vec<_>>(),
                        want.iter().map(|x| x.to_bits()).collect::<Vec<_>>(),
                        "{rows}x{cols} dim {dim} curves {curves}"
                    );
                }
            }
        }
    }

    #[test]
    fn portable_instance_is_the_definition_bit_for_bit() {
        check::<false>(&|at, rows, dim, input, out, s| {
            apply_generic::<false>(at, rows, dim, input, out, s, super::transpose)
        });
    }

    #[test]
    fn fused_instance_is_the_fused_definition_bit_for_bit() {
        // The fused instance as compiled without AVX2 (software FMA: slow, same bits) and,
        // where the CPU has it, through the dispatch.
        check::<true>(&|at, rows, dim, input, out, s| {
            apply_generic::<true>(at, rows, dim, input, out, s, super::transpose)
        });
        #[cfg(target_arch = "x86_64")]
        if fused_available() {
            check::<true>(&|at, rows, dim, input, out, s| apply(at, rows, dim, input, out, s));
        }
    }

    #[test]
    fn a_curve_gets_the_same_bits_wherever_it_sits() {
        // Curve 0 of a batch of 1 (the one-curve loop) and at every position of a group.
        let (rows, cols, dim) = (6, 11, 3);
        let a: Vec<f64> = (0..rows * cols).map(|i| (i as f64 * 0.37).sin()).collect();
        let at = transpose(&a, rows, cols);
        let mut scratch = Vec::new();
        let input: Vec<f64> = (0..9 * cols * dim)
            .map(|i| (i as f64 * 1.3).cos())
            .collect();
        let mut all = vec![0.0; 9 * rows * dim];
        apply(&at, rows, dim, &input, &mut all, &mut scratch);
        for c in 0..9 {
            let mut one = vec![0.0; rows * dim];
            let p = &input[c * cols * dim..(c + 1) * cols * dim];
            apply(&at, rows, dim, p, &mut one, &mut scratch);
            assert_eq!(
                &all[c * rows * dim..(c + 1) * rows * dim],
                &one[..],
                "curve {c}"
            );
        }
    }

    #[test]
    fn non_finite_input_reaches_every_output_of_its_coordinate() {
        // A zero column of the map: the NaN / infinity still reaches the outputs.
        let (rows, cols) = (5, 7);
        let mut a = vec![1.0; rows * cols];
        for i in 0..rows {
            a[i * cols + 3] = 0.0;
        }
        let at = transpose(&a, rows, cols);
        let mut scratch = Vec::new();
        for dim in [1, 3, 5] {
            for bad in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
                for curve in [0, 2, 5, 8] {
                    let curves = 9;
                    let mut input = vec![0.5; curves * cols * dim];
                    let k = dim - 1;
                    input[(curve * cols + 3) * dim + k] = bad;
                    let mut out = vec![0.0; curves * rows * dim];
                    apply(&at, rows, dim, &input, &mut out, &mut scratch);
                    for (c, q) in out.chunks_exact(rows * dim).enumerate() {
                        for (i, p) in q.chunks_exact(dim).enumerate() {
                            for (kk, x) in p.iter().enumerate() {
                                let hit = c == curve && kk == k;
                                assert_eq!(!x.is_finite(), hit, "dim {dim} {bad} {c} {i} {kk}");
                            }
                        }
                    }
                }
            }
        }
    }
}
