//! The one adapter around the kept LP crate (`microlp`, a pure-Rust simplex solver; see
//! SPEC-convert I.2, "Solver recommendation").
//!
//! Every call runs inside `std::panic::catch_unwind`: a solver panic, an internal error, an
//! interrupted solve, a status other than proven optimal or a non-finite answer becomes
//! [`Error::LpSolverFailed`]; "infeasible" and "unbounded" become [`Error::LpInfeasible`] /
//! [`Error::LpUnbounded`]. Nothing from `microlp` leaves this file.

use std::panic::{AssertUnwindSafe, catch_unwind};

use microlp::{ComparisonOp, OptimizationDirection, Problem, SolutionStatus};

use crate::{Error, Result};

/// The sense of one constraint row.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Sense {
    /// `a'x <= rhs`.
    Le,
    /// `a'x >= rhs`.
    Ge,
    /// `a'x = rhs`.
    #[cfg_attr(
        not(test),
        allow(dead_code, reason = "used by the dual route of the tests")
    )]
    Eq,
}

/// One constraint: non-zero `(variable, coefficient)` pairs, sense, right-hand side.
pub(crate) type Row = (Vec<(usize, f64)>, Sense, f64);

/// A dense LP `min c'x` subject to `lower <= x <= upper` (infinite bounds allowed) and
/// sparse rows `a_r'x (sense_r) rhs_r`.
#[derive(Debug, Clone, Default)]
pub(crate) struct Lp {
    /// Objective coefficients (one per variable).
    pub(crate) cost: Vec<f64>,
    /// Variable bounds.
    pub(crate) bounds: Vec<(f64, f64)>,
    /// Rows: non-zero `(variable, coefficient)` pairs, sense, right-hand side.
    pub(crate) rows: Vec<Row>,
}

impl Lp {
    /// Adds a variable with cost `c` and bounds `(lo, hi)`; returns its index.
    pub(crate) fn var(&mut self, c: f64, bounds: (f64, f64)) -> usize {
        self.cost.push(c);
        self.bounds.push(bounds);
        self.cost.len() - 1
    }

    /// Adds a row.
    pub(crate) fn row(&mut self, coefs: Vec<(usize, f64)>, sense: Sense, rhs: f64) {
        self.rows.push((coefs, sense, rhs));
    }
}

/// An optimal vertex: the variables and the objective value.
#[derive(Debug, Clone)]
pub(crate) struct LpSolution {
    /// One value per variable.
    pub(crate) x: Vec<f64>,
    /// `c'x` as the solver reports it.
    pub(crate) objective: f64,
}

/// Solves `lp` (a minimisation) with microlp; `what` names the LP in errors.
///
/// # Errors
/// [`Error::LpInfeasible`], [`Error::LpUnbounded`], [`Error::LpSolverFailed`].
pub(crate) fn solve_min(lp: &Lp, what: &'static str) -> Result<LpSolution> {
    let run = catch_unwind(AssertUnwindSafe(|| solve_inner(lp)));
    let fail = |why: String| Error::LpSolverFailed { what, why };
    let (x, objective, status) = match run {
        Err(_) => return Err(fail("the solver panicked".to_string())),
        Ok(Err(microlp::Error::Infeasible)) => return Err(Error::LpInfeasible { what }),
        Ok(Err(microlp::Error::Unbounded)) => return Err(Error::LpUnbounded { what }),
        Ok(Err(e)) => return Err(fail(e.to_string())),
        Ok(Ok(None)) => return Err(fail("the solve was interrupted".to_string())),
        Ok(Ok(Some(s))) => s,
    };
    if status != SolutionStatus::Optimal {
        return Err(fail(format!("status {status:?}, not proven optimal")));
    }
    if !objective.is_finite() || x.iter().any(|v| !v.is_finite()) {
        return Err(fail("non-finite answer".to_string()));
    }
    Ok(LpSolution { x, objective })
}

type Raw = Option<(Vec<f64>, f64, SolutionStatus)>;

fn solve_inner(lp: &Lp) -> core::result::Result<Raw, microlp::Error> {
    let mut p = Problem::new(OptimizationDirection::Minimize);
    let vars: Vec<_> = lp
        .cost
        .iter()
        .zip(&lp.bounds)
        .map(|(&c, &b)| p.add_var(c, b))
        .collect();
    for (coefs, sense, rhs) in &lp.rows {
        let terms: Vec<_> = coefs.iter().map(|&(i, a)| (vars[i], a)).collect();
        let op = match sense {
            Sense::Le => ComparisonOp::Le,
            Sense::Ge => ComparisonOp::Ge,
            Sense::Eq => ComparisonOp::Eq,
        };
        p.add_constraint(terms.as_slice(), op, *rhs);
    }
    let outcome = p.solve()?;
    let Some(sol) = outcome.solution() else {
        return Ok(None);
    };
    let x = vars.iter().map(|&v| sol.var_value_raw(v)).collect();
    Ok(Some((x, sol.objective(), sol.status())))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn small_lp_and_named_failures() {
        // min x + y s.t. x + 2y >= 4, 3x + y >= 3 (free vars): vertex (0.4, 1.8), value 2.2.
        let mut lp = Lp::default();
        let x = lp.var(1.0, (f64::NEG_INFINITY, f64::INFINITY));
        let y = lp.var(1.0, (f64::NEG_INFINITY, f64::INFINITY));
        lp.row(vec![(x, 1.0), (y, 2.0)], Sense::Ge, 4.0);
        lp.row(vec![(x, 3.0), (y, 1.0)], Sense::Ge, 3.0);
        let s = solve_min(&lp, "test").unwrap();
        assert!((s.objective - 2.2).abs() < 1e-12);
        assert!((s.x[0] - 0.4).abs() < 1e-12 && (s.x[1] - 1.8).abs() < 1e-12);

        let mut bad = lp.clone();
        bad.row(vec![(x, 1.0), (y, 1.0)], Sense::Le, 1.0);
        assert_eq!(
            solve_min(&bad, "t").unwrap_err(),
            Error::LpInfeasible { what: "t" }
        );

        let mut unb = Lp::default();
        let z = unb.var(-1.0, (0.0, f64::INFINITY));
        unb.row(vec![(z, 1.0)], Sense::Ge, 1.0);
        assert_eq!(
            solve_min(&unb, "u").unwrap_err(),
            Error::LpUnbounded { what: "u" }
        );

        let mut eq = Lp::default();
        let a = eq.var(2.0, (0.0, f64::INFINITY));
        let b = eq.var(1.0, (0.0, f64::INFINITY));
        eq.row(vec![(a, 1.0), (b, 1.0)], Sense::Eq, 3.0);
        let s = solve_min(&eq, "eq").unwrap();
        assert!((s.objective - 3.0).abs() < 1e-12);
    }
}
