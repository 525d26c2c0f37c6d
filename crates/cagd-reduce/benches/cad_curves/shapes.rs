//! Synthetic curves that look like the B-spline / NURBS curves of CAD exchange files (the
//! proxy of issue 17's held-back row): degree 4–15, 1–20 spans, smooth 3-D paths of size
//! 10–1000 (mm), non-uniform knots, some interior knots of multiplicity above one, and
//! three kinds:
//!
//! - `bspline`: a polynomial B-spline whose control points sample a smooth path at the
//!   Greville abscissae (a sweep of 0.05–0.5 turns with a gentle bend and lift: a face
//!   edge, not a coil);
//! - `nurbs`: the same with smooth weights in `[0.5, 2]`;
//! - `conic`: 1–4 exact ellipse arcs (each at most a quarter turn, rational quadratic
//!   Bézier pieces) in a tilted plane, elevated to degree 4–8 and merged `C^0` (knots of
//!   multiplicity `p` at the joints, as exchange files write elevated conics).
//!
//! Half the curves are parametrized on `[0, 1]`, half on `[0, size]` (arc-length-like), as
//! files do. Everything is reproducible from the curve's index.

use cagd_core::{BSplineCurve, BezierCurve};

/// The three kinds of curve, in the order the generator cycles through them.
pub(crate) const KINDS: [&str; 3] = ["bspline", "nurbs", "conic"];

/// A small reproducible generator (xorshift64).
struct Rng(u64);

impl Rng {
    fn new(seed: u64) -> Self {
        Self(0x9E37_79B9_7F4A_7C15 ^ seed.wrapping_mul(0x2545_F491_4F6C_DD1D))
    }

    fn next(&mut self) -> u64 {
        let s = &mut self.0;
        *s ^= *s << 13;
        *s ^= *s >> 7;
        *s ^= *s << 17;
        *s
    }

    /// Uniform in `[0, 1)`.
    fn unit(&mut self) -> f64 {
        (self.next() >> 11) as f64 / (1u64 << 53) as f64
    }

    fn range(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * self.unit()
    }

    /// Uniform in `lo..=hi` (`hi - lo < 2^11`): `floor(unit * count)` in integers.
    fn int(&mut self, lo: usize, hi: usize) -> usize {
        let count = (hi - lo + 1) as u64;
        let k = ((self.next() >> 11) * count) >> 53;
        lo + usize::try_from(k).unwrap_or(0).min(hi - lo)
    }
}

/// Curve `i` of the set: its kind (`KINDS[i % 3]`) and the curve.
pub(crate) fn curve(i: usize) -> (&'static str, BSplineCurve) {
    let kind = KINDS[i % KINDS.len()];
    let mut rng = Rng::new(i as u64 + 1);
    let c = match kind {
        "conic" => conic(&mut rng),
        _ => free_form(&mut rng, kind == "nurbs"),
    };
    (kind, c)
}

/// An orthonormal frame `(e1, e2, e3)` turned by random angles.
fn frame(rng: &mut Rng) -> [[f64; 3]; 3] {
    let (a, b) = (rng.range(0.0, std::f64::consts::TAU), rng.range(-1.2, 1.2));
    let e1 = [a.cos() * b.cos(), a.sin() * b.cos(), b.sin()];
    let e2 = [-a.sin(), a.cos(), 0.0];
    let e3 = [
        e1[1] * e2[2] - e1[2] * e2[1],
        e1[2] * e2[0] - e1[0] * e2[2],
        e1[0] * e2[1] - e1[1] * e2[0],
    ];
    [e1, e2, e3]
}

/// `o + x e1 + y e2 + z e3`.
fn place(o: &[f64; 3], f: &[[f64; 3]; 3], (x, y, z): (f64, f64, f64)) -> [f64; 3] {
    std::array::from_fn(|k| o[k] + x * f[0][k] + y * f[1][k] + z * f[2][k])
}

/// A polynomial (or, with `rational`, NURBS) B-spline of degree 4–15 on a smooth path.
fn free_form(rng: &mut Rng, rational: bool) -> BSplineCurve {
    let p = rng.int(4, 15);
    let spans = rng.int(1, 20);
    let size = 10f64.powf(rng.range(1.0, 3.0));
    let (t0, t1) = if rng.unit() < 0.5 {
        (0.0, 1.0)
    } else {
        (0.0, size)
    };
    // Breaks with spacings in [0.4, 1.6] of the mean.
    let gaps: Vec<f64> = (0..spans).map(|_| rng.range(0.4, 1.6)).collect();
    let total: f64 = gaps.iter().sum();
    let mut breaks = vec![t0];
    let mut acc = 0.0;
    for g in &gaps[..spans - 1] {
        acc += g;
        breaks.push(t0 + (t1 - t0) * acc / total);
    }
    breaks.push(t1);
    let mut knots = vec![t0; p + 1];
    // One curve in three with two or more spans: one interior knot of multiplicity 2..p-1.
    let multiple = (spans >= 2 && rng.unit() < 1.0 / 3.0).then(|| rng.int(1, spans - 1));
    for (j, &t) in breaks[1..spans].iter().enumerate() {
        let mult = if multiple == Some(j + 1) {
            rng.int(2, p - 1)
        } else {
            1
        };
        knots.extend(std::iter::repeat_n(t, mult));
    }
    knots.extend(std::iter::repeat_n(t1, p + 1));
    let n = knots.len() - p - 1;
    // The path: a helix-like sweep with low-frequency bends, size `size`.
    let turns = rng.range(0.05, 0.5) * std::f64::consts::TAU;
    let (phase, bend, lift) = (
        rng.range(0.0, 6.3),
        rng.range(0.0, 0.4),
        rng.range(-0.5, 0.5),
    );
    let (wf, wp) = (rng.range(0.5, 4.0), rng.range(0.0, 6.3));
    let origin = [
        rng.range(-500.0, 500.0),
        rng.range(-500.0, 500.0),
        rng.range(0.0, 300.0),
    ];
    let f = frame(rng);
    let mut points = Vec::with_capacity(3 * n);
    let mut weights = Vec::with_capacity(n);
    for i in 0..n {
        // Greville abscissa, as a fraction of the domain.
        let g = knots[i + 1..=i + p].iter().sum::<f64>() / p as f64;
        let s = (g - t0) / (t1 - t0);
        let a = phase + turns * s;
        let r = 0.5 * size * (1.0 + bend * (3.0 * s).sin());
        let q = place(&origin, &f, (r * a.cos(), r * a.sin(), lift * size * s));
        points.extend_from_slice(&q);
        weights.push(2f64.powf((wf * s * std::f64::consts::PI + wp).sin()));
    }
    if rational {
        BSplineCurve::new_rational(p, knots, points, weights, 3).expect("valid NURBS")
    } else {
        BSplineCurve::new(p, knots, points, 3).expect("valid B-spline")
    }
}

/// 1–4 exact ellipse arcs of at most a quarter turn each, elevated to degree 4–8.
fn conic(rng: &mut Rng) -> BSplineCurve {
    let arcs = rng.int(1, 4);
    let p = rng.int(4, 8);
    let size = 10f64.powf(rng.range(1.0, 3.0));
    let (ra, rb) = (0.5 * size, 0.5 * size * rng.range(0.3, 1.0));
    let origin = [
        rng.range(-500.0, 500.0),
        rng.range(-500.0, 500.0),
        rng.range(0.0, 300.0),
    ];
    let f = frame(rng);
    let mut alpha = rng.range(0.0, std::f64::consts::TAU);
    let mut segs = Vec::with_capacity(arcs);
    for _ in 0..arcs {
        let theta = rng.range(0.3, 1.0) * std::f64::consts::FRAC_PI_2;
        let (a0, am, a1) = (alpha, alpha + 0.5 * theta, alpha + theta);
        let c = (0.5 * theta).cos();
        let on = |a: f64, s: f64| place(&origin, &f, (ra * a.cos() / s, rb * a.sin() / s, 0.0));
        let mut pts = Vec::with_capacity(9);
        for q in [on(a0, 1.0), on(am, c), on(a1, 1.0)] {
            pts.extend_from_slice(&q);
        }
        let quad = BezierCurve::new_rational(pts, vec![1.0, c, 1.0], 3).expect("valid arc");
        segs.push(quad.elevate(p - 2).expect("elevate"));
        alpha = a1;
    }
    let scale = if rng.unit() < 0.5 { 1.0 } else { size };
    let breaks: Vec<f64> = (0..=arcs).map(|j| scale * j as f64 / arcs as f64).collect();
    BSplineCurve::from_beziers(&segs, &breaks, 0, 1e-9 * size).expect("merge")
}
