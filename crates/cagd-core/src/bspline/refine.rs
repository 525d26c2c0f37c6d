//! Knot refinement in one pass (Piegl & Tiller, "The NURBS Book", §5.3, Algorithm A5.4):
//! all new knots at once, working from the back, `O((n + r) p)` per coordinate instead of
//! `O(n r)` for one Boehm insertion after another (each of which copies the whole net).
//! Goes beyond the seeds; used where many knots are inserted into a large net (a surface
//! measured against a reduction with thousands of spans).

use super::insert::insert_once;

/// The spline `(u, work)` of degree `p` (points of `width` coordinates) with the sorted
/// values `x` inserted, each once more: new knots and points, the same spline.
///
/// Requires every `x_j` in the domain `[u_p, u_{n+1}]`, `x` sorted ascending, and every
/// resulting multiplicity at most `p + 1` (checked by the callers); where one reaches
/// `p + 1` (always for `p = 0`), and for empty `x`, it runs the one-at-a-time route, which
/// the tests compare this one with.
pub(crate) fn refine_work(
    u: &[f64],
    p: usize,
    work: &[f64],
    width: usize,
    x: &[f64],
) -> (Vec<f64>, Vec<f64>) {
    // A multiplicity reaching p + 1 (allowed by the callers' checks: the spline splits)
    // takes the one-at-a-time route too.
    let too_many = x
        .chunk_by(|a, b| a == b)
        .any(|run| run.len() + u.iter().filter(|v| **v == run[0]).count() > p);
    if p == 0 || x.is_empty() || too_many {
        let (mut knots, mut pts) = (u.to_vec(), work.to_vec());
        for &t in x {
            (knots, pts) = insert_once(&knots, p, &pts, width, t);
        }
        return (knots, pts);
    }
    let n = work.len() / width - 1;
    let m = n + p + 1;
    let r = x.len() - 1;
    // The span index k with u_k <= t < u_{k+1}, in p..=n (t = u_{n+1}: n).
    let span = |t: f64| -> usize {
        if t >= u[n + 1] {
            n
        } else {
            (u.partition_point(|v| *v <= t) - 1).clamp(p, n)
        }
    };
    let a = span(x[0]);
    let b = span(x[r]) + 1;
    let mut q = vec![0.0; (n + r + 2) * width];
    let mut ub = vec![0.0; m + r + 2];
    q[..(a - p + 1) * width].copy_from_slice(&work[..(a - p + 1) * width]);
    q[(b + r) * width..].copy_from_slice(&work[(b - 1) * width..]);
    ub[..=a].copy_from_slice(&u[..=a]);
    ub[b + p + r + 1..].copy_from_slice(&u[b + p..]);
    let mut i = b + p - 1;
    let mut k = b + p + r;
    for j in (0..=r).rev() {
        while x[j] <= u[i] && i > a {
            let (dst, src) = ((k - p - 1) * width, (i - p - 1) * width);
            q[dst..dst + width].copy_from_slice(&work[src..src + width]);
            ub[k] = u[i];
            k -= 1;
            i -= 1;
        }
        q.copy_within((k - p) * width..(k - p + 1) * width, (k - p - 1) * width);
        for l in 1..=p {
            let ind = k - p + l;
            let alfa = ub[k + l] - x[j];
            if alfa == 0.0 {
                q.copy_within(ind * width..(ind + 1) * width, (ind - 1) * width);
            } else {
                let alfa = alfa / (ub[k + l] - u[i + l - p]);
                let beta = 1.0 - alfa;
                for c in 0..width {
                    q[(ind - 1) * width + c] =
                        alfa * q[(ind - 1) * width + c] + beta * q[ind * width + c];
                }
            }
        }
        ub[k] = x[j];
        k -= 1;
    }
    (ub, q)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A deterministic pseudo-random stream in `[0, 1)`.
    fn stream(seed: u64) -> impl FnMut() -> f64 {
        let mut s = seed.wrapping_mul(0x9E37_79B9_7F4A_7C15) | 1;
        move || {
            s ^= s << 13;
            s ^= s >> 7;
            s ^= s << 17;
            (s >> 11) as f64 / (1u64 << 53) as f64
        }
    }

    #[test]
    fn equals_one_insertion_after_another() {
        for seed in 0..400usize {
            let mut rnd = stream(seed as u64 + 1);
            let p = 1 + seed % 6;
            let width = 1 + seed % 4;
            let spans = 1 + seed % 7;
            // Clamped or not, interior knots with multiplicities 1..=p - 1 or simple.
            let mut u: Vec<f64> = Vec::new();
            let clamped = seed % 2 == 0;
            for i in 0..=p {
                u.push(if clamped {
                    0.0
                } else {
                    -((p - i) as f64) * 0.3
                });
            }
            for s in 1..spans {
                let t = s as f64 + 0.3 * rnd();
                let mult = if seed % 3 == 0 { 1 + (seed + s) % p } else { 1 };
                u.extend(std::iter::repeat_n(t, mult));
            }
            let end = spans as f64 + 0.5;
            for i in 0..=p {
                u.push(if clamped { end } else { end + i as f64 * 0.3 });
            }
            let n = u.len() - p - 1;
            let work: Vec<f64> = (0..n * width).map(|_| rnd() * 4.0 - 2.0).collect();
            let (lo, hi) = (u[p], u[n]);
            // New knots: distinct from the existing ones, some at the domain ends' inside.
            let mut x: Vec<f64> = (0..1 + seed % 9)
                .map(|_| lo + (hi - lo) * rnd())
                .filter(|t| !u.contains(t))
                .collect();
            x.sort_by(f64::total_cmp);
            x.dedup();
            if x.is_empty() {
                continue;
            }
            let (k1, q1) = refine_work(&u, p, &work, width, &x);
            let (mut k2, mut q2) = (u.clone(), work.clone());
            for &t in &x {
                (k2, q2) = insert_once(&k2, p, &q2, width, t);
            }
            assert_eq!(k1, k2, "seed {seed}: knots");
            assert_eq!(q1.len(), q2.len(), "seed {seed}");
            for (a, b) in q1.iter().zip(&q2) {
                assert!(
                    (a - b).abs() <= 1e-13 * (1.0 + b.abs()),
                    "seed {seed}: {a} vs {b}"
                );
            }
        }
    }

    #[test]
    fn degree_zero_and_no_knots_take_the_simple_route() {
        let u = [0.0, 1.0, 2.0];
        let w = [5.0, 7.0];
        assert_eq!(refine_work(&u, 0, &w, 1, &[]), (u.to_vec(), w.to_vec()));
        let (k, q) = refine_work(&u, 0, &w, 1, &[0.5]);
        assert_eq!(k, vec![0.0, 0.5, 1.0, 2.0]);
        assert_eq!(q, vec![5.0, 5.0, 7.0]);
    }
}
