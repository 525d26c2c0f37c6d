//! Helpers shared by the benchmarks of every crate: reproducible input, a median timer and
//! the time of a plain copy of the same bytes (the yardstick every benchmark reports a
//! ratio to), and the GEMM floor of the batch benchmarks.

use std::hint::black_box;
use std::time::Instant;

/// `len` pseudo-random numbers in `[-1, 1)` (xorshift64, reproducible per `seed`).
pub fn random_input(len: usize, seed: u64) -> Vec<f64> {
    let mut s: u64 = 0x9E37_79B9_7F4A_7C15 ^ seed;
    (0..len)
        .map(|_| {
            s ^= s << 13;
            s ^= s >> 7;
            s ^= s << 17;
            (s >> 11) as f64 / (1u64 << 53) as f64 * 2.0 - 1.0
        })
        .collect()
}

/// Median wall time of 15 runs of `f` (after one warm-up run), in nanoseconds.
pub fn median_ns(f: impl FnMut()) -> f64 {
    median_ns_of(15, f)
}

/// Median wall time of `runs` runs of `f` (after one warm-up run), in nanoseconds.
pub fn median_ns_of(runs: usize, mut f: impl FnMut()) -> f64 {
    f();
    let mut t: Vec<f64> = (0..runs.max(1))
        .map(|_| {
            let s = Instant::now();
            f();
            s.elapsed().as_secs_f64() * 1e9
        })
        .collect();
    t.sort_by(f64::total_cmp);
    t[t.len() / 2]
}

/// Median wall time (ns) of copying `input` and `output` into fresh buffers of their sizes
/// with `copy_from_slice` (a `memcpy` of the bytes a reduction reads and writes).
pub fn memcpy_ns(input: &[f64], output: &[f64]) -> f64 {
    let (mut copy_in, mut copy_out) = (vec![0.0; input.len()], vec![0.0; output.len()]);
    median_ns(|| {
        copy_in.copy_from_slice(black_box(input));
        copy_out.copy_from_slice(black_box(output));
        black_box(&copy_in);
        black_box(&copy_out);
    })
}

/// Median wall times (ns) of each of `fs`, measured in `rounds` interleaved rounds (one run
/// of each per round, after one warm-up run each), so that a change of machine load during
/// the measurement affects every variant alike: the ratios between them stay meaningful on
/// a shared machine.
pub fn interleaved_ns(rounds: usize, fs: &mut [&mut dyn FnMut()]) -> Vec<f64> {
    for f in fs.iter_mut() {
        f();
    }
    let mut t = vec![Vec::with_capacity(rounds); fs.len()];
    for _ in 0..rounds.max(1) {
        for (f, ti) in fs.iter_mut().zip(&mut t) {
            let s = Instant::now();
            f();
            ti.push(s.elapsed().as_secs_f64() * 1e9);
        }
    }
    t.into_iter()
        .map(|mut v| {
            v.sort_by(f64::total_cmp);
            v[v.len() / 2]
        })
        .collect()
}

/// The point-major GEMM floor of the batch benchmarks (issue 17): `Q = A P` with `A`
/// `m1 x n1`, `P` `n1 x cols`, `Q` `m1 x cols`, all row-major and contiguous, in one
/// `matrixmultiply::dgemm` (the kernel crate the batch calls use).
///
/// # Panics
/// When the lengths do not match (`a.len() != m1 n1`, `q.len() != m1 cols`, `cols = p.len() /
/// n1`).
#[allow(unsafe_code, reason = "the floor is one matrixmultiply::dgemm call")]
pub fn gemm_floor(a: &[f64], n1: usize, m1: usize, p: &[f64], q: &mut [f64]) {
    let cols = p.len() / n1;
    assert!(a.len() == m1 * n1 && p.len() == n1 * cols && q.len() == m1 * cols);
    let s = |x: usize| isize::try_from(x).unwrap_or(isize::MAX);
    // SAFETY: the sizes are checked above; the three matrices are row-major, contiguous.
    unsafe {
        matrixmultiply::dgemm(
            m1,
            n1,
            cols,
            1.0,
            a.as_ptr(),
            s(n1),
            1,
            p.as_ptr(),
            s(cols),
            1,
            0.0,
            q.as_mut_ptr(),
            s(cols),
            1,
        );
    }
}
