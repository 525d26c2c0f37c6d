//! One object of the input as read, before cagd-core validates it.

use crate::input::PointList;

/// One object of the input, before it is validated by cagd-core.
#[derive(Debug, Clone, PartialEq)]
pub(crate) enum RawShape {
    Bezier {
        points: PointList,
        weights: Option<Vec<f64>>,
    },
    BSpline {
        degree: usize,
        knots: Vec<f64>,
        points: PointList,
        weights: Option<Vec<f64>>,
    },
    Tensor {
        degree: (usize, usize),
        points: PointList,
    },
    Triangle {
        degree: usize,
        points: PointList,
    },
    /// An interval triangle (seed 004): degree and the lower / upper nets.
    IntervalTriangle {
        degree: usize,
        lo: PointList,
        hi: PointList,
    },
    /// A WSGB(n, L) curve of seed 003 ([`crate::commands::reduce::wsgb`]).
    Wsgb {
        l: usize,
        points: PointList,
    },
    /// A B-spline / NURBS surface: points flat and i-major over `counts = (n_u, n_v)`.
    BSplineSurface {
        degree: (usize, usize),
        knots_u: Vec<f64>,
        knots_v: Vec<f64>,
        points: PointList,
        counts: (usize, usize),
        weights: Option<Vec<f64>>,
    },
}

impl RawShape {
    /// The number of control points (both nets of an interval triangle).
    pub(crate) fn point_count(&self) -> usize {
        match self {
            RawShape::Bezier { points, .. }
            | RawShape::BSpline { points, .. }
            | RawShape::Tensor { points, .. }
            | RawShape::Triangle { points, .. }
            | RawShape::Wsgb { points, .. }
            | RawShape::BSplineSurface { points, .. } => points.len(),
            RawShape::IntervalTriangle { lo, hi, .. } => lo.len() + hi.len(),
        }
    }
}
