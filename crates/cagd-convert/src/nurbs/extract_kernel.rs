//! The Bézier extraction kernel of the general route (SPEC-convert §15.3 "Recommendation":
//! the Bézier point `i` of the span `[t_s, t_{s+1}]` is the blossom `b(t_s^(p-i), t_{s+1}^i)`),
//! done as Böhm knot insertion in place on one window of `p + 1` working points (Piegl &
//! Tiller's decomposition, written anew and extended to unclamped ends).
//!
//! Window invariant: before a span `[a, b] = [u_s, u_{s+1}]` is finished, slot `j` of the
//! window holds the blossom `(a^(p-j), u_{s+1}, ..., u_{s+j})`. Inserting `b` (levels
//! `r = 1..=p-mu`, `mu` the multiplicity of `b`) turns slot `j` into `(a^(p-j), b^j)`; the
//! right edge of that triangle, `(b^(mu+r), u_{s'+1}, ...)`, is the start of the next
//! window, so each span costs `(p - mu)(p - mu + 1)/2` combinations and no allocation. The
//! very first window is brought to the invariant by inserting `a` (only an unclamped start
//! needs it). Every step is a convex combination: a relative error of a few `p` ulp.

use super::width::{Width, blend_in, with_width};

/// Runs the extraction over the spline of degree `p` with knots `u` (`n + p + 1` of them,
/// valid, domain of positive length) and `n` working points of `pdim` coordinates, which
/// `load(i, out)` writes; `emit(a, b, window)` receives each non-empty span `[a, b]` in order
/// with its `p + 1` Bézier working points.
pub(crate) fn extract<L, E>(u: &[f64], p: usize, n: usize, pdim: usize, load: L, emit: E)
where
    L: FnMut(usize, &mut [f64]),
    E: FnMut(f64, f64, &[f64]),
{
    with_width!(pdim, extract_w(u, p, n, load, emit));
}

/// [`extract`] for the point width `w`.
fn extract_w<L, E, W: Width>(u: &[f64], p: usize, n: usize, mut load: L, mut emit: E, w: W)
where
    L: FnMut(usize, &mut [f64]),
    E: FnMut(f64, f64, &[f64]),
{
    let pdim = w.get();
    let len = (p + 1) * pdim;
    let mut win = vec![0.0; len];
    let mut next = vec![0.0; len];
    let mut alpha = vec![0.0; p + 2];
    let mut s = p;
    while u[s] >= u[s + 1] {
        s += 1;
    }
    for i in 0..=p {
        load(s - p + i, &mut win[i * pdim..(i + 1) * pdim]);
    }
    insert_start(u, p, s, w, &mut win);
    loop {
        let (a, b) = (u[s], u[s + 1]);
        let mut mu = 1;
        while s + mu + 1 < u.len() && u[s + mu + 1] == b {
            mu += 1;
        }
        let last = s + mu >= n;
        let levels = p.saturating_sub(mu);
        if !last && mu <= p {
            let k = p - mu;
            next[k * pdim..(k + 1) * pdim].copy_from_slice(&win[p * pdim..]);
        }
        for k in mu + 1..p + 1 {
            alpha[k] = (b - a) / (u[s + k] - a);
        }
        for r in 1..levels + 1 {
            // Points j = r + mu..=p, from the right (slot j - 1 is read before it
            // changes); `seg` starts at point r + mu - 1, and point j uses
            // alpha[j - r + 1], i.e. alpha[mu + 1..=p - r + 1] in order.
            let seg = &mut win[(r + mu - 1) * pdim..];
            for (jj, &al) in alpha[mu + 1..p - r + 2].iter().enumerate().rev() {
                let (lo, hi) = seg[jj * pdim..(jj + 2) * pdim].split_at_mut(pdim);
                blend_in(w, hi, lo, 1.0 - al, al);
            }
            if !last {
                let k = p - mu - r;
                next[k * pdim..(k + 1) * pdim].copy_from_slice(&win[p * pdim..]);
            }
        }
        emit(a, b, &win);
        if last {
            break;
        }
        for i in (p + 1).saturating_sub(mu)..p + 1 {
            load(s + mu - p + i, &mut next[i * pdim..(i + 1) * pdim]);
        }
        std::mem::swap(&mut win, &mut next);
        s += mu;
    }
}

/// Brings the first window (points `s-p..=s`) to the invariant: inserts `a = u_s` until
/// its multiplicity is `p` (a no-op for a clamped start). After level `r` slot `j` holds
/// the de Boor point `d_{j+r}^r`; the final window is the right edge `d_p^p, ..., d_p^0`.
fn insert_start<W: Width>(u: &[f64], p: usize, s: usize, w: W, win: &mut [f64]) {
    let pdim = w.get();
    let a = u[s];
    for r in 1..=p {
        for j in 0..=p - r {
            let tl = u[s - p + j + r];
            if tl == a {
                break;
            }
            let tr = u[s + j + 1];
            let beta = (a - tl) / (tr - tl);
            let al = 1.0 - beta;
            let (lo, hi) = win.split_at_mut((j + 1) * pdim);
            blend_in(w, &mut lo[j * pdim..], hi, beta, al);
        }
    }
}
