//! Grading of the global fit's refinement mesh (beyond the seed): after the offending spans
//! are split, every span is made at most [`GRADE`] times as long as its neighbours by
//! geometric splits growing away from the short side.
//!
//! Why: the fit is global, and the value of the spline at a knot is a compromise of the
//! spans around it, weighted by their length. Refining only the spans on one side of a
//! knot builds a geometric mesh whose tiny spans carry no weight in the L2 objective, so
//! the value there stays the one the long neighbour wants — and for a NURBS the long
//! neighbour may be well within the budget in model space (large weights) while its
//! homogeneous fit is far off at that knot. The tiny spans then inherit the error (and an
//! oscillation decaying from it, which can make fitted weights negative) at every level:
//! the refinement stalls until a span cannot be split further. Found by the
//! `random_curves_meet_the_tolerance` law: a degree-5 NURBS with weights 0.023..43 to
//! degree 1, refused at the rounding level. On a graded mesh the long neighbour is refined
//! along with the short spans, so the node is set locally and the fit converges (the L2
//! spline projector is bounded in the maximum norm independently of the knots, Shadrin
//! 2001, so the error follows the best approximation on the spans around the node).

/// Largest length ratio of neighbouring spans the refinement leaves. The first split of a
/// span makes at most 16 parts ([`super::global`]), so a first round on a graded mesh
/// needs no grading; only repeated refinement at one place does.
pub(crate) const GRADE: f64 = 16.0;

/// The breaks to add to the increasing `breaks` so that every span is at most about
/// `ratio` (> 1) times as long as each neighbour: a forward pass splits each span
/// geometrically from its left end (parts `ratio h`, `ratio^2 h`, ... after a left
/// neighbour of length `h`, the last two parts evened out), a backward pass the same from
/// the right. The added breaks are strictly inside spans; neighbouring parts differ by at
/// most `2 ratio`. `None` when more than `limit` breaks would be added (the work stops
/// there).
pub(crate) fn grading_breaks(breaks: &[f64], ratio: f64, limit: usize) -> Option<Vec<f64>> {
    let mut added = Vec::new();
    let forward = graded_pass(breaks, ratio, &mut added, limit)?;
    let reversed: Vec<f64> = forward.iter().rev().map(|x| -x).collect();
    let mut back = Vec::new();
    graded_pass(&reversed, ratio, &mut back, limit - added.len())?;
    added.extend(back.iter().map(|x| -x));
    added.sort_by(f64::total_cmp);
    Some(added)
}

/// One pass of [`grading_breaks`] from the left: the graded breaks; the new ones are also
/// pushed to `added` (`None` past `limit` of them).
fn graded_pass(breaks: &[f64], ratio: f64, added: &mut Vec<f64>, limit: usize) -> Option<Vec<f64>> {
    let mut out = Vec::with_capacity(breaks.len());
    out.extend(breaks.iter().take(2));
    for w in breaks.windows(2).skip(1) {
        let (mut x, end) = (w[0], w[1]);
        let mut h = x - out[out.len() - 2];
        loop {
            let rem = end - x;
            if rem <= ratio * h {
                break;
            }
            let step = if rem >= 2.0 * ratio * h {
                ratio * h
            } else {
                0.5 * rem
            };
            let y = x + step;
            if !(y > x && y < end) {
                break;
            }
            if added.len() >= limit {
                return None;
            }
            out.push(y);
            added.push(y);
            h = y - x;
            x = y;
        }
        out.push(end);
    }
    Some(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The neighbour ratios of `breaks` merged with the graded additions.
    fn ratios(breaks: &[f64], ratio: f64) -> (Vec<f64>, f64) {
        let mut all = breaks.to_vec();
        all.extend(grading_breaks(breaks, ratio, usize::MAX).unwrap());
        all.sort_by(f64::total_cmp);
        let lens: Vec<f64> = all.windows(2).map(|w| w[1] - w[0]).collect();
        let worst = lens
            .windows(2)
            .map(|w| (w[0] / w[1]).max(w[1] / w[0]))
            .fold(0.0, f64::max);
        (all, worst)
    }

    #[test]
    fn a_graded_mesh_is_left_alone() {
        let b = [0.0, 1.0, 1.5, 3.0, 3.25, 4.0];
        assert!(grading_breaks(&b, 16.0, 0).unwrap().is_empty());
    }

    /// A span split geometrically towards a point (the stall of the global fit): both
    /// long neighbours are graded, with few breaks (logarithmic in the length ratio).
    #[test]
    fn a_geometric_cluster_grades_its_neighbours() {
        let mut b = vec![0.0];
        let (mut x, mut h) = (1.0, 1.0);
        for _ in 0..12 {
            b.push(x);
            h *= 0.25;
            x += h;
        }
        let tiny = x;
        b.push(tiny);
        b.push(2.0);
        b.push(3.0);
        let (all, worst) = ratios(&b, 16.0);
        assert!(worst <= 32.0, "{worst}");
        assert!(all.len() - b.len() < 40, "{}", all.len() - b.len());
        // The work stops at the limit.
        assert!(grading_breaks(&b, 16.0, 3).is_none());
        // The span right of the cluster now starts with a part comparable to the last
        // tiny span.
        let i = all.iter().position(|v| *v == tiny).unwrap();
        let (last, next) = (tiny - all[i - 1], all[i + 1] - tiny);
        assert!(next <= 32.0 * last, "{last} {next}");
    }

    #[test]
    fn every_added_break_is_inside_a_span() {
        let b = [0.0, 1e-12, 1.0, 1.0 + 1e-9, 5.0, 1e6];
        let add = grading_breaks(&b, 4.0, usize::MAX).unwrap();
        assert!(!add.is_empty());
        for v in &add {
            assert!(!b.contains(v) && *v > 0.0 && *v < 1e6, "{v}");
        }
        let (_, worst) = ratios(&b, 4.0);
        assert!(worst <= 8.0, "{worst}");
    }
}
