//! [`Width`]: the number of working coordinates of a point as a type, so that the kernels of
//! the general route are compiled once per common width (2, 3, 4: plane and space,
//! polynomial or homogeneous) with fixed-length inner loops, and once for any width (the
//! rows of a surface). Beyond the seed: an implementation device only.

/// A point width known at compile time ([`Fixed`]) or at run time ([`Dynamic`]).
pub(crate) trait Width: Copy {
    /// The number of working coordinates.
    fn get(self) -> usize;
}

/// A width known at compile time.
#[derive(Clone, Copy)]
pub(crate) struct Fixed<const D: usize>;

impl<const D: usize> Width for Fixed<D> {
    #[inline(always)]
    fn get(self) -> usize {
        D
    }
}

/// A width known at run time.
#[derive(Clone, Copy)]
pub(crate) struct Dynamic(pub(crate) usize);

impl Width for Dynamic {
    #[inline(always)]
    fn get(self) -> usize {
        self.0
    }
}

/// Calls `$f` with the [`Width`] of `$pdim`: [`Fixed`] for 1 to 4, else [`Dynamic`].
macro_rules! with_width {
    ($pdim:expr, $f:ident ( $($arg:expr),* )) => {
        match $pdim {
            1 => $f($($arg,)* $crate::nurbs::width::Fixed::<1>),
            2 => $f($($arg,)* $crate::nurbs::width::Fixed::<2>),
            3 => $f($($arg,)* $crate::nurbs::width::Fixed::<3>),
            4 => $f($($arg,)* $crate::nurbs::width::Fixed::<4>),
            d => $f($($arg,)* $crate::nurbs::width::Dynamic(d)),
        }
    };
}
pub(crate) use with_width;

// Point operations of the kernels: index loops over exactly `w.get()` coordinates (a
// constant for `Fixed`, so they unroll; the zip of two slice iterators did not, its length
// being recomputed from pointers at every point).

/// `y = cx * x + cy * y` for one point.
#[inline(always)]
#[allow(
    clippy::needless_range_loop,
    reason = "fixed-length index loop, unrolled"
)]
pub(crate) fn blend_in<W: Width>(w: W, y: &mut [f64], x: &[f64], cx: f64, cy: f64) {
    let d = w.get();
    let (y, x) = (&mut y[..d], &x[..d]);
    for c in 0..d {
        y[c] = cx * x[c] + cy * y[c];
    }
}

/// `y = (y - c * x) * inv` for one point (a knot-removal step in place).
#[inline(always)]
#[allow(
    clippy::needless_range_loop,
    reason = "fixed-length index loop, unrolled"
)]
pub(crate) fn unblend_in<W: Width>(w: W, y: &mut [f64], x: &[f64], c: f64, inv: f64) {
    let d = w.get();
    let (y, x) = (&mut y[..d], &x[..d]);
    for k in 0..d {
        y[k] = (y[k] - c * x[k]) * inv;
    }
}

/// `out = (x - c * y) * inv` for one point (a knot-removal step).
#[inline(always)]
#[allow(
    clippy::needless_range_loop,
    reason = "fixed-length index loop, unrolled"
)]
pub(crate) fn unblend<W: Width>(w: W, out: &mut [f64], x: &[f64], y: &[f64], c: f64, inv: f64) {
    let d = w.get();
    let (out, x, y) = (&mut out[..d], &x[..d], &y[..d]);
    for k in 0..d {
        out[k] = (x[k] - c * y[k]) * inv;
    }
}

/// `|x - a q - b q1|^2` for one point (the residual of a knot-insertion equation).
#[inline(always)]
#[allow(
    clippy::needless_range_loop,
    reason = "fixed-length index loop, unrolled"
)]
pub(crate) fn residual2<W: Width>(w: W, x: &[f64], q: &[f64], q1: &[f64], a: f64, b: f64) -> f64 {
    let d = w.get();
    let (x, q, q1) = (&x[..d], &q[..d], &q1[..d]);
    let mut e2 = 0.0;
    for k in 0..d {
        let e = x[k] - a * q[k] - b * q1[k];
        e2 += e * e;
    }
    e2
}

/// `|x - y|^2` for one point.
#[inline(always)]
#[allow(
    clippy::needless_range_loop,
    reason = "fixed-length index loop, unrolled"
)]
pub(crate) fn dist2<W: Width>(w: W, x: &[f64], y: &[f64]) -> f64 {
    let d = w.get();
    let (x, y) = (&x[..d], &y[..d]);
    let mut e2 = 0.0;
    for k in 0..d {
        e2 += (x[k] - y[k]) * (x[k] - y[k]);
    }
    e2
}

/// `out = u * x + t * y` for one point.
#[inline(always)]
#[allow(
    clippy::needless_range_loop,
    reason = "fixed-length index loop, unrolled"
)]
pub(crate) fn lerp<W: Width>(w: W, out: &mut [f64], x: &[f64], y: &[f64], u: f64, t: f64) {
    let d = w.get();
    let (out, x, y) = (&mut out[..d], &x[..d], &y[..d]);
    for k in 0..d {
        out[k] = u * x[k] + t * y[k];
    }
}
