//! The curves-in-lanes kernel: one small linear map `Q_c = A P_c` applied to many curves
//! stored curve-major, `L` curves at a time (4 with AVX2, 8 with AVX-512), each curve in
//! one lane of an `L`-wide vector.
//! Goes beyond the seed: the data path under [`crate::reduce_batch`] for points of other
//! than three coordinates, for the last curves of a 3-D batch, and under the batch bounds
//! (see `gemm.rs`; 3-D batches take `padded.rs`).
//!
//! A group of `L` curves is transposed (4 x 4 blocks, in L1) so that element `l` of the
//! `L` flat curves is one vector `t_l`; the output element `(i, k)` of the four curves is
//! then `sum_j a_ij t_(j dim + k)`, accumulated in registers over tiles of up to 4 rows x 3
//! coordinates (12 vectors) and transposed back. This does exactly the `(m+1)(n+1) dim`
//! multiply-adds per curve of the definition (the Kronecker-expanded GEMM does `dim` times
//! as many, most of them on zeros), needs no packing, and works for every `dim` alike.
//!
//! Three instances of the same code: with AVX-512F and FMA (8 lanes), with AVX2 and FMA
//! (4 lanes; both detected at run time, the sums fused multiply-adds, so the two give the
//! same bits) and the portable one (4 lanes, a multiply then an add, whatever the target
//! vectorises it to). Both sum every output over `j = 0..=n` in increasing order, the zeros
//! of the map included, so a NaN or infinity anywhere in coordinate `k` of a curve reaches
//! every output of coordinate `k` of that curve. The curves that do not fill a group
//! go through a one-curve loop with the same operations in the same order, so every
//! curve gets the same bits wherever it sits in the batch (the result does not depend on
//! how the caller cuts the batch into blocks or threads).

/// A 4 x 4 transpose of four vectors of four doubles (AVX shuffles or portable).
type Quad = [f64; 4];

/// How many groups ahead [`apply`] asks the CPU to fetch the input (a hint: measured 0–14 %
/// faster at (4,3)…(20,10) in alternated runs, neutral at (30,15); see the benches README).
const PREFETCH_GROUPS: usize = 2;

/// Asks the CPU to bring every cache line of `x` towards L1 (a hint; no effect on results).
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2,fma")]
#[inline]
fn prefetch_avx(x: &[f64]) {
    use std::arch::x86_64::{_MM_HINT_T0, _mm_prefetch};
    for line in x.chunks(8) {
        _mm_prefetch::<_MM_HINT_T0>(line.as_ptr().cast::<i8>());
    }
}

/// Runs `$f::<R, C>($args)`, an instance of a kernel with `rows = R`, `cols = C` and
/// `dim = 3` as constants (its loops unroll and its index checks fold; used by the batch
/// bounds here and by `padded.rs`), when the map
/// (`rows`, `len` entries) is `R x C` with `C <= 11` (degree 10 and below, where the loop overhead of the general instance
/// weighs most: 2.4x / 2.0x / 1.7x fewer instructions per curve at (4,3) / (5,4) / (10,5),
/// callgrind, AVX2), and says whether it did. Same operations in the same order as the
/// general instance, so the same bits.
macro_rules! sized {
    ($f:ident, $rows:expr, $len:expr, $args:tt) => {
        sized!(@ $f, $rows, $len, $args;
            (1, 2)
            (1, 3) (2, 3)
            (1, 4) (2, 4) (3, 4)
            (1, 5) (2, 5) (3, 5) (4, 5)
            (1, 6) (2, 6) (3, 6) (4, 6) (5, 6)
            (1, 7) (2, 7) (3, 7) (4, 7) (5, 7) (6, 7)
            (1, 8) (2, 8) (3, 8) (4, 8) (5, 8) (6, 8) (7, 8)
            (1, 9) (2, 9) (3, 9) (4, 9) (5, 9) (6, 9) (7, 9) (8, 9)
            (1, 10) (2, 10) (3, 10) (4, 10) (5, 10) (6, 10) (7, 10) (8, 10) (9, 10)
            (1, 11) (2, 11) (3, 11) (4, 11) (5, 11) (6, 11) (7, 11) (8, 11) (9, 11) (10, 11))
    };
    (@ $f:ident, $rows:expr, $len:expr, $args:tt; $(($r:literal, $c:literal))*) => {
        match ($rows, $len) {
            $(
                (r, len) if r == $r && len == $r * $c => {
                    sized!(@call $f, $r, $c, $args);
                    true
                }
            )*
            _ => false,
        }
    };
    (@call $f:ident, $r:literal, $c:literal, ($($arg:expr),*)) => {
        $f::<$r, $c>($($arg),*)
    };
}
pub(crate) use sized;

/// Rows of the map per register tile.
const TILE_ROWS: usize = 4;

/// Coordinates per register tile (12 accumulators with [`TILE_ROWS`]).
const TILE_COORDS: usize = 3;

/// The instance this CPU runs (detected once).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Isa {
    /// AVX-512F + AVX2 + FMA: 8 lanes, fused.
    Avx512,
    /// AVX2 + FMA: 4 lanes, fused.
    Avx2,
    /// Portable: 4 lanes, multiply then add.
    Portable,
}

/// The instance this CPU runs.
pub(crate) fn isa() -> Isa {
    #[cfg(target_arch = "x86_64")]
    {
        use std::arch::is_x86_feature_detected as has;
        if has!("avx2") && has!("fma") {
            return if has!("avx512f") {
                Isa::Avx512
            } else {
                Isa::Avx2
            };
        }
    }
    Isa::Portable
}

/// Applies the row-major `rows x cols` map `a`, given transposed (`at` is `cols x rows`,
/// row-major), to every curve of `input` (`cols * dim` doubles each, curve-major) into
/// `output` (`rows * dim` doubles each). `scratch` is resized as needed (one allocation
/// per call at most).
pub(crate) fn apply(
    at: &[f64],
    rows: usize,
    dim: usize,
    input: &[f64],
    output: &mut [f64],
    scratch: &mut Vec<f64>,
) {
    #[cfg(target_arch = "x86_64")]
    match isa() {
        #[allow(unsafe_code, reason = "the call of a `target_feature` function")]
        // SAFETY: the CPU supports AVX-512F, AVX2 and FMA (detected by `isa`), the only
        // requirement of the function, which is itself safe code.
        Isa::Avx512 => unsafe { apply_avx512(at, rows, dim, input, output, scratch) },
        #[allow(unsafe_code, reason = "the call of a `target_feature` function")]
        // SAFETY: the CPU supports AVX2 and FMA (detected by `isa`), as above.
        Isa::Avx2 => unsafe { apply_avx2(at, rows, dim, input, output, scratch) },
        Isa::Portable => {
            apply_generic::<false, 4>(at, rows, dim, input, output, scratch, transpose, |_| {})
        }
    }
    #[cfg(not(target_arch = "x86_64"))]
    apply_generic::<false, 4>(at, rows, dim, input, output, scratch, transpose, |_| {});
}

/// The kernel compiled with AVX-512F and FMA, 8 lanes.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx512f,avx2,fma")]
fn apply_avx512(
    at: &[f64],
    rows: usize,
    dim: usize,
    input: &[f64],
    output: &mut [f64],
    scratch: &mut Vec<f64>,
) {
    // The closure inherits the target features (so the AVX transpose is inlined).
    apply_generic::<true, 8>(
        at,
        rows,
        dim,
        input,
        output,
        scratch,
        |a, b, c, d| transpose_avx(a, b, c, d),
        |x| prefetch_avx(x),
    );
}

/// The kernel compiled with AVX2 and FMA, 4 lanes.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2,fma")]
fn apply_avx2(
    at: &[f64],
    rows: usize,
    dim: usize,
    input: &[f64],
    output: &mut [f64],
    scratch: &mut Vec<f64>,
) {
    apply_generic::<true, 4>(
        at,
        rows,
        dim,
        input,
        output,
        scratch,
        |a, b, c, d| transpose_avx(a, b, c, d),
        |x| prefetch_avx(x),
    );
}

/// The 4 x 4 transpose with AVX shuffles (two `unpack`s and a 128-bit permute per row).
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2,fma")]
#[inline]
fn transpose_avx(a: Quad, b: Quad, c: Quad, d: Quad) -> [Quad; 4] {
    use std::arch::x86_64::{
        __m256d, _mm256_permute2f128_pd, _mm256_unpackhi_pd, _mm256_unpacklo_pd,
    };
    let [a, b, c, d] = [a, b, c, d].map(bytemuck::cast::<Quad, __m256d>);
    // [a0 b0 a2 b2], [a1 b1 a3 b3], [c0 d0 c2 d2], [c1 d1 c3 d3]
    let (t0, t1) = (_mm256_unpacklo_pd(a, b), _mm256_unpackhi_pd(a, b));
    let (t2, t3) = (_mm256_unpacklo_pd(c, d), _mm256_unpackhi_pd(c, d));
    [
        _mm256_permute2f128_pd::<0x20>(t0, t2),
        _mm256_permute2f128_pd::<0x20>(t1, t3),
        _mm256_permute2f128_pd::<0x31>(t0, t2),
        _mm256_permute2f128_pd::<0x31>(t1, t3),
    ]
    .map(bytemuck::cast::<__m256d, Quad>)
}

/// The 4 x 4 transpose, portable.
#[inline(always)]
fn transpose(a: Quad, b: Quad, c: Quad, d: Quad) -> [Quad; 4] {
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

/// `len` vectors of `L` lanes in `scratch` (zeroed).
#[inline(always)]
fn vectors<const L: usize>(scratch: &mut Vec<f64>, len: usize) -> &mut [[f64; L]] {
    scratch.clear();
    scratch.resize(len * L, 0.0);
    bytemuck::cast_slice_mut(scratch)
}

/// The kernel, for either kind of multiply-add and `L` lanes (a multiple of 4; see
/// [`apply`]).
#[inline(always)]
#[allow(
    clippy::too_many_arguments,
    reason = "the kernel's data plus the two instance hooks (transpose, prefetch)"
)]
pub(crate) fn apply_generic<const F: bool, const L: usize>(
    at: &[f64],
    rows: usize,
    dim: usize,
    input: &[f64],
    output: &mut [f64],
    scratch: &mut Vec<f64>,
    tr: impl Fn(Quad, Quad, Quad, Quad) -> [Quad; 4],
    prefetch: impl Fn(&[f64]),
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
    let groups = curves / L;
    // No scratch (no allocation) when there is no whole group, e.g. a single curve.
    let (t, u) = vectors::<L>(scratch, if groups > 0 { lin + lout } else { 0 })
        .split_at_mut(if groups > 0 { lin } else { 0 });
    let (in_g, in_rest) = input.split_at(groups * L * lin);
    let (out_g, out_rest) = output.split_at_mut(groups * L * lout);
    for (g, (inp, out)) in in_g
        .chunks_exact(L * lin)
        .zip(out_g.chunks_exact_mut(L * lout))
        .enumerate()
    {
        // The input of a group further on, towards L1 while this one is computed.
        let ahead = (g + PREFETCH_GROUPS) * L * lin;
        if let Some(next) = in_g.get(ahead..ahead + L * lin) {
            prefetch(next);
        }
        transpose_in(inp, lin, t, &tr);
        tiles::<F, L>(at, rows, cols, dim, t, u);
        transpose_out(u, lout, out, &tr);
    }
    for (inp, out) in in_rest
        .chunks_exact(lin)
        .zip(out_rest.chunks_exact_mut(lout))
    {
        one_curve::<F>(at, rows, dim, inp, out);
    }
}

/// `t[l][c] = curve_c[l]` for the `L` flat curves of `inp` (`lin` doubles each), in
/// 4 x 4 blocks.
#[inline(always)]
fn transpose_in<const L: usize>(
    inp: &[f64],
    lin: usize,
    t: &mut [[f64; L]],
    tr: impl Fn(Quad, Quad, Quad, Quad) -> [Quad; 4],
) {
    let whole = lin / 4 * 4;
    for h in 0..L / 4 {
        let c = |q: usize| &inp[(4 * h + q) * lin..(4 * h + q + 1) * lin];
        let (c0, c1, c2, c3) = (c(0), c(1), c(2), c(3));
        for l in (0..whole).step_by(4) {
            let [x0, x1, x2, x3] = [c0, c1, c2, c3].map(|x| quad(&x[l..l + 4]));
            for (q, v) in tr(x0, x1, x2, x3).iter().enumerate() {
                t[l + q][4 * h..4 * h + 4].copy_from_slice(v);
            }
        }
        for l in whole..lin {
            t[l][4 * h..4 * h + 4].copy_from_slice(&[c0[l], c1[l], c2[l], c3[l]]);
        }
    }
}

/// Four doubles as one value (a vector load).
#[inline(always)]
fn quad(x: &[f64]) -> Quad {
    x.try_into().unwrap_or([0.0; 4])
}

/// The inverse of [`transpose_in`]: the `L` flat curves of `out` (`lout` doubles each)
/// from the vectors `u`.
#[inline(always)]
fn transpose_out<const L: usize>(
    u: &[[f64; L]],
    lout: usize,
    out: &mut [f64],
    tr: impl Fn(Quad, Quad, Quad, Quad) -> [Quad; 4],
) {
    let whole = lout / 4 * 4;
    for h in 0..L / 4 {
        let part = |l: usize| quad(&u[l][4 * h..4 * h + 4]);
        let block = &mut out[4 * h * lout..(4 * h + 4) * lout];
        for l in (0..whole).step_by(4) {
            let ys = tr(part(l), part(l + 1), part(l + 2), part(l + 3));
            for (q, y) in ys.iter().enumerate() {
                block[q * lout + l..q * lout + l + 4].copy_from_slice(y);
            }
        }
        for l in whole..lout {
            for q in 0..4 {
                block[q * lout + l] = u[l][4 * h + q];
            }
        }
    }
}

/// Every output vector `u[i dim + k] = sum_j a_ij t[j dim + k]`, tile by tile.
#[inline(always)]
fn tiles<const F: bool, const L: usize>(
    at: &[f64],
    rows: usize,
    cols: usize,
    dim: usize,
    t: &[[f64; L]],
    u: &mut [[f64; L]],
) {
    let mut i = 0;
    while i < rows {
        let r = (rows - i).min(TILE_ROWS);
        let mut k = 0;
        while k < dim {
            let kk = (dim - k).min(TILE_COORDS);
            let at_ = (at, rows, cols, dim, i, k);
            match (r, kk) {
                (4, 3) => tile::<F, L, 4, 3>(at_, t, u),
                (4, 2) => tile::<F, L, 4, 2>(at_, t, u),
                (4, 1) => tile::<F, L, 4, 1>(at_, t, u),
                (3, 3) => tile::<F, L, 3, 3>(at_, t, u),
                (3, 2) => tile::<F, L, 3, 2>(at_, t, u),
                (3, 1) => tile::<F, L, 3, 1>(at_, t, u),
                (2, 3) => tile::<F, L, 2, 3>(at_, t, u),
                (2, 2) => tile::<F, L, 2, 2>(at_, t, u),
                (2, 1) => tile::<F, L, 2, 1>(at_, t, u),
                (1, 3) => tile::<F, L, 1, 3>(at_, t, u),
                (1, 2) => tile::<F, L, 1, 2>(at_, t, u),
                _ => tile::<F, L, 1, 1>(at_, t, u),
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
fn tile<const F: bool, const L: usize, const R: usize, const K: usize>(
    (at, rows, cols, dim, i, k): TileAt<'_>,
    t: &[[f64; L]],
    u: &mut [[f64; L]],
) {
    let mut acc = [[[0.0f64; L]; K]; R];
    for (acol, tj) in at.chunks_exact(rows).zip(t.chunks_exact(dim)).take(cols) {
        let c: &[f64; R] = acol[i..i + R].try_into().unwrap_or(&[0.0; R]);
        let x: &[[f64; L]; K] = tj[k..k + K].try_into().unwrap_or(&[[0.0; L]; K]);
        for r in 0..R {
            for q in 0..K {
                for l in 0..L {
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
/// bits): `out[i dim + k] = sum_j a_ij in[j dim + k]`, `j` increasing; four rows at a
/// time with the point in registers for `dim <= 4`.
#[inline(always)]
fn one_curve<const F: bool>(at: &[f64], rows: usize, dim: usize, inp: &[f64], out: &mut [f64]) {
    match dim {
        1 => one_curve_fixed::<F, 1>(at, rows, inp, out),
        2 => one_curve_fixed::<F, 2>(at, rows, inp, out),
        3 => one_curve_fixed::<F, 3>(at, rows, inp, out),
        4 => one_curve_fixed::<F, 4>(at, rows, inp, out),
        _ => {
            out.fill(0.0);
            for (acol, pj) in at.chunks_exact(rows).zip(inp.chunks_exact(dim)) {
                for (c, o) in acol.iter().zip(out.chunks_exact_mut(dim)) {
                    for (ok, xk) in o.iter_mut().zip(pj) {
                        *ok = madd::<F>(*c, *xk, *ok);
                    }
                }
            }
        }
    }
}

/// [`one_curve`] for `dim = D`.
#[inline(always)]
fn one_curve_fixed<const F: bool, const D: usize>(
    at: &[f64],
    rows: usize,
    inp: &[f64],
    out: &mut [f64],
) {
    for (b, ob) in out.chunks_mut(4 * D).enumerate() {
        let i0 = 4 * b;
        let r = ob.len() / D;
        let mut acc = [[0.0f64; D]; 4];
        for (acol, pj) in at.chunks_exact(rows).zip(inp.chunks_exact(D)) {
            let c = &acol[i0..i0 + r];
            for (ar, cr) in acc.iter_mut().zip(c) {
                for k in 0..D {
                    ar[k] = madd::<F>(*cr, pj[k], ar[k]);
                }
            }
        }
        for (o, ar) in ob.chunks_exact_mut(D).zip(&acc) {
            o.copy_from_slice(ar);
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
    /// The node values: `V^T` and `N + 1`, or the symmetric split's halves.
    pub(crate) v: NodeMaps<'a>,
}

impl BoundMaps<'_> {
    /// The same maps with `A^T` as a slice of exactly `R * C` entries and `R` rows, so
    /// that an inlined kernel sees the sizes as constants (the caller checked them).
    #[inline(always)]
    fn with_sized_a<const R: usize, const C: usize>(&self) -> BoundMaps<'_> {
        BoundMaps {
            a: (&self.a.0[..R * C], R),
            g: self.g,
            v: self.v,
        }
    }
}

/// The node map of a batch with bounds (see `operator/error_map.rs`).
#[derive(Clone, Copy)]
pub(crate) enum NodeMaps<'a> {
    /// `V^T` and its number of rows (nodes).
    Full(&'a [f64], usize),
    /// The symmetric split: `V_e^T`, `V_o^T` (transposed, `r_e x rows` and `r_o x
    /// rows`), `r_e` and the number of rows (node pairs `t_j`, `1 - t_j`); the node values
    /// are `e_j + o_j` and `e_j - o_j`.
    Split(&'a [f64], &'a [f64], usize, usize),
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
    scratch: &mut Vec<f64>,
) {
    #[cfg(target_arch = "x86_64")]
    match isa() {
        #[allow(unsafe_code, reason = "the call of a `target_feature` function")]
        // SAFETY: as in `apply`: the CPU has the functions' features (detected by `isa`);
        // the sized instances chosen outside the general one, as there.
        Isa::Avx512 => unsafe {
            let (at, rows) = maps.a;
            if !(dim == 3
                && sized!(
                    norms_sized_avx512,
                    rows,
                    at.len(),
                    (maps, input, output, norms, scratch)
                ))
            {
                with_norms_avx512(maps, dim, input, output, norms, scratch);
            }
        },
        #[allow(unsafe_code, reason = "the call of a `target_feature` function")]
        // SAFETY: as above.
        Isa::Avx2 => unsafe {
            let (at, rows) = maps.a;
            if !(dim == 3
                && sized!(
                    norms_sized_avx2,
                    rows,
                    at.len(),
                    (maps, input, output, norms, scratch)
                ))
            {
                with_norms_avx2(maps, dim, input, output, norms, scratch);
            }
        },
        Isa::Portable => {
            with_norms_generic::<false, 4>(maps, dim, input, output, norms, scratch, transpose);
        }
    }
    #[cfg(not(target_arch = "x86_64"))]
    with_norms_generic::<false, 4>(maps, dim, input, output, norms, scratch, transpose);
}

/// [`apply_with_norms`] compiled with AVX-512F and FMA, 8 lanes.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx512f,avx2,fma")]
fn with_norms_avx512(
    maps: &BoundMaps<'_>,
    dim: usize,
    input: &[f64],
    output: &mut [f64],
    norms: &mut [CurveNorms],
    scratch: &mut Vec<f64>,
) {
    with_norms_generic::<true, 8>(maps, dim, input, output, norms, scratch, |a, b, c, d| {
        transpose_avx(a, b, c, d)
    });
}

/// [`with_norms_avx512`] for `dim = 3` and an `R x C` reduction with the sizes as
/// constants (see [`sized!`]).
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx512f,avx2,fma")]
fn norms_sized_avx512<const R: usize, const C: usize>(
    maps: &BoundMaps<'_>,
    input: &[f64],
    output: &mut [f64],
    norms: &mut [CurveNorms],
    scratch: &mut Vec<f64>,
) {
    let maps = maps.with_sized_a::<R, C>();
    with_norms_generic::<true, 8>(&maps, 3, input, output, norms, scratch, |a, b, c, d| {
        transpose_avx(a, b, c, d)
    });
}

/// [`apply_with_norms`] compiled with AVX2 and FMA, 4 lanes.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2,fma")]
fn with_norms_avx2(
    maps: &BoundMaps<'_>,
    dim: usize,
    input: &[f64],
    output: &mut [f64],
    norms: &mut [CurveNorms],
    scratch: &mut Vec<f64>,
) {
    with_norms_generic::<true, 4>(maps, dim, input, output, norms, scratch, |a, b, c, d| {
        transpose_avx(a, b, c, d)
    });
}

/// [`with_norms_avx2`] for `dim = 3` and an `R x C` reduction with the sizes as constants.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2,fma")]
fn norms_sized_avx2<const R: usize, const C: usize>(
    maps: &BoundMaps<'_>,
    input: &[f64],
    output: &mut [f64],
    norms: &mut [CurveNorms],
    scratch: &mut Vec<f64>,
) {
    let maps = maps.with_sized_a::<R, C>();
    with_norms_generic::<true, 4>(&maps, 3, input, output, norms, scratch, |a, b, c, d| {
        transpose_avx(a, b, c, d)
    });
}

/// The body of [`apply_with_norms`] for either kind of multiply-add.
#[inline(always)]
pub(crate) fn with_norms_generic<const F: bool, const L: usize>(
    maps: &BoundMaps<'_>,
    dim: usize,
    input: &[f64],
    output: &mut [f64],
    norms: &mut [CurveNorms],
    scratch: &mut Vec<f64>,
    tr: impl Fn(Quad, Quad, Quad, Quad) -> [Quad; 4],
) {
    let ((at, rows), (gt, rank)) = (maps.a, maps.g);
    let (nodes, halves) = match maps.v {
        NodeMaps::Full(_, nodes) => (nodes, 1),
        NodeMaps::Split(_, _, _, pairs) => (pairs, 2),
    };
    if rows == 0 || dim == 0 {
        return;
    }
    let cols = at.len() / rows;
    let (lin, lout, lc, lv) = (cols * dim, rows * dim, rank * dim, halves * nodes * dim);
    if lin == 0 {
        return;
    }
    let curves = input.len() / lin;
    debug_assert!(output.len() == curves * lout && norms.len() == curves);
    let (t, rest) = vectors::<L>(scratch, lin + lout + lc + lv).split_at_mut(lin);
    let (u, rest) = rest.split_at_mut(lout);
    let (c, vv) = rest.split_at_mut(lc);
    // A partial last group: its curves in a zero-padded copy.
    let mut pad_in = Vec::new();
    let mut pad_out = Vec::new();
    for ((inp, out), nrm) in input
        .chunks(L * lin)
        .zip(output.chunks_mut(L * lout))
        .zip(norms.chunks_mut(L))
    {
        let whole = nrm.len() == L;
        if whole {
            transpose_in(inp, lin, t, &tr);
        } else {
            pad_in.clear();
            pad_in.extend_from_slice(inp);
            pad_in.resize(L * lin, 0.0);
            transpose_in(&pad_in, lin, t, &tr);
        }
        tiles::<F, L>(at, rows, cols, dim, t, u);
        if whole {
            transpose_out(u, lout, out, &tr);
        } else {
            pad_out.resize(L * lout, 0.0);
            transpose_out(u, lout, &mut pad_out, &tr);
            out.copy_from_slice(&pad_out[..out.len()]);
        }
        let smax = if rank == 0 || nodes == 0 {
            [0.0; L]
        } else {
            tiles::<F, L>(gt, rank, cols, dim, t, c);
            match maps.v {
                NodeMaps::Full(vt, _) => {
                    tiles::<F, L>(vt, nodes, rank, dim, c, vv);
                    max_point_norm::<F, L>(vv, dim)
                }
                NodeMaps::Split(vet, vot, re, _) => {
                    let (ce, co) = c.split_at(re * dim);
                    let (e, o) = vv.split_at_mut(nodes * dim);
                    tiles::<F, L>(vet, nodes, re, dim, ce, e);
                    tiles::<F, L>(vot, nodes, rank - re, dim, co, o);
                    max_pair_point_norm::<F, L>(e, o, dim)
                }
            }
        };
        let pmax = max_point_norm::<F, L>(t, dim);
        let amax = max_abs::<L>(t);
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
fn max_point_norm<const F: bool, const L: usize>(x: &[[f64; L]], dim: usize) -> [f64; L] {
    let (mut best, mut nan) = ([0.0f64; L], [0.0f64; L]);
    for p in x.chunks_exact(dim) {
        let mut q = [0.0f64; L];
        for v in p {
            for l in 0..L {
                q[l] = madd::<F>(v[l], v[l], q[l]);
            }
        }
        for l in 0..L {
            best[l] = if q[l] > best[l] { q[l] } else { best[l] };
            nan[l] = if q[l].is_nan() { 1.0 } else { nan[l] };
        }
    }
    std::array::from_fn(|l| {
        if nan[l] != 0.0 {
            f64::NAN
        } else {
            best[l].sqrt()
        }
    })
}

/// Per lane, `max |x|` over the vectors `x` (NaN in a lane holding a NaN): selects only,
/// so that the loop runs on whole vectors.
#[inline(always)]
fn max_abs<const L: usize>(x: &[[f64; L]]) -> [f64; L] {
    let (mut m, mut nan) = ([0.0f64; L], [0.0f64; L]);
    for v in x {
        for l in 0..L {
            let a = v[l].abs();
            m[l] = if a > m[l] { a } else { m[l] };
            nan[l] = if a.is_nan() { 1.0 } else { nan[l] };
        }
    }
    std::array::from_fn(|l| if nan[l] != 0.0 { f64::NAN } else { m[l] })
}

/// Per lane, `max_j max(||e_j + o_j||, ||e_j - o_j||)` over the points `e_j`, `o_j`
/// (`dim` vectors each; the symmetric split's node values); NaN in a lane where a squared
/// norm is NaN.
#[inline(always)]
fn max_pair_point_norm<const F: bool, const L: usize>(
    e: &[[f64; L]],
    o: &[[f64; L]],
    dim: usize,
) -> [f64; L] {
    let (mut best, mut nan) = ([0.0f64; L], [0.0f64; L]);
    for (pe, po) in e.chunks_exact(dim).zip(o.chunks_exact(dim)) {
        let (mut qp, mut qm) = ([0.0f64; L], [0.0f64; L]);
        for (ve, vo) in pe.iter().zip(po) {
            for l in 0..L {
                let (p, m) = (ve[l] + vo[l], ve[l] - vo[l]);
                qp[l] = madd::<F>(p, p, qp[l]);
                qm[l] = madd::<F>(m, m, qm[l]);
            }
        }
        // Selects only (whole-vector max and NaN flag): `qp + qm` is NaN iff either is.
        for l in 0..L {
            let q = if qp[l] > qm[l] { qp[l] } else { qm[l] };
            best[l] = if q > best[l] { q } else { best[l] };
            nan[l] = if (qp[l] + qm[l]).is_nan() {
                1.0
            } else {
                nan[l]
            };
        }
    }
    std::array::from_fn(|l| {
        if nan[l] != 0.0 {
            f64::NAN
        } else {
            best[l].sqrt()
        }
    })
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
    type Kernel<'a> = &'a dyn Fn(&[f64], usize, usize, &[f64], &mut [f64], &mut Vec<f64>);

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
            apply_generic::<false, 4>(at, rows, dim, input, out, s, super::transpose, |_| {})
        });
        check::<false>(&|at, rows, dim, input, out, s| {
            apply_generic::<false, 8>(at, rows, dim, input, out, s, super::transpose, |_| {})
        });
    }

    #[test]
    fn fused_instances_are_the_fused_definition_bit_for_bit() {
        // The fused code at 4 and 8 lanes as compiled without the target features
        // (software FMA: slow, same bits), each instance this CPU has by name, and the
        // dispatch: all equal to the fused definition, so to one another.
        check::<true>(&|at, rows, dim, input, out, s| {
            apply_generic::<true, 4>(at, rows, dim, input, out, s, super::transpose, |_| {})
        });
        check::<true>(&|at, rows, dim, input, out, s| {
            apply_generic::<true, 8>(at, rows, dim, input, out, s, super::transpose, |_| {})
        });
        #[cfg(target_arch = "x86_64")]
        {
            let i = isa();
            if i != Isa::Portable {
                #[allow(unsafe_code, reason = "a `target_feature` function under test")]
                // SAFETY: the CPU has AVX2 and FMA (detected by `isa`).
                check::<true>(&|at, rows, dim, input, out, s| unsafe {
                    apply_avx2(at, rows, dim, input, out, s)
                });
            }
            if i == Isa::Avx512 {
                #[allow(unsafe_code, reason = "a `target_feature` function under test")]
                // SAFETY: the CPU has AVX-512F, AVX2 and FMA (detected by `isa`).
                check::<true>(&|at, rows, dim, input, out, s| unsafe {
                    apply_avx512(at, rows, dim, input, out, s)
                });
            }
            if i != Isa::Portable {
                check::<true>(&|at, rows, dim, input, out, s| apply(at, rows, dim, input, out, s));
            }
        }
    }

    #[test]
    fn sized_instances_are_the_fused_definition_bit_for_bit() {
        // Every map of the `sized!` table (dim 3, C <= 11), and its neighbours outside it,
        // through each instance this CPU has: the definition's bits.
        let mut scratch = Vec::new();
        for cols in 2..=12 {
            for rows in 1..cols {
                let a: Vec<f64> = (0..rows * cols)
                    .map(|i| ((i * 37 % 23) as f64 - 11.0) / 7.0)
                    .collect();
                let at = transpose(&a, rows, cols);
                for curves in [1, 7, 8, 9, 33] {
                    let input: Vec<f64> = (0..curves * cols * 3)
                        .map(|i| ((i * 7919 % 1001) as f64 - 500.0) / 97.0)
                        .collect();
                    let want = reference::<true>(&a, rows, cols, &input, 3);
                    let mut out = vec![f64::NAN; curves * rows * 3];
                    apply(&at, rows, 3, &input, &mut out, &mut scratch);
                    if isa() == Isa::Portable {
                        continue;
                    }
                    assert_eq!(
                        out.iter().map(|x| x.to_bits()).collect::<Vec<_>>(),
                        want.iter().map(|x| x.to_bits()).collect::<Vec<_>>(),
                        "{rows}x{cols} curves {curves}"
                    );
                }
            }
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
    fn split_node_norms_equal_the_mirrored_definition() {
        // The split's node values e +- o, against the full map [Ve Vo; Ve -Vo] applied by
        // the reference, for every split of the columns (empty parts included).
        let (rows, cols, rank, pairs) = (4, 9, 5, 7);
        let mk = |r: usize, c: usize, s: f64| -> Vec<f64> {
            (0..r * c).map(|i| (i as f64 * s).sin()).collect()
        };
        let (a, g, v) = (
            mk(rows, cols, 0.37),
            mk(rank, cols, 0.53),
            mk(pairs, rank, 0.71),
        );
        let (at, gt) = (transpose(&a, rows, cols), transpose(&g, rank, cols));
        let mut scratch = Vec::new();
        for re in 0..=rank {
            let part = |range: std::ops::Range<usize>| -> Vec<f64> {
                let w = range.len();
                let p: Vec<f64> = (0..pairs)
                    .flat_map(|j| v[j * rank..(j + 1) * rank][range.clone()].to_vec())
                    .collect();
                transpose(&p, pairs, w)
            };
            let (vet, vot) = (part(0..re), part(re..rank));
            let full: Vec<f64> = (0..2 * pairs)
                .flat_map(|j| {
                    let row = &v[(j % pairs) * rank..(j % pairs + 1) * rank];
                    let s = |k: usize| if j >= pairs && k >= re { -1.0 } else { 1.0 };
                    row.iter()
                        .enumerate()
                        .map(move |(k, x)| s(k) * x)
                        .collect::<Vec<_>>()
                })
                .collect();
            let maps = BoundMaps {
                a: (&at, rows),
                g: (&gt, rank),
                v: NodeMaps::Split(&vet, &vot, re, pairs),
            };
            for dim in [1, 3, 5] {
                for curves in [1, 4, 9] {
                    let input: Vec<f64> = (0..curves * cols * dim)
                        .map(|i| (i as f64 * 1.7).cos() * 3.0)
                        .collect();
                    let mut out = vec![0.0; curves * rows * dim];
                    let mut norms = vec![CurveNorms::default(); curves];
                    apply_with_norms(&maps, dim, &input, &mut out, &mut norms, &mut scratch);
                    for (cv, nrm) in input.chunks_exact(cols * dim).zip(&norms) {
                        let coef = reference::<false>(&g, rank, cols, cv, dim);
                        let vals = reference::<false>(&full, 2 * pairs, rank, &coef, dim);
                        let norm = |x: &[f64]| x.iter().map(|y| y * y).sum::<f64>().sqrt();
                        let smax = vals.chunks_exact(dim).map(norm).fold(0.0, f64::max);
                        assert!(
                            (nrm.smax - smax).abs() <= 1e-13 * smax.max(1.0),
                            "re {re} dim {dim} curves {curves}: {nrm:?} {smax}"
                        );
                    }
                    let mut bad = input.clone();
                    bad[cols * dim * (curves - 1)] = f64::NAN;
                    apply_with_norms(&maps, dim, &bad, &mut out, &mut norms, &mut scratch);
                    assert!(norms[curves - 1].smax.is_nan() || rank == 0);
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
            v: NodeMaps::Full(&vt, nodes),
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

    #[test]
    fn sized_norm_instances_are_the_general_instance_bit_for_bit() {
        // Every reduction map of the `sized!` table with a full and a split node map,
        // dim 3: the dispatch (sized instance) gives the general instance's bits, outputs
        // and norms alike.
        #[cfg(target_arch = "x86_64")]
        {
            let i = isa();
            if i == Isa::Portable {
                return;
            }
            let mk = |r: usize, c: usize, s: f64| -> Vec<f64> {
                (0..r * c).map(|i| (i as f64 * s).sin()).collect()
            };
            let mut scratch = Vec::new();
            for cols in 2..=12 {
                for rows in 1..cols {
                    let (rank, nodes) = (cols - rows, 2 * cols + 1);
                    let at = transpose(&mk(rows, cols, 0.37), rows, cols);
                    let gt = transpose(&mk(rank, cols, 0.53), rank, cols);
                    let vt = transpose(&mk(nodes, rank, 0.71), nodes, rank);
                    let re = rank.div_ceil(2);
                    let vet = transpose(&mk(nodes, re, 0.29), nodes, re);
                    let vot = transpose(&mk(nodes, rank - re, 0.31), nodes, rank - re);
                    for v in [
                        NodeMaps::Full(&vt, nodes),
                        NodeMaps::Split(&vet, &vot, re, nodes),
                    ] {
                        let maps = BoundMaps {
                            a: (&at, rows),
                            g: (&gt, rank),
                            v,
                        };
                        for curves in [1, 8, 13] {
                            let input: Vec<f64> = (0..curves * cols * 3)
                                .map(|i| (i as f64 * 1.7).cos() * 3.0)
                                .collect();
                            let run = |general: bool, scratch: &mut Vec<f64>| {
                                let mut out = vec![0.0; curves * rows * 3];
                                let mut norms = vec![CurveNorms::default(); curves];
                                let (o, n) = (&mut out, &mut norms);
                                match (general, i) {
                                    (false, _) => apply_with_norms(&maps, 3, &input, o, n, scratch),
                                    (true, Isa::Avx512) => with_norms_generic::<true, 8>(
                                        &maps,
                                        3,
                                        &input,
                                        o,
                                        n,
                                        scratch,
                                        super::transpose,
                                    ),
                                    (true, _) => with_norms_generic::<true, 4>(
                                        &maps,
                                        3,
                                        &input,
                                        o,
                                        n,
                                        scratch,
                                        super::transpose,
                                    ),
                                }
                                let bits =
                                    |x: &[f64]| x.iter().map(|y| y.to_bits()).collect::<Vec<_>>();
                                let nb: Vec<[u64; 3]> = norms
                                    .iter()
                                    .map(|c| [c.smax.to_bits(), c.pmax.to_bits(), c.amax.to_bits()])
                                    .collect();
                                (bits(&out), nb)
                            };
                            assert_eq!(
                                run(false, &mut scratch),
                                run(true, &mut scratch),
                                "{rows}x{cols} curves {curves}"
                            );
                        }
                    }
                }
            }
        }
    }
}
