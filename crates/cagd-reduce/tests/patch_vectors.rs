//! The patch vectors of `vectors-reduce.json` (SPEC-reduce §4, §5): tensor-1, tri-1 (and
//! tensor-2 / tri-2 when the file holds them).

use cagd_core::{TensorPatch, TriPatch};
use cagd_reduce::{
    PatchConstraint, PatchOptions, TensorMethod, TriMethod, TriOptions, reduce_tensor,
    reduce_triangle,
};
use cagd_testkit::{assert_close, flat, inner_dim, load_vectors, num};

const FILE: &str = "vectors-reduce.json";

fn with_prefix(prefix: &str) -> Vec<cagd_testkit::serde_json::Value> {
    load_vectors(FILE)
        .into_iter()
        .filter(|v| v["id"].as_str().is_some_and(|s| s.starts_with(prefix)))
        .collect()
}

#[test]
fn tensor_vectors() {
    let vs = with_prefix("tensor-");
    assert!(!vs.is_empty());
    for v in vs {
        let id = v["id"].as_str().unwrap();
        let (m, n) = (
            usize::try_from(v["params"]["m"].as_u64().unwrap()).unwrap(),
            usize::try_from(v["params"]["n"].as_u64().unwrap()).unwrap(),
        );
        let p = &v["input"]["P"];
        let dim = inner_dim(p);
        let patch = TensorPatch::new(flat(p), m, n, dim).unwrap();
        let opts = PatchOptions::new(TensorMethod::Perturb(PatchConstraint::None));
        let red = reduce_tensor(&patch, (m - 1, n - 1), &opts).unwrap();
        let tol = num(&v["tol"]);
        let e = &v["expected"];
        assert_close(id, red.patch.points(), &flat(&e["Q"]), tol);
        assert_close(id, red.patch.points(), &flat(&e["Q_exact"]), tol);
        assert_close(id, &red.perturbation, &flat(&e["eps"]), tol);
        let bound = num(&e["bound"]);
        let got = red.report.error_bound;
        // The certified bound adds a rounding allowance of ~1e-13 relative.
        assert!(
            got >= bound && got <= bound * (1.0 + 1e-12),
            "{id}: {got} vs {bound}"
        );
    }
}

#[test]
fn tri_vectors() {
    let vs = with_prefix("tri-");
    assert!(!vs.is_empty());
    for v in vs {
        let id = v["id"].as_str().unwrap();
        let n = usize::try_from(v["params"]["n"].as_u64().unwrap()).unwrap();
        let t = &v["input"]["T"];
        let dim = inner_dim(t);
        let patch = TriPatch::new(flat(t), n, dim).unwrap();
        let red = reduce_triangle(&patch, n - 1, &TriOptions::new(TriMethod::Perturb)).unwrap();
        let tol = num(&v["tol"]);
        let e = &v["expected"];
        assert_close(id, red.patch.points(), &flat(&e["Q"]), tol);
        assert_close(id, red.patch.points(), &flat(&e["Q_exact"]), tol);
        assert_close(
            id,
            red.multipliers.as_deref().unwrap(),
            &flat(&e["lambda"]),
            tol,
        );
        let b = cagd_reduce::tri_perturbation_matrix(n);
        assert_close(id, &b, &flat(&e["B_km"]), 0.0);
        // The certified bound is max ||eps_ij|| (convex hull).
        let eps_max = red
            .perturbation
            .chunks_exact(dim)
            .map(|p| p.iter().map(|x| x * x).sum::<f64>().sqrt())
            .fold(0.0, f64::max);
        let got = red.report.error_bound;
        assert!(
            got >= eps_max && got <= eps_max * (1.0 + 1e-12) + 1e-14,
            "{id}"
        );
    }
}
