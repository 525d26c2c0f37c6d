//! Tests of [`super::outer_knots`]: each rule a named error, and a start break of
//! multiplicity `p + 1` after an outer knot.

use cagd_core::{BSplineCurve, Error};

use crate::{BezierPieces, pieces_to_nurbs, to_bezier_pieces};

fn pieces() -> BezierPieces {
    BezierPieces::new(2, 1, vec![0.0, 1.0], vec![0.0, 1.0, 3.0], None).unwrap()
}

fn named(e: Error) -> &'static str {
    match e {
        Error::BadParameter { name, .. } => name,
        other => panic!("unexpected {other:?}"),
    }
}

#[test]
fn each_rule_is_a_named_error() {
    let bad = [
        (vec![-1.0], vec![2.0, 3.0], "outer_knots.left"), // fewer than p
        (vec![-1.0, f64::NAN], vec![2.0, 3.0], "outer_knots.left"),
        (vec![-0.5, -1.0], vec![2.0, 3.0], "outer_knots.left"), // decreasing
        (vec![-1.0, 0.5], vec![2.0, 3.0], "outer_knots.left"),  // inside the domain
        (vec![-1.0, -0.5, -0.2], vec![2.0, 3.0], "outer_knots.left"), // domain not at 0
        (vec![0.0, 0.0, 0.0], vec![2.0, 3.0], "outer_knots.left"), // multiplicity p + 2
        (vec![-1.0, 0.0], vec![0.5, 3.0], "outer_knots.right"),
        (vec![-1.0, 0.0], vec![3.0, 2.0], "outer_knots.right"),
        (vec![-1.0, 0.0], vec![1.0, 1.0, 1.0], "outer_knots.right"),
        (
            vec![-1.0, 0.0],
            vec![2.0, f64::INFINITY],
            "outer_knots.right",
        ),
    ];
    for (l, r, want) in bad {
        let e = pieces().with_outer_knots(l.clone(), r.clone()).unwrap_err();
        assert_eq!(named(e), want, "{l:?} {r:?}");
    }
    // Valid: partly clamped ends, and the extra copies of a break of multiplicity p + 1.
    for (l, r) in [
        (vec![-1.0, 0.0], vec![1.0, 1.0]),
        (vec![-1.0, 0.0, 0.0], vec![1.0, 1.0, 4.0]),
    ] {
        assert!(pieces().with_outer_knots(l, r).is_ok());
    }
}

#[test]
fn a_start_break_of_multiplicity_p_plus_1_after_an_outer_knot() {
    // u_1 = u_2 = u_3 = 0 (p = 2): the first point's support ends where the domain
    // starts, so it does not shape the curve; the knot vector comes back all the same.
    let knots = vec![-1.0, 0.0, 0.0, 0.0, 0.5, 1.0, 1.0, 1.0];
    let pts = vec![7.0, 0.0, 1.0, 3.0, 2.0];
    let c = BSplineCurve::new_rational(2, knots, pts, vec![1.0, 2.0, 0.5, 1.0, 3.0], 1).unwrap();
    let pieces = to_bezier_pieces(&c).unwrap();
    let outer = pieces.outer_knots().unwrap();
    assert_eq!(
        (outer.left(), outer.right()),
        (&[-1.0, 0.0, 0.0][..], &[1.0, 1.0][..])
    );
    let back = pieces_to_nurbs(&pieces, None).unwrap();
    assert_eq!(back.curve.knots(), c.knots());
    for i in 0..=50 {
        let t = f64::from(i) / 50.0;
        let (x, y) = (back.curve.eval(t).unwrap(), c.eval(t).unwrap());
        assert!((x[0] - y[0]).abs() < 1e-14, "{t}: {x:?} vs {y:?}");
    }
    // The points that shape the curve are the same.
    for (g, w) in back.curve.points()[1..].iter().zip(&c.points()[1..]) {
        assert!((g - w).abs() < 1e-14);
    }
}
