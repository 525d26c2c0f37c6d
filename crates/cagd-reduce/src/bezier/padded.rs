//! The padded-point kernel: one linear map `Q_c = A P_c` applied to many 3-D curves stored
//! curve-major, one *point* per 256-bit vector (AVX2 + FMA).
//! Goes beyond the seed: the data path of [`crate::reduce_batch`] for `dim = 3` (see
//! `gemm.rs`).
//!
//! A point `(x, y, z)` is loaded as the four doubles that start at its `x` (the fourth is
//! the next point's `x`: a padding lane, computed and never kept), so the input needs no
//! transpose; output point `i` of a curve is `sum_j a_ij p_j`, one fused multiply-add per
//! `j` with the coefficient `a_ij` in all four lanes (the map's table of splatted
//! coefficients, [`splat`]). Three curves times up to four output points are summed in
//! registers at a time (up to eight with AVX-512VL's 32 registers, for maps of at most
//! eight rows: the `wide` instance). An output point is stored as four doubles too: its padding lane
//! lands on the next point's `x`, which the next store (same curve, `i` increasing)
//! overwrites; the last point of a curve is stored as three doubles.
//!
//! Why: the transposing kernel of `lanes.rs` spends about one shuffle per double moved
//! (4 x 4 blocks in and out), and the shuffles' port is the bottleneck at the small pairs
//! and the memory traffic of its scratch at the large ones; this kernel does
//! `(m + 1)(n + 1)` 256-bit multiply-adds per curve (a quarter of their lanes are padding)
//! and no shuffle. Figures in the benches README (`batch`, "Eighth session").
//!
//! Every output coordinate is the same chain as in `lanes.rs` (`acc = 0`, then
//! `acc = fma(a_ij, x_j, acc)` for `j` increasing, the map's zeros included), so the two
//! kernels give the same bits, and a NaN or infinity anywhere in coordinate `k` of a curve
//! reaches every summed output of coordinate `k` of that curve. The wide instance copies
//! a map's unit end rows (an operator with interpolated ends: [`Units`]) instead of
//! summing them: the same bits for finite inputs, and at (5,4) L2-C0 three rows of five
//! summed.
//!
//! The output is checked for non-finite values in the same pass: the sum of every stored
//! vector (padding lanes included) is finite when every output is; when it is not (a
//! non-finite output, or only an overflow of the sum or of a padding lane), the caller
//! scans the output.

use super::lanes::sized;

/// Curves summed at a time (three curves x four points = 12 accumulators + 3 points: 15 of
/// the 16 vector registers of AVX2).
pub(crate) const CURVES: usize = 3;

/// Output points summed at a time per curve, at most.
const POINTS: usize = 4;

/// Whether [`apply3`] runs on this CPU (AVX2 + FMA; detected once by the standard library).
pub(crate) fn available() -> bool {
    #[cfg(target_arch = "x86_64")]
    {
        use std::arch::is_x86_feature_detected as has;
        has!("avx2") && has!("fma")
    }
    #[cfg(not(target_arch = "x86_64"))]
    false
}

/// The table [`apply3`] takes: each coefficient of `at` (the map transposed, `cols x rows`
/// row-major) four times.
pub(crate) fn splat(at: &[f64]) -> Vec<f64> {
    at.iter().flat_map(|&a| [a; 4]).collect()
}

/// Whether the map's first and last rows are unit rows (one coefficient `1`, zeros
/// elsewhere: the end points an operator with interpolated ends keeps, e.g. L2 with
/// `r = p = 0`), with at least one row between them. The kernel then sums only the rows
/// between and copies the two end rows from their input points as `p_j + 0`: the bits of
/// the kernel's chain for finite inputs (its zero terms add `+0`, its one term gives `p_j`
/// with `-0` made `+0`). A non-finite input coordinate still reaches the summed rows'
/// outputs of its coordinate, so the check still sees it.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) struct Units {
    /// The columns of the ones of the first and the last row.
    ends: Option<[usize; 2]>,
}

impl Units {
    /// The end rows of the row-major `rows x cols` matrix `a`.
    pub(crate) fn of(a: &[f64], rows: usize, cols: usize) -> Self {
        let unit = |i: usize| -> Option<usize> {
            let row = a.get(i * cols..(i + 1) * cols)?;
            let one = row.iter().position(|&v| v == 1.0)?;
            row.iter()
                .enumerate()
                .all(|(j, &v)| j == one || v == 0.0)
                .then_some(one)
        };
        let ends = match rows {
            0..=2 => None,
            _ => unit(0).zip(unit(rows - 1)).map(|(a, b)| [a, b]),
        };
        Self { ends }
    }

    /// No unit rows: every row is summed.
    #[cfg(test)]
    pub(crate) fn none() -> Self {
        Self { ends: None }
    }

    /// The columns of the ones of the end rows, when both are unit rows.
    #[cfg(test)]
    pub(crate) fn ends(&self) -> Option<[usize; 2]> {
        self.ends
    }
}

/// Applies the map whose [`splat`] table is `table` (`rows` output points) to the first
/// curves of `input` (3-D, `cols * 3` doubles each): the whole groups of [`CURVES`] among
/// all curves but the last. Returns how many curves it did and whether the sum of their
/// outputs is finite (when it is, every one of their outputs is); the caller runs the
/// others (at least one) through another kernel with the same operations. `None` when
/// the CPU lacks AVX2 + FMA.
pub(crate) fn apply3(
    table: &[f64],
    units: &Units,
    rows: usize,
    input: &[f64],
    output: &mut [f64],
) -> Option<(usize, bool)> {
    let cols = table.len() / (4 * rows.max(1));
    let (lin, lout) = (cols * 3, rows * 3);
    if !available() || lin == 0 || lout == 0 {
        return None;
    }
    let curves = input.len() / lin;
    debug_assert_eq!(output.len(), curves * lout);
    // Every curve reads one double past its own points (the padding lane of its last
    // point), so the last curve of `input` is not done here.
    let done = curves.saturating_sub(1) / CURVES * CURVES;
    if done == 0 {
        return Some((0, true));
    }
    #[cfg(target_arch = "x86_64")]
    {
        let finite = groups(
            table,
            units,
            rows,
            cols,
            &input[..done * lin + 1],
            &mut output[..done * lout],
        );
        Some((done, finite))
    }
    #[cfg(not(target_arch = "x86_64"))]
    None
}

/// The groups of [`CURVES`] curves (`input` has one double more than they take), through
/// a sized instance where there is one: with AVX-512VL (32 vector registers) and at most
/// [`POINTS_WIDE`] output points, all of a curve's points in one block (module `wide`);
/// else in blocks of at most [`POINTS`].
#[cfg(target_arch = "x86_64")]
fn groups(
    table: &[f64],
    units: &Units,
    rows: usize,
    cols: usize,
    input: &[f64],
    output: &mut [f64],
) -> bool {
    use std::arch::is_x86_feature_detected as has;
    use wide::sized as wide_sized;
    let mut finite = true;
    #[allow(unsafe_code, reason = "the call of a `target_feature` function")]
    // SAFETY: `apply3` checked `available` (AVX2 + FMA), the only requirement of the
    // narrow functions; the wide ones are called only when AVX-512F and AVX-512VL are
    // detected here. All of them are safe code.
    unsafe {
        if rows <= POINTS_WIDE && has!("avx512f") && has!("avx512vl") {
            if !sized!(
                wide_sized,
                rows,
                rows * cols,
                (table, units, input, output, &mut finite)
            ) {
                finite = wide::general(table, units, rows, cols, input, output);
            }
        } else if !sized!(
            groups_sized,
            rows,
            rows * cols,
            (table, units, input, output, &mut finite)
        ) {
            finite = groups_avx2(table, units, rows, cols, input, output);
        }
    }
    finite
}

/// [`run`] with the sizes as values.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2,fma")]
fn groups_avx2(
    table: &[f64],
    units: &Units,
    rows: usize,
    cols: usize,
    input: &[f64],
    output: &mut [f64],
) -> bool {
    // The narrow instance sums every row, the end rows too: with a copy of them its
    // blocks were no longer inlined (at (15,10) 34 against 38 ns per curve).
    run::<0, 0, false>(table, units, rows, cols, input, output)
}

/// [`run`] with `rows = RW` and `cols = CL` as constants (its loops unroll and its index
/// checks fold: at (4,3) 4.4 against 6.4 ns per curve).
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2,fma")]
fn groups_sized<const RW: usize, const CL: usize>(
    table: &[f64],
    units: &Units,
    input: &[f64],
    output: &mut [f64],
    finite: &mut bool,
) {
    // Every row summed, as in `groups_avx2`.
    *finite = run::<RW, CL, false>(table, units, RW, CL, input, output);
}

/// The loop over the groups; `RW, CL > 0` are the sizes as constants (then `rows`, `cols`
/// are not read).
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2,fma")]
#[inline]
fn run<const RW: usize, const CL: usize, const E: bool>(
    table: &[f64],
    units: &Units,
    rows: usize,
    cols: usize,
    input: &[f64],
    output: &mut [f64],
) -> bool {
    use std::arch::x86_64::_mm256_setzero_pd;
    let (rows, cols) = if RW > 0 { (RW, CL) } else { (rows, cols) };
    debug_assert_eq!(table.len(), rows * cols * 4);
    let (lin, lout) = (cols * 3, rows * 3);
    let mut chk = _mm256_setzero_pd();
    // Rows `lo..hi` are summed; with `E` the end rows are copied (see `Units`).
    let (lo, hi) = if E { (1, rows - 1) } else { (0, rows) };
    let [j0, j1] = units.ends.unwrap_or([0, 0]);
    for (g, out) in output.chunks_exact_mut(CURVES * lout).enumerate() {
        let inp = &input[g * CURVES * lin..(g + 1) * CURVES * lin + 1];
        if E {
            copy_row(0, j0, rows, cols, inp, out);
        }
        let mut i0 = lo;
        while i0 < hi {
            // Blocks of four points; five left go as three and two (a block of one point
            // has too few independent sums to hide the multiply-add latency).
            let r = match hi - i0 {
                5 => 3,
                left => left.min(POINTS),
            };
            let at = (table, rows, cols, i0);
            match r {
                4 => block::<4, RW, CL>(at, inp, out, &mut chk),
                3 => block::<3, RW, CL>(at, inp, out, &mut chk),
                2 => block::<2, RW, CL>(at, inp, out, &mut chk),
                _ => block::<1, RW, CL>(at, inp, out, &mut chk),
            }
            i0 += r;
        }
        if E {
            copy_row(rows - 1, j1, rows, cols, inp, out);
        }
    }
    let lanes: [f64; 4] = bytemuck::cast(chk);
    lanes.iter().all(|v| v.is_finite())
}

/// Row `i` of the [`CURVES`] curves of `inp` (plus one double), a unit row with its one
/// in column `j` (see [`Units`]), copied from input point `j` as `p_j + 0`. Stored as
/// four doubles but in the map's last row: the fourth lands on the next row's `x`, which
/// is stored after it (the first row is copied before the summed rows, the last after).
#[inline(always)]
fn copy_row(i: usize, j: usize, rows: usize, cols: usize, inp: &[f64], out: &mut [f64]) {
    let (lin, lout) = (cols * 3, rows * 3);
    let n = if i + 1 < rows { 4 } else { 3 };
    for c in 0..CURVES {
        let (o, a) = (c * lout + 3 * i, c * lin + 3 * j);
        for (q, p) in out[o..o + n].iter_mut().zip(&inp[a..a + n]) {
            *q = p + 0.0;
        }
    }
}

/// Output points `i0 .. i0 + R` of the [`CURVES`] curves of `inp` (plus one double) into
/// `out`, their sum added to `chk`. Sizes as in [`run`].
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2,fma")]
#[inline]
fn block<const R: usize, const RW: usize, const CL: usize>(
    (table, rows, cols, i0): (&[f64], usize, usize, usize),
    inp: &[f64],
    out: &mut [f64],
    chk: &mut std::arch::x86_64::__m256d,
) {
    use std::arch::x86_64::{__m256d, _mm256_add_pd, _mm256_fmadd_pd, _mm256_setzero_pd};
    let (rows, cols) = if RW > 0 { (RW, CL) } else { (rows, cols) };
    let (lin, lout) = (cols * 3, rows * 3);
    let vec = |x: &[f64]| -> __m256d {
        let q: [f64; 4] = x.try_into().unwrap_or([0.0; 4]);
        bytemuck::cast(q)
    };
    let mut acc = [[_mm256_setzero_pd(); CURVES]; R];
    for j in 0..cols {
        // Point `j` of curve `c` and the next double (its padding lane).
        let x: [__m256d; CURVES] =
            std::array::from_fn(|c| vec(&inp[c * lin + 3 * j..c * lin + 3 * j + 4]));
        let tj = &table[(j * rows + i0) * 4..(j * rows + i0 + R) * 4];
        for (q, accq) in acc.iter_mut().enumerate() {
            let a = vec(&tj[q * 4..q * 4 + 4]);
            for (xc, accqc) in x.iter().zip(accq.iter_mut()) {
                *accqc = _mm256_fmadd_pd(a, *xc, *accqc);
            }
        }
    }
    // The block's sum, then one add into `chk` (an add into `chk` per stored vector
    // would chain the loop on the add's latency).
    let part: [__m256d; R] =
        std::array::from_fn(|q| _mm256_add_pd(_mm256_add_pd(acc[q][0], acc[q][1]), acc[q][2]));
    *chk = _mm256_add_pd(
        *chk,
        part[1..].iter().fold(part[0], |s, p| _mm256_add_pd(s, *p)),
    );
    for c in 0..CURVES {
        for (q, accq) in acc.iter().enumerate() {
            let i = i0 + q;
            let v: [f64; 4] = bytemuck::cast(accq[c]);
            let o = c * lout + 3 * i;
            if i + 1 < rows {
                // The padding lane lands on the next point's `x`, stored after this.
                out[o..o + 4].copy_from_slice(&v);
            } else {
                out[o..o + 3].copy_from_slice(&v[..3]);
            }
        }
    }
}

/// Output points per block with 32 vector registers (3 curves x 8 points = 24 accumulators):
/// measured at (10,5), six points, 11.3 against 16–21 ns per curve in blocks of 4 + 2; maps
/// with more rows keep the blocks of four (at (30,15) 86 against 122–140 ns in blocks of 8).
const POINTS_WIDE: usize = 8;

/// The instances of the kernel for one set of CPU features and one largest block: `general`
/// (the sizes as values) and `sized::<RW, CL>` (the sizes as constants: its loops unroll
/// and its index checks fold; at (4,3) 4.4 against 6.4 ns per curve), the groups' loop
/// `run` and the register block `block` (a `target_feature` function cannot be forced
/// inline, so each instance has its own copy, compiled with its features).
macro_rules! kernel {
    ($name:ident, $features:literal, $maxp:expr, $($r:literal)*) => {
        #[cfg(target_arch = "x86_64")]
        mod $name {
            use super::{CURVES, Units, copy_row};

            /// [`run`] with the sizes as values.
            #[target_feature(enable = $features)]
            pub(super) fn general(
                table: &[f64],
                units: &Units,
                rows: usize,
                cols: usize,
                input: &[f64],
                output: &mut [f64],
            ) -> bool {
                match units.ends.is_some() {
                    true => run::<0, 0, true>(table, units, rows, cols, input, output),
                    false => run::<0, 0, false>(table, units, rows, cols, input, output),
                }
            }

            /// [`run`] with `rows = RW` and `cols = CL` as constants.
            #[target_feature(enable = $features)]
            pub(super) fn sized<const RW: usize, const CL: usize>(
                table: &[f64],
                units: &Units,
                input: &[f64],
                output: &mut [f64],
                finite: &mut bool,
            ) {
                *finite = match units.ends.is_some() {
                    true => run::<RW, CL, true>(table, units, RW, CL, input, output),
                    false => run::<RW, CL, false>(table, units, RW, CL, input, output),
                };
            }

            /// The loop over the groups; `RW, CL > 0` are the sizes as constants (then
            /// `rows`, `cols` are not read).
            #[target_feature(enable = $features)]
            #[inline]
            fn run<const RW: usize, const CL: usize, const E: bool>(
                table: &[f64],
                units: &Units,
                rows: usize,
                cols: usize,
                input: &[f64],
                output: &mut [f64],
            ) -> bool {
                use std::arch::x86_64::_mm256_setzero_pd;
                let (rows, cols) = if RW > 0 { (RW, CL) } else { (rows, cols) };
                debug_assert_eq!(table.len(), rows * cols * 4);
                let (lin, lout) = (cols * 3, rows * 3);
                let mut chk = _mm256_setzero_pd();
                // Rows `lo..hi` are summed; with `E` the end rows are copied (see `Units`).
                let (lo, hi) = if E { (1, rows - 1) } else { (0, rows) };
                let [j0, j1] = units.ends.unwrap_or([0, 0]);
                for (g, out) in output.chunks_exact_mut(CURVES * lout).enumerate() {
                    let inp = &input[g * CURVES * lin..(g + 1) * CURVES * lin + 1];
                    if E {
                        copy_row(0, j0, rows, cols, inp, out);
                    }
                    let mut i0 = lo;
                    while i0 < hi {
                        // Blocks of at most `$maxp` points; five left (of blocks of four)
                        // go as three and two (a block of one point has too few independent
                        // sums to hide the multiply-add latency).
                        let r = match hi - i0 {
                            left if left <= $maxp => left,
                            5 => 3,
                            _ => $maxp,
                        };
                        let at = (table, rows, cols, i0);
                        match r {
                            $($r => block::<$r, RW, CL>(at, inp, out, &mut chk),)*
                            _ => block::<1, RW, CL>(at, inp, out, &mut chk),
                        }
                        i0 += r;
                    }
                    if E {
                        copy_row(rows - 1, j1, rows, cols, inp, out);
                    }
                }
                let lanes: [f64; 4] = bytemuck::cast(chk);
                lanes.iter().all(|v| v.is_finite())
            }

            /// Output points `i0 .. i0 + R` of the [`CURVES`] curves of `inp` (plus one
            /// double) into `out`, their sum added to `chk`. Sizes as in [`run`].
            #[target_feature(enable = $features)]
            #[inline]
            fn block<const R: usize, const RW: usize, const CL: usize>(
                (table, rows, cols, i0): (&[f64], usize, usize, usize),
                inp: &[f64],
                out: &mut [f64],
                chk: &mut std::arch::x86_64::__m256d,
            ) {
                use std::arch::x86_64::{
                    __m256d, _mm256_add_pd, _mm256_fmadd_pd, _mm256_setzero_pd,
                };
                let (rows, cols) = if RW > 0 { (RW, CL) } else { (rows, cols) };
                let (lin, lout) = (cols * 3, rows * 3);
                let vec = |x: &[f64]| -> __m256d {
                    let q: [f64; 4] = x.try_into().unwrap_or([0.0; 4]);
                    bytemuck::cast(q)
                };
                let mut acc = [[_mm256_setzero_pd(); CURVES]; R];
                for j in 0..cols {
                    // Point `j` of curve `c` and the next double (its padding lane).
                    let x: [__m256d; CURVES] = std::array::from_fn(|c| {
                        vec(&inp[c * lin + 3 * j..c * lin + 3 * j + 4])
                    });
                    let tj = &table[(j * rows + i0) * 4..(j * rows + i0 + R) * 4];
                    for (q, accq) in acc.iter_mut().enumerate() {
                        let a = vec(&tj[q * 4..q * 4 + 4]);
                        for (xc, accqc) in x.iter().zip(accq.iter_mut()) {
                            *accqc = _mm256_fmadd_pd(a, *xc, *accqc);
                        }
                    }
                }
                // The block's sum, then one add into `chk` (an add into `chk` per stored vector
                // would chain the loop on the add's latency).
                let part: [__m256d; R] = std::array::from_fn(|q| {
                    _mm256_add_pd(_mm256_add_pd(acc[q][0], acc[q][1]), acc[q][2])
                });
                *chk = _mm256_add_pd(*chk, part[1..].iter().fold(part[0], |s, p| _mm256_add_pd(s, *p)));
                for c in 0..CURVES {
                    for (q, accq) in acc.iter().enumerate() {
                        let i = i0 + q;
                        let v: [f64; 4] = bytemuck::cast(accq[c]);
                        let o = c * lout + 3 * i;
                        if i + 1 < rows {
                            // The padding lane lands on the next point's `x`, stored
                            // after this.
                            out[o..o + 4].copy_from_slice(&v);
                        } else {
                            out[o..o + 3].copy_from_slice(&v[..3]);
                        }
                    }
                }
            }
        }
    };
}

kernel!(wide, "avx512f,avx512vl,avx2,fma", 8, 8 7 6 5 4 3 2);
