//! The timing helper shared by every part of `cagd demo`.

use std::time::Instant;

/// Median time of `reps` runs of `f`, in microseconds.
pub(crate) fn time_us(reps: usize, mut f: impl FnMut()) -> f64 {
    let mut times: Vec<f64> = (0..reps)
        .map(|_| {
            let t = Instant::now();
            f();
            t.elapsed().as_secs_f64() * 1e6
        })
        .collect();
    times.sort_by(f64::total_cmp);
    times[times.len() / 2]
}
