//! Helpers shared by the benchmarks: reproducible input and a median timer.

use std::time::Instant;

/// `len` pseudo-random numbers in `[-1, 1)` (xorshift64, reproducible per `seed`).
pub(crate) fn random_input(len: usize, seed: u64) -> Vec<f64> {
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
pub(crate) fn median_ns(mut f: impl FnMut()) -> f64 {
    f();
    let mut t: Vec<f64> = (0..15)
        .map(|_| {
            let s = Instant::now();
            f();
            s.elapsed().as_secs_f64() * 1e9
        })
        .collect();
    t.sort_by(f64::total_cmp);
    t[t.len() / 2]
}
