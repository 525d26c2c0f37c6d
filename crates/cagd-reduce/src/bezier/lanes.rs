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

/// The three maps of a batch with certified bounds, each transposed (`cols x rows`,
/// row-major) with its number of rows: the reduction `A` (`m + 1` rows), the error
/// curve's coefficient map `G` (`r` rows) and its node map `V` (`N + 1` rows, `r`
/// columns).
pub(crate) struct BoundMaps<'a> {
    /// `A^T` and `m + 1`.
    pub(crate) a: (&'a [f64], usize),
    /// `G^T` and `r` (`r = 0`: no error space; every node value is zero).
    pub(crate) g: (&'a [f64], usize),
    /// `V^T` and `N + 1`.
    pub(crate) v: (&'a [f64], usize),
}

/// Per curve of a batch with bounds: the largest node value norm `max_j ||(V G P)_j||`,
/// the largest point norm `max_j ||P_j||` and the largest coordinate magnitude; each NaN
/// when a value it is the maximum of is NaN.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub(crate) struct CurveNorms {
    /// `max_j ||s_j||` over the node values `s = V G P`.
    pub(crate) smax: f64,
    /// `max_j ||P_j||`.
    pub(crate) pmax: f64,
    /// `max |P_jk|`.
    pub(crate) amax: f64,
}

/// [`apply`] with the reduction `maps.a` plus, per curve, the norms of [`CurveNorms`]
/// into `norms` (one per curve): the coefficient and node maps run on the group's
/// transposed input while it is in L1 (no second pass over the input, no buffer of node
/// values per curve), and the norms are maxima over lanes. The curves that do not fill a
/// group are padded with zero curves (every lane is computed alike, so a curve's results
/// do not depend on its position).
pub(crate) fn apply_with_norms(
    maps: &BoundMaps<'_>,
    dim: usize,
    input: &[f64],
    output: &mut [f64],
    norms: &mut [CurveNorms],
    scratch: &mut Vec<V>,
) {
    #[cfg(target_arch = "x86_64")]
    if fused_available() {
        #[allow(unsafe_code, reason = "the one call of a `target_feature` function")]
        // SAFETY: as in `apply`: AVX2 and FMA were detected just above.
        unsafe {
            with_norms_avx2_fma(maps, dim, input, output, norms, scratch);
        }
        return;
    }
    with_norms_generic::<false>(maps, dim, input, output, norms, scratch, transpose);
}

/// [`apply_with_norms`] compiled with AVX2 and FMA.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2,fma")]
fn with_norms_avx2_fma(
    maps: &BoundMaps<'_>,
    dim: usize,
    input: &[f64],
    output: &mut [f64],
    norms: &mut [CurveNorms],
    scratch: &mut Vec<V>,
) {
    with_norms_generic::<true>(maps, dim, input, output, norms, scratch, |a, b, c, d| {
        transpose_avx(a, b, c, d)
    });
}

/// The body of [`apply_with_norms`] for either kind of multiply-add.
#[inline(always)]
pub(crate) fn with_norms_generic<const F: bool>(
    maps: &BoundMaps<'_>,
    dim: usize,
    input: &[f64],
    output: &mut [f64],
    norms: &mut [CurveNorms],
    scratch: &mut Vec<V>,
    tr: impl Fn(V, V, V, V) -> [V; W],
) {
    let ((at, rows), (gt, rank), (vt, nodes)) = (maps.a, maps.g, maps.v);
    if rows == 0 || dim == 0 {
        return;
    }
    let cols = at.len() / rows;
    let (lin, lout, lc, lv) = (cols * dim, rows * dim, rank * dim, nodes * dim);
    if lin == 0 {
        return;
    }
    let curves = input.len() / lin;
    debug_assert!(output.len() == curves * lout && norms.len() == curves);
    scratch.clear();
    scratch.resize(lin + lout + lc + lv, [0.0; W]);
    let (t, rest) = scratch.split_at_mut(lin);
    let (u, rest) = rest.split_at_mut(lout);
    let (c, vv) = rest.split_at_mut(lc);
    // A partial last group: its curves in a zero-padded copy.
    let mut pad_in = Vec::new();
    let mut pad_out = Vec::new();
    for ((inp, out), nrm) in input
        .chunks(W * lin)
        .zip(output.chunks_mut(W * lout))
        .zip(norms.chunks_mut(W))
    {
        let whole = nrm.len() == W;
        if whole {
            transpose_in(inp, lin, t, &tr);
        } else {
            pad_in.clear();
            pad_in.extend_from_slice(inp);
            pad_in.resize(W * lin, 0.0);
            transpose_in(&pad_in, lin, t, &tr);
        }
        tiles::<F>(at, rows, cols, dim, t, u);
        if whole {
            transpose_out(u, lout, out, &tr);
        } else {
            pad_out.resize(W * lout, 0.0);
            transpose_out(u, lout, &mut pad_out, &tr);
            out.copy_from_slice(&pad_out[..out.len()]);
        }
        let smax = if rank == 0 || nodes == 0 {
            [0.0; W]
        } else {
            tiles::<F>(gt, rank, cols, dim, t, c);
            tiles::<F>(vt, nodes, rank, dim, c, vv);
            max_point_norm::<F>(vv, dim)
        };
        let pmax = max_point_norm::<F>(t, dim);
        let amax = t.iter().fold([0.0f64; W], |m, x| {
            std::array::from_fn(|l| {
                if x[l].abs() > m[l] || x[l].is_nan() {
                    x[l].abs()
                } else {
                    m[l]
                }
            })
        });
        for (l, n) in nrm.iter_mut().enumerate() {
            *n = CurveNorms {
                smax: smax[l],
                pmax: pmax[l],
                amax: amax[l],
            };
        }
    }
}

/// Per lane, `max_j ||x_j||` over the points `x_j` (`dim` vectors each); NaN in a lane
/// where a squared norm is NaN (never skipped).
#[inline(always)]
fn max_point_norm<const F: bool>(x: &[V], dim: usize) -> V {
    let mut best = [0.0f64; W];
    let mut bad = [false; W];
    for p in x.chunks_exact(dim) {
        let mut q = [0.0f64; W];
        for v in p {
            for l in 0..W {
                q[l] = madd::<F>(v[l], v[l], q[l]);
            }
        }
        for l in 0..W {
            bad[l] |= q[l].is_nan();
            best[l] = best[l].max(q[l]);
        }
    }
    std::array::from_fn(|l| if bad[l] { f64::NAN } else { best[l].sqrt() })
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

    #[test]
    fn norms_equal_their_definitions_and_the_reduction_is_apply_bit_for_bit() {
        let (rows, cols, rank, nodes) = (5, 9, 4, 23);
        let mk = |r: usize, c: usize, s: f64| -> Vec<f64> {
            (0..r * c).map(|i| (i as f64 * s).sin()).collect()
        };
        let (a, g, v) = (
            mk(rows, cols, 0.37),
            mk(rank, cols, 0.53),
            mk(nodes, rank, 0.71),
        );
        let (at, gt, vt) = (
            transpose(&a, rows, cols),
            transpose(&g, rank, cols),
            transpose(&v, nodes, rank),
        );
        let maps = BoundMaps {
            a: (&at, rows),
            g: (&gt, rank),
            v: (&vt, nodes),
        };
        let mut scratch = Vec::new();
        for dim in [1, 2, 3, 4, 7] {
            for curves in [1, 3, 4, 9] {
                let input: Vec<f64> = (0..curves * cols * dim)
                    .map(|i| (i as f64 * 1.7).cos() * 3.0)
                    .collect();
                let mut out = vec![0.0; curves * rows * dim];
                let mut norms = vec![CurveNorms::default(); curves];
                apply_with_norms(&maps, dim, &input, &mut out, &mut norms, &mut scratch);
                let mut want = vec![0.0; out.len()];
                apply(&at, rows, dim, &input, &mut want, &mut scratch);
                assert_eq!(out, want, "dim {dim} curves {curves}");
                for (cv, nrm) in input.chunks_exact(cols * dim).zip(&norms) {
                    let coef = reference::<false>(&g, rank, cols, cv, dim);
                    let vals = reference::<false>(&v, nodes, rank, &coef, dim);
                    let norm = |x: &[f64]| x.iter().map(|y| y * y).sum::<f64>().sqrt();
                    let smax = vals.chunks_exact(dim).map(norm).fold(0.0, f64::max);
                    let pmax = cv.chunks_exact(dim).map(norm).fold(0.0, f64::max);
                    let amax = cv.iter().fold(0.0f64, |m, x| m.max(x.abs()));
                    assert!(
                        (nrm.smax - smax).abs() <= 1e-13 * smax.max(1.0),
                        "{nrm:?} {smax}"
                    );
                    assert!((nrm.pmax - pmax).abs() <= 1e-14 * pmax, "{nrm:?} {pmax}");
                    assert_eq!(nrm.amax, amax);
                }
                // A NaN shows in the curve's node and point norms.
                let mut bad = input.clone();
                bad[cols * dim * (curves - 1) + dim - 1] = f64::NAN;
                apply_with_norms(&maps, dim, &bad, &mut out, &mut norms, &mut scratch);
                let last = norms[curves - 1];
                assert!(last.smax.is_nan() && last.pmax.is_nan() && last.amax.is_nan());
            }
        }
    }
}
