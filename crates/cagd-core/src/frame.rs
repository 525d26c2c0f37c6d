//! The unit-consistent model-space bound of a change of a rational shape, and the frame in
//! which every reducer works on rational shapes (ADDED, beyond the seeds: the seeds do not
//! treat rounding or units of rational bounds).
//!
//! **Centred bound.** A rational shape `S = A / W` (homogeneous points `(A_i, W_i) = (w_i
//! P_i, w_i)`) changed to `S' = A' / W'` on the same basis satisfies, for any centre `c`,
//! `S - S' = ((S - c)(W' - W) + (A_c - A'_c)) / W'` with `A_c = A - c W` (Piegl & Tiller
//! eq. 5.30 taken about `c`). With `R >= max ||P_i - c||` (the shape lies in the hull of
//! its model points), `h_A >= max ||A_c - A'_c||`, `h_W >= max |W - W'|` and the partition
//! of unity, `||S - S'|| <= (h_A + R h_W) / v` with `v = max(min v_i, min w_i - h_W)`
//! ([`centred_rational_bound`]). It is independent of where the shape sits and scales with
//! it — unlike `eps_h (1 + max ||P||) / min w`, which mixes a length with a pure number.
//!
//! **Frame.** The reducers that only know one homogeneous bound `eps_h` (of `(A_c - A'_c,
//! W - W')` together) work in a [`ModelFrame`]: the model points are mapped to `(P - c) /
//! s` (`c` the centre of their bounding box, `s = R` their radius about it), the algorithm
//! runs unchanged on the framed shape with the tolerance divided by `s`, its homogeneous
//! bound becomes `(1 + R / s) eps_h / v = 2 eps_h / v` in frame units (the centred bound
//! with `h_A = h_W = eps_h`, `c = 0`), and the result is mapped back, `s` times the bound
//! plus [`ModelFrame::rounding`]. The same shape moved or scaled gives the same framed
//! shape up to the rounding of the map, hence the same spans and a bound that scales with
//! it. (A power-of-two `s` would make the map exact but not the law: the homogeneous norm
//! mixes the framed points, which would then differ by a factor up to 2, with the weights.)

/// The model-space bound `(h_a + radius h_w) / v * (1 + 8 eps)`, `v = max(vmin, wmin -
/// h_w)`, of a change of a rational shape (module docs): `h_a` bounds the centred
/// homogeneous point change `||dA_i - c dW_i||`, `h_w` the weight change `|dW_i|`, `radius`
/// the distance of the old shape's model points from `c`, `wmin` the smallest old weight,
/// `vmin` the smallest new one. Infinity when `v <= 0` or an argument is NaN.
///
/// ```
/// use cagd_core::centred_rational_bound;
/// // Weights change by 1e-3 around a shape of radius 10: 10 * 1e-3 plus the point part,
/// // over the new weights' lower bound max(0.5, 1 - 1e-3).
/// let b = centred_rational_bound(1e-4, 1e-3, 10.0, 1.0, 0.5);
/// assert!((b - (1e-4 + 1e-2) / (1.0 - 1e-3)).abs() < 1e-15);
/// assert!(centred_rational_bound(1.0, 2.0, 1.0, 1.0, 0.0).is_infinite());
/// ```
pub fn centred_rational_bound(h_a: f64, h_w: f64, radius: f64, wmin: f64, vmin: f64) -> f64 {
    let v = vmin.max(wmin - h_w);
    let b = (h_a + radius * h_w) / v * (1.0 + 8.0 * f64::EPSILON);
    if v > 0.0 && b >= 0.0 {
        b
    } else {
        f64::INFINITY
    }
}

/// The affine frame `x -> (x - c) / s` of a rational shape's model points (module docs):
/// `c` the centre of their bounding box, `s = R` their largest distance from `c` (`s = 1`
/// when all points coincide or `R` is not a positive finite number).
#[derive(Debug, Clone, PartialEq)]
pub struct ModelFrame {
    centre: Vec<f64>,
    scale: f64,
    radius: f64,
    /// `max_k |x_k|` over the input points and the centre: the size the in-map rounds at.
    size: f64,
}

impl ModelFrame {
    /// The frame of `points` (`dim` coordinates each). Non-finite points give a frame with
    /// non-finite numbers; callers validate their shapes first.
    ///
    /// ```
    /// use cagd_core::ModelFrame;
    /// let f = ModelFrame::new(&[1e8, 0.0, 1e8 + 3.0, 4.0], 2);
    /// assert_eq!(f.centre(), &[1e8 + 1.5, 2.0]);
    /// assert_eq!(f.scale(), 2.5); // the radius
    /// let framed = f.to_frame(&[1e8, 0.0]);
    /// assert_eq!(framed, vec![-0.6, -0.8]);
    /// assert_eq!(f.from_frame(&framed), vec![1e8, 0.0]);
    /// ```
    pub fn new(points: &[f64], dim: usize) -> Self {
        let centre = crate::kernel::bounding_box_centre(points, dim.max(1));
        let radius = points
            .chunks_exact(dim.max(1))
            .map(|q| {
                q.iter()
                    .zip(&centre)
                    .map(|(x, c)| (x - c) * (x - c))
                    .sum::<f64>()
                    .sqrt()
            })
            .fold(0.0f64, f64::max);
        let scale = if radius > 0.0 && radius.is_finite() {
            radius
        } else {
            1.0
        };
        let size = points
            .iter()
            .chain(&centre)
            .fold(0.0f64, |m, x| m.max(x.abs()));
        Self {
            centre,
            scale,
            radius,
            size,
        }
    }

    /// The centre `c`.
    pub fn centre(&self) -> &[f64] {
        &self.centre
    }

    /// The scale `s` (the radius, or 1).
    pub fn scale(&self) -> f64 {
        self.scale
    }

    /// The largest distance `R` of the points from the centre (model units).
    pub fn radius(&self) -> f64 {
        self.radius
    }

    /// The radius in frame units, `R / s` (1, or 0 when all points coincide).
    pub fn framed_radius(&self) -> f64 {
        self.radius / self.scale
    }

    /// `(x - c) / s` for every point of `points`.
    pub fn to_frame(&self, points: &[f64]) -> Vec<f64> {
        let dim = self.centre.len().max(1);
        points
            .iter()
            .enumerate()
            .map(|(i, x)| (x - self.centre.get(i % dim).copied().unwrap_or(0.0)) / self.scale)
            .collect()
    }

    /// `s x + c` for every point of `points` (the inverse of [`ModelFrame::to_frame`]).
    pub fn from_frame(&self, points: &[f64]) -> Vec<f64> {
        let dim = self.centre.len().max(1);
        points
            .iter()
            .enumerate()
            .map(|(i, x)| x * self.scale + self.centre.get(i % dim).copied().unwrap_or(0.0))
            .collect()
    }

    /// The model-space bound of a homogeneous bound `eps_h` found in the frame (on the
    /// framed shape's `(w x, w)`, weights unchanged): `s` times [`centred_rational_bound`]
    /// with `h_A = h_W = eps_h` and radius `R / s`, `wmin` / `vmin` as there.
    pub fn model_bound(&self, eps_h: f64, wmin: f64, vmin: f64) -> f64 {
        let b = centred_rational_bound(eps_h, eps_h, self.framed_radius(), wmin, vmin);
        b * self.scale * (1.0 + 2.0 * f64::EPSILON)
    }

    /// The model-space distance a round trip through the frame can add (model units): the
    /// in-map moves every input point by at most `2 sqrt(dim) eps size` (one subtraction
    /// and one division, `|x - c| <= R <= 2 size`, `size` the largest input or centre
    /// coordinate), the out-map every output point of `out` (frame units) by at most
    /// `2 sqrt(dim) eps (s max |x| + |c|)`; a rational shape moves by at most its points'
    /// largest move (the hull property). Twice the sum, for slack.
    pub fn rounding(&self, out: &[f64]) -> f64 {
        let dim = self.centre.len().max(1) as f64;
        let out_size = out.iter().fold(0.0f64, |m, x| m.max(x.abs())) * self.scale
            + self.centre.iter().fold(0.0f64, |m, x| m.max(x.abs()));
        4.0 * dim.sqrt() * f64::EPSILON * (2.0 * self.size + out_size)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn frame_round_trip_and_invariance() {
        let pts = [0.3, -1.0, 2.0, 0.5, 1.0, 4.0];
        let f = ModelFrame::new(&pts, 2);
        for (t, k) in [(1e8, 1.0), (-3e5, 1e-6), (0.0, 1e6), (1e-6, 0.125)] {
            let moved: Vec<f64> = pts.iter().map(|x| x * k + t).collect();
            let g = ModelFrame::new(&moved, 2);
            // The framed points agree up to the rounding of building `moved` and framing it.
            let (a, b) = (f.to_frame(&pts), g.to_frame(&moved));
            assert!((g.scale() - f.scale() * k).abs() <= 8.0 * f64::EPSILON * (t.abs() + 4.0 * k));
            let tol = 8.0 * f64::EPSILON * (t.abs() + 4.0 * k) / g.scale() + 1e-15;
            for (x, y) in a.iter().zip(&b) {
                assert!((x - y).abs() <= tol, "{t} {k}: {x} vs {y}");
            }
            let back = g.from_frame(&b);
            for (x, y) in back.iter().zip(&moved) {
                assert!((x - y).abs() <= g.rounding(&b), "{t} {k}: {x} vs {y}");
            }
        }
    }

    #[test]
    fn centred_bound_is_a_true_bound() {
        // S(t) = ((1 - t) w0 P0 + t w1 P1) / ((1 - t) w0 + t w1) against its perturbed copy.
        let (p0, p1, w0, w1) = (1e6 + 1.0, 1e6 + 3.0, 1.0, 4.0);
        let (dw0, dw1, da0, da1) = (1e-3, -2e-3, 5e-4, 1e-4);
        let frame = ModelFrame::new(&[p0, p1], 1);
        let c = frame.centre()[0];
        let h_a = f64::abs(da0 - c * dw0).max(f64::abs(da1 - c * dw1));
        let h_w = f64::abs(dw0).max(f64::abs(dw1));
        let b = centred_rational_bound(h_a, h_w, frame.radius(), w0, (w0 - dw0).min(w1 - dw1));
        let mut worst = 0.0f64;
        for i in 0..=1000 {
            let t = f64::from(i) / 1000.0;
            let (a, w) = ((1.0 - t) * w0 * p0 + t * w1 * p1, (1.0 - t) * w0 + t * w1);
            let (a2, w2) = (
                (1.0 - t) * (w0 * p0 - da0) + t * (w1 * p1 - da1),
                (1.0 - t) * (w0 - dw0) + t * (w1 - dw1),
            );
            worst = worst.max((a / w - a2 / w2).abs());
        }
        assert!(worst > 0.0 && worst <= b, "{worst} {b}");
    }
}
