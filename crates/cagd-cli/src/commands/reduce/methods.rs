//! The method names of the command line and how they map to [`cagd_reduce::Method`].

use cagd_reduce::Method;

pub(crate) use crate::method_names::NAMES;

/// How a name is carried out: a linear method, or the G1 perturbation with optimal
/// `l1, l2` (not linear; one degree per step).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum Plan {
    Linear(Method),
    PerturbationG1,
}

/// The plan for a method name; `r`, `p` are the end orders for `chebyshev` and `l2`
/// (default 0: end points interpolated; -1: no constraint). Unknown names and `--r/--p`
/// given to a method without them are errors.
pub(crate) fn plan(name: &str, r: Option<i64>, p: Option<i64>) -> Result<Plan, String> {
    let order = |v: Option<i64>, flag: &str| -> Result<i32, String> {
        let v = v.unwrap_or(0);
        i32::try_from(v)
            .ok()
            .filter(|o| *o >= -1)
            .ok_or_else(|| format!("{flag} {v}: must be -1 (none) or a derivative order >= 0"))
    };
    let takes_orders = matches!(name, "chebyshev" | "l2");
    if !takes_orders && (r.is_some() || p.is_some()) {
        return Err(format!("--r/--p apply to chebyshev and l2, not to {name}"));
    }
    Ok(match name {
        "forrest" => Plan::Linear(Method::Forrest),
        "farin" => Plan::Linear(Method::Farin),
        "piegl" => Plan::Linear(Method::PieglTiller),
        "perturbation" => Plan::Linear(Method::Perturb),
        "perturbation-g1" => Plan::PerturbationG1,
        "pinv" => Plan::Linear(Method::GeneralizedInverse),
        "pinv-ends" => Plan::Linear(Method::GeneralizedInverseEnds),
        "chebyshev" => Plan::Linear(Method::ConstrainedChebyshev {
            r: order(r, "--r")?,
            p: order(p, "--p")?,
        }),
        "eck" => Plan::Linear(Method::Eck),
        "watkins-worsey" => Plan::Linear(Method::WatkinsWorsey),
        "bogacki" => Plan::Linear(Method::BogackiWeinsteinXu),
        "l2" => Plan::Linear(Method::L2 {
            r: order(r, "--r")?,
            p: order(p, "--p")?,
        }),
        other => {
            return Err(format!(
                "unknown method {other:?} (one of: {})",
                NAMES.join(", ")
            ));
        }
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_name_maps() {
        for n in NAMES {
            assert!(plan(n, None, None).is_ok(), "{n}");
        }
        assert_eq!(
            plan("l2", Some(2), Some(-1)).unwrap(),
            Plan::Linear(Method::L2 { r: 2, p: -1 })
        );
        assert!(plan("eck", Some(1), None).is_err());
        assert!(plan("l2", Some(-2), None).is_err());
        assert!(
            plan("nope", None, None)
                .unwrap_err()
                .starts_with("unknown method \"nope\"")
        );
    }
}
